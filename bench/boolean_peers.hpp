// The other libraries bench_boolean times against genbsp, behind one small
// interface.  Each peer lives in its own translation unit (boolean_boost.cpp,
// boolean_clipper.cpp, boolean_cgal.cpp), built when its Debian package is
// present, so that a machine without CGAL or Clipper still builds the rest.
//
// Inputs reach a peer as polygons in double whose coordinates are exact
// (integers below 2^22 and halves of them), so that every library reads the
// very numbers genbsp reads.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace bench::boolean_peers {

using xy = std::array<double, 2>;
using path = std::vector<xy>; ///< a ring, first point not repeated

struct polygon {
  path outer;
  std::vector<path> holes;
};
using polygons = std::vector<polygon>;

enum class operation { union_, intersection };

/// One peer's result, as plain rings.
struct output {
  polygons shape;
  double area = 0; ///< computed by the peer (exactly, then rounded, for an exact peer)
};

/// One case prepared for one peer: `run` is the timed job, the rest is not.
class job {
public:
  virtual ~job() = default;
  /// Builds the operands from the prepared input and computes the operation;
  /// keeps the result for `result`.
  virtual void run() = 0;
  /// The last run's result.
  virtual output result() = 0;
  /// Frees the last run's result (not timed).
  virtual void clear() = 0;
};

struct peer {
  std::string name;    ///< command-line name: "boost", "clipper", "cgal"
  std::string label;   ///< for people: "Boost.Geometry 1.74", …
  std::string timed;   ///< what the timed job does, in one line
  bool exact = false;  ///< exact constructions (no rounding of new vertices)
  /// Prepares the inputs (conversions, not timed).
  std::unique_ptr<job> (*prepare)(operation, polygons const& a, polygons const& b) = nullptr;
};

/// The peers this binary was built with, in a fixed order.
std::vector<peer> available();

/// Whether `shape` is a valid multi-polygon by Boost.Geometry's rules
/// (`bg::is_valid`); if not, why.  Used on every inexact peer's output.
bool valid(polygons const& shape, std::string& why);

// The peers themselves (boolean_*.cpp).
peer boost_peer();
#ifdef GENBSP_BENCH_CLIPPER
peer clipper_peer();
#endif
#ifdef GENBSP_BENCH_CGAL
peer cgal_peer();
#endif

} // namespace bench::boolean_peers
