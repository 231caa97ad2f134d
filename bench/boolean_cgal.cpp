// bench_boolean's CGAL peer: Polygon_set_2 on the exact-predicates,
// exact-constructions kernel (Epeck), the only other exact library of the
// benchmark.  Its result is exact; the area is summed exactly and rounded.
#include "boolean_peers.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/version_macros.h>

#include <iterator>
#include <memory>
#include <vector>

namespace bench::boolean_peers {

namespace {

using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using cpoint = kernel::Point_2;
using cpolygon = CGAL::Polygon_2<kernel>;
using cpolygon_with_holes = CGAL::Polygon_with_holes_2<kernel>;
using cset = CGAL::Polygon_set_2<kernel>;

/// `r` as a CGAL polygon turning counter-clockwise (an outer boundary) or
/// clockwise (a hole), as Polygon_set_2 expects.  Doubles convert exactly.
cpolygon to_cgal(path const& r, bool counterclockwise) {
  cpolygon p;
  for (auto const& [x, y] : r) p.push_back(cpoint(x, y));
  if (p.is_counterclockwise_oriented() != counterclockwise) p.reverse_orientation();
  return p;
}

std::vector<cpolygon_with_holes> to_cgal(polygons const& m) {
  std::vector<cpolygon_with_holes> out;
  for (auto const& p : m) {
    std::vector<cpolygon> holes;
    for (auto const& h : p.holes) holes.push_back(to_cgal(h, false));
    out.emplace_back(to_cgal(p.outer, true), holes.begin(), holes.end());
  }
  return out;
}

path from_cgal(cpolygon const& p) {
  path out;
  out.reserve(p.size());
  for (auto const& q : p.container()) out.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y())});
  return out;
}

class cgal_job final : public job {
public:
  cgal_job(operation op, polygons const& a, polygons const& b) : op_(op), a_(to_cgal(a)), b_(to_cgal(b)) {}
  void run() override {
    // The operands are sets of disjoint polygons (a star, or a grid of
    // squares): inserted as a range, without pairwise unions.
    result_ = std::make_unique<cset>();
    result_->insert(a_.begin(), a_.end());
    other_ = std::make_unique<cset>();
    other_->insert(b_.begin(), b_.end());
    if (op_ == operation::union_)
      result_->join(*other_);
    else
      result_->intersection(*other_);
  }
  output result() override {
    output r;
    std::vector<cpolygon_with_holes> out;
    result_->polygons_with_holes(std::back_inserter(out));
    kernel::FT area = 0;
    for (auto const& p : out) {
      polygon q{from_cgal(p.outer_boundary()), {}};
      area += p.outer_boundary().area();
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
        q.holes.push_back(from_cgal(*h));
        area += h->area(); // negative: holes turn clockwise
      }
      r.shape.push_back(std::move(q));
    }
    r.area = CGAL::to_double(area);
    return r;
  }
  void clear() override {
    result_.reset();
    other_.reset();
  }

private:
  operation op_;
  std::vector<cpolygon_with_holes> a_, b_;
  std::unique_ptr<cset> result_, other_; ///< freed by clear, not timed
};

} // namespace

peer cgal_peer() {
  return {"cgal", "CGAL " CGAL_VERSION_STR " Polygon_set_2 (Epeck)",
          "Polygon_set_2<Epeck>::insert of both operands' polygons, then join or intersection (conversion to "
          "CGAL polygons not timed)",
          true, [](operation op, polygons const& a, polygons const& b) -> std::unique_ptr<job> {
            return std::make_unique<cgal_job>(op, a, b);
          }};
}

} // namespace bench::boolean_peers
