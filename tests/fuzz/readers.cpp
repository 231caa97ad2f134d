// libFuzzer targets for the readers, one program per format (the format is
// chosen when compiling: GENBSP_FUZZ_OFF, _OBJ, _STL, _MTL, _WKT, _GEOJSON).
// Each input is read the way the command-line program reads a file, then
// prepared the way it is prepared next (scenes cut into convex polygons).
// The only acceptable failure is a `read_error` whose message is one line
// naming the file; any other exception, crash, sanitizer report, hang or
// unbounded allocation is a finding.
#include <geometry/io/geojson.hpp>
#include <geometry/io/polygons.hpp>
#include <geometry/io/scene.hpp>
#include <geometry/io/wkt.hpp>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

namespace {

constexpr char const* file_name() {
#if defined(GENBSP_FUZZ_OFF)
  return "fuzz.off";
#elif defined(GENBSP_FUZZ_OBJ)
  return "fuzz.obj";
#elif defined(GENBSP_FUZZ_STL)
  return "fuzz.stl";
#elif defined(GENBSP_FUZZ_MTL)
  return "fuzz.mtl";
#elif defined(GENBSP_FUZZ_WKT)
  return "fuzz.wkt";
#elif defined(GENBSP_FUZZ_GEOJSON)
  return "fuzz.geojson";
#else
#error "define one of GENBSP_FUZZ_OFF, _OBJ, _STL, _MTL, _WKT, _GEOJSON"
#endif
}

void read(std::string const& text) {
  std::string const name = file_name();
#if defined(GENBSP_FUZZ_OFF) || defined(GENBSP_FUZZ_OBJ) || defined(GENBSP_FUZZ_STL)
  std::istringstream in(text);
#if defined(GENBSP_FUZZ_OFF)
  auto scene = geometry::io::read_off(in, name);
#elif defined(GENBSP_FUZZ_OBJ)
  auto scene = geometry::io::read_obj(in, name);
#else
  auto scene = geometry::io::read_stl(in, name);
#endif
  auto prepared = geometry::io::convex_polygons(scene);
  if (prepared.polygons.size() + prepared.degenerate_faces < scene.faces.size()) __builtin_trap(); // a face lost
#elif defined(GENBSP_FUZZ_MTL)
  std::istringstream in(text);
  geometry::io::detail::material_map materials;
  geometry::io::detail::read_mtl(in, name, materials);
#elif defined(GENBSP_FUZZ_WKT)
  (void)geometry::io::read_wkt(text, name);
#else
  (void)geometry::io::read_geojson(text, name);
#endif
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
  std::string text(reinterpret_cast<char const*>(data), size);
  try {
    read(text);
  } catch (geometry::io::read_error const& e) {
    // One line, naming the file.
    std::string_view what = e.what();
    if (what.find('\n') != std::string_view::npos || !what.starts_with(file_name()) || e.message.empty()) __builtin_trap();
  }
  return 0;
}
