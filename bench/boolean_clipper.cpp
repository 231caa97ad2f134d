// bench_boolean's Clipper peer: Angus Johnson's Clipper 1 (Debian
// libpolyclipping-dev), a Vatti sweep on 64-bit integer coordinates.  New
// vertices are rounded to the integer grid, so its output is not exact.
#include "boolean_peers.hpp"

#include <clipper.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace bench::boolean_peers {

namespace {

namespace cl = ClipperLib;

/// Clipper reads integers: the inputs' coordinates are integers and halves
/// of integers, so twice them are integers (checked).
constexpr double scale = 2;

cl::Paths to_clipper(polygons const& m) {
  cl::Paths out;
  auto add = [&](path const& r) {
    cl::Path p;
    p.reserve(r.size());
    for (auto const& [x, y] : r) {
      double sx = x * scale, sy = y * scale;
      if (sx != std::nearbyint(sx) || sy != std::nearbyint(sy) || std::abs(sx) > 0x1p52 || std::abs(sy) > 0x1p52)
        throw std::invalid_argument("bench_boolean: a coordinate Clipper cannot read exactly");
      p.push_back({static_cast<cl::cInt>(sx), static_cast<cl::cInt>(sy)});
    }
    out.push_back(std::move(p));
  };
  for (auto const& p : m) {
    add(p.outer);
    for (auto const& h : p.holes) add(h);
  }
  return out;
}

path from_clipper(cl::Path const& p) {
  path out;
  out.reserve(p.size());
  for (auto const& q : p) out.push_back({static_cast<double>(q.X) / scale, static_cast<double>(q.Y) / scale});
  return out;
}

/// The outer rings of `node`'s children, each with its holes, and those
/// below them (islands in holes).
void collect(cl::PolyNode const& node, polygons& out, double& area) {
  for (cl::PolyNode const* outer : node.Childs) {
    polygon p{from_clipper(outer->Contour), {}};
    area += cl::Area(outer->Contour);
    for (cl::PolyNode const* hole : outer->Childs) {
      p.holes.push_back(from_clipper(hole->Contour));
      area += cl::Area(hole->Contour); // negative: holes turn the other way
      collect(*hole, out, area);
    }
    out.push_back(std::move(p));
  }
}

class clipper_job final : public job {
public:
  clipper_job(operation op, polygons const& a, polygons const& b) : op_(op), a_(to_clipper(a)), b_(to_clipper(b)) {}
  void run() override {
    clipper_ = std::make_unique<cl::Clipper>();
    clipper_->AddPaths(a_, cl::ptSubject, true);
    clipper_->AddPaths(b_, cl::ptClip, true);
    clipper_->Execute(op_ == operation::union_ ? cl::ctUnion : cl::ctIntersection, tree_, cl::pftNonZero,
                      cl::pftNonZero);
  }
  output result() override {
    output r;
    double area = 0;
    collect(tree_, r.shape, area);
    r.area = area / (scale * scale);
    return r;
  }
  void clear() override {
    clipper_.reset();
    tree_.Clear();
  }

private:
  operation op_;
  cl::Paths a_, b_;
  std::unique_ptr<cl::Clipper> clipper_;
  cl::PolyTree tree_;
};

} // namespace

peer clipper_peer() {
  return {"clipper", "Clipper " CLIPPER_VERSION,
          "Clipper::AddPaths of both operands and Clipper::Execute into a PolyTree, non-zero fill, on 64-bit "
          "integers (twice the input coordinates; conversion not timed)",
          false, [](operation op, polygons const& a, polygons const& b) -> std::unique_ptr<job> {
            return std::make_unique<clipper_job>(op, a, b);
          }};
}

} // namespace bench::boolean_peers
