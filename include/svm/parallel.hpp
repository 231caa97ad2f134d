/// @file
/// Views from a point at infinity (parallel projections, and lights at
/// infinity) by the central construction, exactly.
///
/// A projective map sends the point at infinity in direction `e` to a finite
/// point and keeps the scene's order along every line parallel to `e`:
///
///     x ↦ c + s·(x − c) / (s + e·(x − c)),   s = ⌊2·max|e·(x − c)|⌋ + 1
///
/// over the scene's vertices x, about a centre c (over `double`, s is
/// 2·max|e·(x − c)| + 1; exactly, an integer, so that the image's points
/// carry no denominator of s).  Every vertex stays on the
/// positive side of the plane the map sends to infinity (s + e·(x − c) > 0),
/// so convex polygons stay convex and keep their orientation (the map's
/// determinant is s⁴ > 0); lines go to lines and planes to planes; the plane
/// e·(x − c) = 0 through the centre is fixed; and the lines parallel to `e`
/// become the lines through the finite point c + s·e/(e·e), in the same
/// order.  So the visibility map from that point of the scene's image is the
/// map of the parallel view along −e, and a perspective camera there,
/// looking along −e, draws the orthographic view of the plane through c.
///
/// A plane (a, b) of the image (a·(x' − c) + b = 0) is the plane
/// (s·a + b·e, s·b) of the scene: input-derived planes stay input-derived,
/// with a constant more in their degree, so the construction's degree bound
/// holds.
#pragma once

#include "build.hpp"
#include "camera.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <vector>

