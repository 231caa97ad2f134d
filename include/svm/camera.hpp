/// @file
/// Cameras and projections of the sphere of directions onto an image.
///
/// A camera looks from the map's eye along `forward`, with `up` giving the
/// image's vertical.  Every projection maps the horizontal half-width of the
/// image (`width / 2` pixels) to half the horizontal field of view, measured
/// along the image's horizontal axis through its centre:
///
/// | projection        | radius of a direction at angle θ from `forward` |
/// |-------------------|-------------------------------------------------|
/// | perspective       | tan θ                                            |
/// | stereographic     | 2 tan(θ/2)                                       |
/// | fisheye (equidistant) | θ                                           |
/// | fisheye (equisolid)   | 2 sin(θ/2)                                  |
///
/// and the equirectangular panorama maps longitude (about `up`, 0 at
/// `forward`, positive to the right) and latitude linearly, both at the same
/// scale.  Pixel (0, 0) is the top left corner of the image; y grows downwards.
///
/// What cannot be computed exactly here is only drawn: the map is clipped to
/// the view before projection, on the sphere, with the map's own exact
/// machinery (`window_options`): a perspective view keeps the directions
/// inside the frustum's four circles; azimuthal views with a wide field keep
/// everything but a small square around the direction opposite `forward`;
/// the panorama cuts the sphere along its seam and through its poles so that
/// every face lies in one quarter of longitudes.
#pragma once

#include "build.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace svm {

using vec3 = std::array<double, 3>;

/// Where the image looks from and how large it is.
struct camera {
  vec3 forward{1, 0, 0}; ///< the view direction (the image centre, before any shift)
  vec3 up{0, 0, 1};      ///< the image's vertical, need not be orthogonal to `forward`
  double hfov = 60;      ///< horizontal field of view, degrees
  int width = 800, height = 600;
  /// Image-plane shift (perspective only), in half-widths of the image: a
  /// shifted lens.  Keeps verticals vertical in architectural views (look
  /// level, shift up).
  double shift_x = 0, shift_y = 0;
};

enum class projection { perspective, stereographic, fisheye_equidistant, fisheye_equisolid, equirectangular };

inline std::optional<projection> projection_from_name(std::string_view s) {
  if (s == "perspective") return projection::perspective;
  if (s == "stereographic") return projection::stereographic;
  if (s == "fisheye" || s == "fisheye-equidistant") return projection::fisheye_equidistant;
  if (s == "fisheye-equisolid") return projection::fisheye_equisolid;
  if (s == "equirectangular") return projection::equirectangular;
  return std::nullopt;
}

inline char const* name(projection p) {
  switch (p) {
  case projection::perspective: return "perspective";
  case projection::stereographic: return "stereographic";
  case projection::fisheye_equidistant: return "fisheye-equidistant";
  case projection::fisheye_equisolid: return "fisheye-equisolid";
  case projection::equirectangular: return "equirectangular";
  }
  return "?";
}

