// bench_boolean's Boost.Geometry peer (bg::union_, bg::intersection in
// double), and the validity check every inexact peer's output goes through.
#include "boolean_peers.hpp"

// Boost 1.74's Geometry includes one of Boost's own deprecated headers, which
// would print a message at every build.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/version.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace bench::boolean_peers {

namespace {

namespace bg = boost::geometry;
using bpoint = bg::model::d2::point_xy<double>;
using bpolygon = bg::model::polygon<bpoint>; // clockwise outer rings, closed (Boost's defaults)
using bmulti = bg::model::multi_polygon<bpolygon>;

bmulti to_boost(polygons const& m) {
  bmulti out;
  for (auto const& p : m) {
    bpolygon q;
    for (auto const& [x, y] : p.outer) q.outer().emplace_back(x, y);
    for (auto const& h : p.holes) {
      q.inners().emplace_back();
      for (auto const& [x, y] : h) q.inners().back().emplace_back(x, y);
    }
    out.push_back(std::move(q));
  }
  bg::correct(out); // Boost's orientation (clockwise outer rings) and closed rings
  return out;
}

path from_boost(bg::model::ring<bpoint> const& r) {
  path out;
  for (auto const& p : r) out.push_back({p.x(), p.y()});
  if (out.size() > 1 && out.front() == out.back()) out.pop_back(); // closed rings repeat their first point
  return out;
}

class boost_job final : public job {
public:
  boost_job(operation op, polygons const& a, polygons const& b) : op_(op), a_(to_boost(a)), b_(to_boost(b)) {}
  void run() override {
    if (op_ == operation::union_)
      bg::union_(a_, b_, out_);
    else
      bg::intersection(a_, b_, out_);
  }
  output result() override {
    output r;
    for (auto const& p : out_) {
      polygon q{from_boost(p.outer()), {}};
      for (auto const& h : p.inners()) q.holes.push_back(from_boost(h));
      r.shape.push_back(std::move(q));
    }
    r.area = bg::area(out_);
    return r;
  }
  void clear() override { bmulti().swap(out_); }

private:
  operation op_;
  bmulti a_, b_, out_;
};

} // namespace

peer boost_peer() {
  std::string version = std::to_string(BOOST_VERSION / 100000) + "." + std::to_string(BOOST_VERSION / 100 % 1000);
  return {"boost", "Boost.Geometry " + version,
          "bg::union_ or bg::intersection on corrected double multi_polygons (conversion not timed)", false,
          [](operation op, polygons const& a, polygons const& b) -> std::unique_ptr<job> {
            return std::make_unique<boost_job>(op, a, b);
          }};
}

bool valid(polygons const& shape, std::string& why) {
  // bg::correct (in to_boost) turns rings to Boost's orientation and closes
  // them: the orientation of a peer's rings is a convention, not a defect.
  // It does not touch crossings, spikes or holes outside their polygon.
  bmulti m = to_boost(shape);
  bool ok = bg::is_valid(m, why);
  if (ok) why.clear();
  std::replace(why.begin(), why.end(), '\n', ' ');
  return ok;
}

std::vector<peer> available() {
  std::vector<peer> all{boost_peer()};
#ifdef GENBSP_BENCH_CLIPPER
  all.push_back(clipper_peer());
#endif
#ifdef GENBSP_BENCH_CGAL
  all.push_back(cgal_peer());
#endif
  return all;
}

} // namespace bench::boolean_peers