namespace svm {

/// The projective map of a view from the point at infinity in direction
/// `toward` (from the scene towards the eye or light), about `centre`.
template <geometry::number FT> class view_from_infinity {
public:
  using point = geometry::e3::point<FT>;
  using plane = geometry::e3::hyperplane<FT>;

  /// For the scene `polygons`, and the points `also` (which must keep
  /// s + e·(x − c) > 0 too: points to be located, say).  Throws
  /// `std::invalid_argument` for a zero direction.
  view_from_infinity(std::vector<polygon<FT>> const& polygons, std::array<FT, 3> toward, point centre = {},
                     std::vector<point> const& also = {})
      : e_(std::move(toward)), c_(std::move(centre)) {
    if (e_[0] == 0 && e_[1] == 0 && e_[2] == 0) throw std::invalid_argument("svm::view_from_infinity: the direction is zero");
    auto each_point = [&](auto&& f) {
      for (auto const& p : polygons)
        for (auto const& q : p.vertices) f(q);
      for (auto const& q : also) f(q);
    };
    if constexpr (geometry::exact_field<FT>) {
      // c = C / K and e = E / Ke on integers; e·(x − c) = E·u / (Ke·K·W)
      // with u = K·X − W·C for x = X / W, so the largest |e·(x − c)| is
      // found by comparing fractions |E·u| / W on integers.
      auto const& cz = c_.homogeneous().integers();
      ints_.C = {cz[0], cz[1], cz[2]};
      ints_.K = cz[3];
      geometry::integer ke(1);
      for (auto const& x : e_) mpz_lcm(ke.backend().data(), ke.backend().data(), mpq_denref(x.backend().data()));
      for (std::size_t k = 0; k < 3; ++k) {
        auto const* q = e_[k].backend().data();
        mpz_divexact(ints_.E[k].backend().data(), ke.backend().data(), mpq_denref(q));
        mpz_mul(ints_.E[k].backend().data(), ints_.E[k].backend().data(), mpq_numref(q));
      }
      geometry::integer top(0), below(1), v;
      each_point([&](point const& q) {
        auto const& z = q.homogeneous().integers();
        v = 0;
        for (std::size_t k = 0; k < 3; ++k) v += ints_.E[k] * (ints_.K * z[k] - z[3] * ints_.C[k]);
        if (v.sign() < 0) v = -v;
        if (v * below > top * z[3]) top = v, below = z[3];
      });
      // s = ⌊2·top / (below·Ke·K)⌋ + 1, an integer: the image's points
      // then carry no denominator of s.
      geometry::integer d = below * ke * ints_.K, S = 2 * top;
      mpz_fdiv_q(S.backend().data(), S.backend().data(), d.backend().data());
      S += 1;
      s_ = FT(S);
      ints_.SKeK = S * ke * ints_.K;
    } else {
      FT m(0);
      each_point([&](point const& q) {
        FT v = along(q);
        if (v < 0) v = -v;
        if (m < v) m = v;
      });
      s_ = FT(2) * m + FT(1);
    }
  }

  FT const& s() const noexcept { return s_; }
  std::array<FT, 3> const& direction() const noexcept { return e_; }
  point const& centre() const noexcept { return c_; }

  /// The finite point that the point at infinity becomes: c + s·e/(e·e).
  point eye() const {
    FT ee = e_[0] * e_[0] + e_[1] * e_[1] + e_[2] * e_[2];
    return {c_.x() + s_ * e_[0] / ee, c_.y() + s_ * e_[1] / ee, c_.z() + s_ * e_[2] / ee};
  }

  /// The image of a point of the scene (which must satisfy s + e·(x − c) > 0).
  point image(point const& x) const {
    if constexpr (geometry::exact_field<FT>) {
      // x = X / W: with u = K·X − W·C and Q = S·Ke·K·W + E·u (positive
      // when s + e·(x − c) is), the image is (C·Q + K·S·Ke·u, K·Q), on
      // integers, without a rational division.
      auto const& z = x.homogeneous().integers();
      auto const& W = z[3];
      std::array<geometry::integer, 3> u;
      for (std::size_t k = 0; k < 3; ++k) u[k] = ints_.K * z[k] - W * ints_.C[k];
      geometry::integer Q = ints_.SKeK * W + geometry::dot(ints_.E, u);
      if (Q.sign() <= 0) throw std::invalid_argument("svm::view_from_infinity: a point beyond the plane sent to infinity");
      std::array<geometry::integer, 4> h;
      for (std::size_t k = 0; k < 3; ++k) h[k] = ints_.C[k] * Q + ints_.SKeK * u[k];
      h[3] = ints_.K * Q;
      return point::from_homogeneous(std::move(h));
    }
    FT w = s_ + along(x);
    if (!(w > 0)) throw std::invalid_argument("svm::view_from_infinity: a point beyond the plane sent to infinity");
    return {c_.x() + s_ * (x.x() - c_.x()) / w, c_.y() + s_ * (x.y() - c_.y()) / w, c_.z() + s_ * (x.z() - c_.z()) / w};
  }

  /// The direction from `eye()` in which the map shows the line through `x`
  /// parallel to the view (x must satisfy s + e·(x − c) > 0).
  geometry::s2::point<FT> direction_of(point const& x) const {
    point y = image(x), o = eye();
    return geometry::s2::point<FT>(std::array<FT, 3>{y.x() - o.x(), y.y() - o.y(), y.z() - o.z()});
  }

  /// The images of polygons, vertex by vertex (same faces).
  std::vector<polygon<FT>> image(std::vector<polygon<FT>> const& polygons) const {
    std::vector<polygon<FT>> out;
    out.reserve(polygons.size());
    for (auto const& p : polygons) {
      std::vector<point> v;
      v.reserve(p.vertices.size());
      for (auto const& q : p.vertices) v.push_back(image(q));
      out.push_back({std::move(v), p.face});
    }
    return out;
  }

  /// The plane of the scene whose image is `h` (same positive side).
  plane preimage(plane const& h) const { return mapped(h, +1); }

  /// The image of a plane of the scene (same positive side).
  plane image(plane const& h) const { return mapped(h, -1); }

  /// The convex polygon of the scene whose image is `s`, or the image of a
  /// polygon of the scene (`forward`): its plane cut by its bounds' planes.
  geometry::e3::sub_hyperplane<FT> carry(geometry::e3::sub_hyperplane<FT> const& piece, bool forward) const {
    auto map = [&](plane const& h) { return forward ? image(h) : preimage(h); };
    std::optional<geometry::e3::sub_hyperplane<FT>> r = geometry::e3::whole_plane(map(piece.support));
    for (auto const& b : piece.bounds) {
      r = geometry::e3::split(*r, map(b.original)).positive;
      if (!r) throw std::logic_error("svm::view_from_infinity: a polygon vanished in the map");
    }
    return std::move(*r);
  }

private:
  /// Plane (a, b) about the centre (a·(x − c) + b = 0) to (s·a + sign·b·e, s·b):
  /// sign +1 from the image back to the scene, −1 from the scene to the image.
  plane mapped(plane const& h, int sign) const {
    auto const& n = h.n;
    FT b = n[3] + n[0] * c_.x() + n[1] * c_.y() + n[2] * c_.z();
    FT be = sign > 0 ? b : -b;
    std::array<FT, 3> a{s_ * n[0] + be * e_[0], s_ * n[1] + be * e_[1], s_ * n[2] + be * e_[2]};
    FT d = s_ * b - (a[0] * c_.x() + a[1] * c_.y() + a[2] * c_.z());
    return plane(geometry::hvec<FT, 4>(std::array<FT, 4>{a[0], a[1], a[2], d}), h.tag);
  }

  /// The centre, the direction and s on integers (exact fields only).
  struct integer_form {
    std::array<geometry::integer, 3> C, E;
    geometry::integer K, SKeK; ///< SKeK = S·Ke·K, s = S an integer
  } ints_;

  FT along(point const& x) const { return e_[0] * (x.x() - c_.x()) + e_[1] * (x.y() - c_.y()) + e_[2] * (x.z() - c_.z()); }

  std::array<FT, 3> e_;
  point c_;
  FT s_{1};
};

/// The perspective camera at `view.eye()` that draws the parallel view along
/// −e: `extent` scene units wide on the plane through the centre, the
/// image's vertical from `up`.  With `svm::projection::perspective`; the
/// map to draw is that of the scene's image from `view.eye()`.
template <geometry::number FT> camera parallel_camera(view_from_infinity<FT> const& view, vec3 up, double extent, int width, int height) {
  auto const& e = view.direction();
  auto d = [](FT const& x) {
    if constexpr (std::is_same_v<FT, double>) return x;
    else return x.template convert_to<double>();
  };
  camera c;
  c.forward = {-d(e[0]), -d(e[1]), -d(e[2])};
  c.up = up;
  c.width = width;
  c.height = height;
  // The plane through the centre is fixed by the map, at distance s/|e| from the eye.
  double distance = d(view.s()) / std::sqrt(d(e[0]) * d(e[0]) + d(e[1]) * d(e[1]) + d(e[2]) * d(e[2]));
  if (!(extent > 0)) throw std::invalid_argument("svm::parallel_camera: the extent must be positive");
  c.hfov = 2 * std::atan(extent / 2 / distance) * 180 / std::numbers::pi;
  return c;
}

} // namespace svm