namespace detail {
inline vec3 sub3(vec3 a, vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline vec3 add3(vec3 a, vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline vec3 mul3(vec3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot3(vec3 a, vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline vec3 cross3(vec3 a, vec3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
inline double norm3(vec3 a) { return std::sqrt(dot3(a, a)); }
inline vec3 unit3(vec3 a) { return mul3(a, 1 / norm3(a)); }
} // namespace detail

/// A point of the image, in pixels.
struct pixel {
  double x, y;
};

/// A camera with a projection: maps unit directions to pixels and pixels back.
class projector {
public:
  projector(camera const& c, projection p) : cam_(c), proj_(p) {
    using namespace detail;
    if (!(c.width > 0 && c.height > 0)) throw std::invalid_argument("camera: the image size must be positive");
    double lf = norm3(c.forward);
    if (!(lf > 0) || !std::isfinite(lf)) throw std::invalid_argument("camera: the view direction is zero");
    f_ = unit3(c.forward);
    vec3 r = cross3(f_, c.up);
    if (!(norm3(r) > 1e-9 * norm3(c.up))) throw std::invalid_argument("camera: the up vector is parallel to the view direction");
    r_ = unit3(r);
    u_ = cross3(r_, f_);
    double h = c.hfov * std::numbers::pi / 180;
    if (!(h > 0)) throw std::invalid_argument("camera: the field of view must be positive");
    double half = c.width / 2.0;
    switch (p) {
    case projection::perspective:
      if (!(h < std::numbers::pi * 179 / 180)) throw std::invalid_argument("camera: a perspective field of view must be below 179 degrees");
      scale_ = half / std::tan(h / 2);
      break;
    case projection::stereographic:
      if (!(h < 2 * std::numbers::pi)) throw std::invalid_argument("camera: a stereographic field of view must be below 360 degrees");
      scale_ = half / (2 * std::tan(h / 4));
      break;
    case projection::fisheye_equidistant:
      if (!(h <= 2 * std::numbers::pi)) throw std::invalid_argument("camera: a fisheye field of view must be at most 360 degrees");
      scale_ = half / (h / 2);
      break;
    case projection::fisheye_equisolid:
      if (!(h <= 2 * std::numbers::pi)) throw std::invalid_argument("camera: a fisheye field of view must be at most 360 degrees");
      scale_ = half / (2 * std::sin(h / 4));
      break;
    case projection::equirectangular:
      if (!(h <= 2 * std::numbers::pi)) throw std::invalid_argument("camera: a panorama's field of view must be at most 360 degrees");
      scale_ = half / (h / 2);
      break;
    }
  }

  camera const& cam() const noexcept { return cam_; }
  projection kind() const noexcept { return proj_; }
  vec3 right() const noexcept { return r_; }
  vec3 up() const noexcept { return u_; }
  vec3 forward() const noexcept { return f_; }
  /// Pixels per unit of the projection's radius.
  double scale() const noexcept { return scale_; }

  /// The camera frame coordinates (right, up, forward) of a direction.
  vec3 local(vec3 const& d) const { return {detail::dot3(d, r_), detail::dot3(d, u_), detail::dot3(d, f_)}; }
  vec3 world(vec3 const& l) const {
    using namespace detail;
    return add3(add3(mul3(r_, l[0]), mul3(u_, l[1])), mul3(f_, l[2]));
  }

  /// The image radius (in projection units) of the angle `theta` from `forward`.
  double radius(double theta) const {
    switch (proj_) {
    case projection::perspective: return std::tan(theta);
    case projection::stereographic: return 2 * std::tan(theta / 2);
    case projection::fisheye_equisolid: return 2 * std::sin(theta / 2);
    default: return theta;
    }
  }
  /// The angle from `forward` at image radius `rho` (in projection units).
  double angle(double rho) const {
    switch (proj_) {
    case projection::perspective: return std::atan(rho);
    case projection::stereographic: return 2 * std::atan(rho / 2);
    case projection::fisheye_equisolid: return 2 * std::asin(std::min(1.0, rho / 2));
    default: return rho;
    }
  }

  /// The pixel of the unit direction `d`.  For the panorama, `side` (+1 or
  /// −1) says which side of the seam a direction on it belongs to (0: the
  /// principal value).
  pixel project(vec3 const& d, int side = 0) const {
    vec3 l = local(d);
    double cx = cam_.width / 2.0, cy = cam_.height / 2.0;
    if (proj_ == projection::perspective) {
      return {cx + scale_ * (l[0] / l[2] - cam_.shift_x * cam_.width / 2.0 / scale_),
              cy - scale_ * (l[1] / l[2] - cam_.shift_y * cam_.width / 2.0 / scale_)};
    }
    if (proj_ == projection::equirectangular) {
      double lon = longitude(l, side), lat = std::asin(std::clamp(l[1], -1.0, 1.0));
      return {cx + scale_ * lon, cy - scale_ * lat};
    }
    double s = std::hypot(l[0], l[1]);
    double theta = std::atan2(s, l[2]);
    if (s == 0) return {cx, cy};
    double rho = radius(theta) * scale_;
    return {cx + rho * l[0] / s, cy - rho * l[1] / s};
  }

  /// The longitude of camera-frame direction `l`, on the given side of the seam.
  static double longitude(vec3 const& l, int side) {
    double lon = std::atan2(l[0], l[2]);
    if (side > 0 && lon < -std::numbers::pi / 2) lon += 2 * std::numbers::pi;
    if (side < 0 && lon > std::numbers::pi / 2) lon -= 2 * std::numbers::pi;
    return lon;
  }

  /// The unit direction seen at pixel (x, y); nothing where the projection
  /// shows no direction.
  std::optional<vec3> direction(double x, double y) const {
    using namespace detail;
    double a = (x - cam_.width / 2.0) / scale_, b = (cam_.height / 2.0 - y) / scale_;
    if (proj_ == projection::perspective) {
      a += cam_.shift_x * cam_.width / 2.0 / scale_;
      b += cam_.shift_y * cam_.width / 2.0 / scale_;
      return unit3(world({a, b, 1}));
    }
    if (proj_ == projection::equirectangular) {
      if (std::abs(b) > std::numbers::pi / 2 || std::abs(a) > std::numbers::pi) return std::nullopt;
      return world({std::cos(b) * std::sin(a), std::sin(b), std::cos(b) * std::cos(a)});
    }
    double rho = std::hypot(a, b);
    if (proj_ == projection::fisheye_equisolid && rho > 2) return std::nullopt;
    double theta = angle(rho);
    if (theta > std::numbers::pi) return std::nullopt;
    if (rho == 0) return f_;
    double s = std::sin(theta);
    return world({s * a / rho, s * b / rho, std::cos(theta)});
  }

  /// The window, exclusion and cuts that clip the map to what this view can
  /// show (see the file's description), as build options.
  build_options window_options(build_options o = {}) const {
    using namespace detail;
    o.window.clear();
    o.exclude.clear();
    o.cuts.clear();
    double cx = cam_.width / 2.0, cy = cam_.height / 2.0;
    if (proj_ == projection::perspective) {
      // The frustum: circles through consecutive corner directions, inside positive.
      o.window = sides({*direction(0, 0), *direction(cam_.width, 0), *direction(cam_.width, cam_.height), *direction(0, cam_.height)},
                       *direction(cx, cy));
      return o;
    }
    if (proj_ == projection::equirectangular) {
      o.cuts.push_back(r_); // the meridians of longitude 0 and 180 (the seam)
      o.cuts.push_back(f_); // the meridians of longitude ±90: with the first, through both poles
      return o;
    }
    // Azimuthal: the largest angle shown is at a corner of the image.
    double rho = std::hypot(cx, cy) / scale_;
    double theta = (proj_ == projection::fisheye_equisolid && rho >= 2) ? std::numbers::pi : angle(rho);
    theta = std::min(theta, std::numbers::pi);
    if (theta < std::numbers::pi * 80 / 180) {
      // A square frustum with the image's corner cap inside it.
      double t = std::tan(std::min(theta * 1.05 + 1e-3, std::numbers::pi * 85 / 180));
      o.window = sides({world({-t, t, 1}), world({t, t, 1}), world({t, -t, 1}), world({-t, -t, 1})}, f_);
      return o;
    }
    // Leave out a small square around the direction opposite `forward`,
    // beyond the image (or, for a full 360° fisheye, of side 0.01°).
    double eps = std::max((std::numbers::pi - theta) / 2, std::numbers::pi / 36000);
    double t = std::tan(eps);
    o.exclude = sides({world({-t, t, -1}), world({t, t, -1}), world({t, -t, -1}), world({-t, -t, -1})}, mul3(f_, -1));
    return o;
  }

private:
  /// The circles through consecutive corners of a spherical quadrilateral,
  /// each oriented with `inside` on its positive side.
  static std::vector<vec3> sides(std::array<vec3, 4> const& corner, vec3 const& inside) {
    using namespace detail;
    std::vector<vec3> out;
    for (std::size_t i = 0; i < 4; ++i) {
      vec3 n = cross3(corner[i], corner[(i + 1) % 4]);
      out.push_back(dot3(n, inside) < 0 ? mul3(n, -1) : n);
    }
    return out;
  }

  camera cam_;
  projection proj_;
  vec3 f_{}, r_{}, u_{};
  double scale_ = 1;
};

/// The camera that looks from `eye` at `target`.
inline camera look_at(vec3 eye, vec3 target, vec3 up = {0, 0, 1}) {
  camera c;
  c.forward = detail::sub3(target, eye);
  c.up = up;
  return c;
}

} // namespace svm
