// Scene readers: exact values, comments and colours, every error at its FILE:LINE,
// OBJ references and materials, ASCII and binary STL, and read_scene's dispatch.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <geometry/io/scene.hpp>

#include <bit>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

using namespace geometry;
using io::read_error;
using test::Q;
namespace io_scene_tests {

namespace fs = std::filesystem;

namespace {

/// A fresh directory under the system's temporary directory, removed with its
/// files when the test ends (also when it fails).
struct temp_dir {
  fs::path dir;
  temp_dir() {
    std::random_device rd;
    auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
    std::string name = "genbsp-io-test-";
    name.append(std::to_string(rd())).append("-").append(std::to_string(static_cast<unsigned long long>(tick)));
    dir = fs::temp_directory_path() / name;
    fs::create_directories(dir);
  }
  ~temp_dir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  temp_dir(temp_dir const&) = delete;
  temp_dir& operator=(temp_dir const&) = delete;

  fs::path write(std::string const& name, std::string const& content) const {
    auto p = dir / name;
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p;
  }
};

io::scene off(std::string const& text) {
  std::istringstream in(text);
  return io::read_off(in, "mem.off");
}

io::scene obj(std::string const& text) {
  std::istringstream in(text);
  return io::read_obj(in, "mem.obj");
}

io::scene stl(std::string const& text) {
  std::istringstream in(text);
  return io::read_stl(in, "mem.stl");
}

/// Runs `read`, which must throw a read_error at `line` whose message contains `part`,
/// with `what()` exactly "FILE:LINE: message" (or "FILE: message" for line 0) on one line.
void check_error(std::function<void()> const& read, std::string const& file, std::size_t line,
                 std::string const& part) {
  try {
    read();
    FAIL("no read_error; expected one at line " << line << " containing '" << part << "'");
  } catch (read_error const& e) {
    INFO("what(): " << e.what());
    CHECK(e.file == file);
    CHECK(e.line == line);
    CHECK(e.message.find(part) != std::string::npos);
    std::string prefix = file;
    if (line) prefix.append(":").append(std::to_string(line));
    prefix.append(": ");
    CHECK(std::string(e.what()) == prefix + e.message);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
}

void off_error(std::string const& text, std::size_t line, std::string const& part) {
  INFO("OFF input:\n" << text);
  check_error([&] { off(text); }, "mem.off", line, part);
}

void obj_error(std::string const& text, std::size_t line, std::string const& part) {
  INFO("OBJ input:\n" << text);
  check_error([&] { obj(text); }, "mem.obj", line, part);
}

void stl_error(std::string const& text, std::size_t line, std::string const& part) {
  INFO("STL input:\n" << text);
  check_error([&] { stl(text); }, "mem.stl", line, part);
}

e3::point<Q> P(Q x, Q y, Q z) { return {x, y, z}; }

std::vector<std::uint32_t> idx(std::initializer_list<std::uint32_t> l) { return l; }

/// Little-endian bytes of binary STL, whatever the host's byte order.
void put32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s += static_cast<char>((v >> (8 * i)) & 0xff);
}
void putf(std::string& s, float f) { put32(s, std::bit_cast<std::uint32_t>(f)); }

std::string binary_stl(std::string header, std::vector<std::array<float, 9>> const& triangles) {
  header.resize(80, ' ');
  std::string s = header;
  put32(s, static_cast<std::uint32_t>(triangles.size()));
  for (auto const& t : triangles) {
    for (int k = 0; k < 3; ++k) putf(s, 9.5f); // a wrong normal: it must be ignored
    for (float x : t) putf(s, x);
    s += '\0';
    s += '\0';
  }
  return s;
}

} // namespace

// ---------------------------------------------------------------------------------------------- OFF

TEST_CASE("OFF: decimals, exponents and fractions are read exactly", "[io][off]") {
  auto s = off("OFF\n"
               "3 1 0\n"
               "0.1 -0.25 1e-3\n"
               "2.5E+1 7/3 -0\n"
               "123456789012345678901234567890 0.0000001 3\n"
               "3 0 1 2\n");
  REQUIRE(s.vertices.size() == 3);
  CHECK(s.vertices[0] == P(Q(1, 10), Q(-1, 4), Q(1, 1000)));
  CHECK(s.vertices[0].x() != Q(0.1)); // not the double nearest 0.1
  CHECK(s.vertices[1] == P(25, Q(7, 3), 0));
  CHECK(s.vertices[2].x() == Q(boost::multiprecision::mpz_int("123456789012345678901234567890")));
  CHECK(s.vertices[2].y() == Q(1, 10000000));
  REQUIRE(s.faces.size() == 1);
  CHECK(s.faces[0].vertices == idx({0, 1, 2}));
  CHECK_FALSE(s.faces[0].colour);
  CHECK(s.faces[0].line == 6);
}

TEST_CASE("OFF: comments, blank lines, header variants and face colours", "[io][off]") {
  auto s = off("# a scene\n"
               "OFF   # the header\n"
               "\n"
               "4 3 0 # counts\n"
               "0 0 0\n"
               "1 0 0   # second vertex\n"
               "\t1 1 0\r\n"
               "0 1 0\n"
               "# faces follow\n"
               "3 0 1 2 255 0 51\n"
               "3 0 2 3 0.5 0.25 1 0.5\n"
               "4 0 1 2 3\n");
  REQUIRE(s.vertices.size() == 4);
  CHECK(s.vertices[2] == P(1, 1, 0));
  REQUIRE(s.faces.size() == 3);
  CHECK(s.faces[0].line == 10);
  CHECK(s.faces[1].line == 11);
  CHECK(s.faces[2].line == 12);
  CHECK(s.faces[2].vertices == idx({0, 1, 2, 3}));
  REQUIRE(s.faces[0].colour);
  CHECK(s.faces[0].colour->r == 1.0);
  CHECK(s.faces[0].colour->g == 0.0);
  CHECK(s.faces[0].colour->b == Approx(0.2));
  REQUIRE(s.faces[1].colour);
  CHECK(s.faces[1].colour->r == 0.5);
  CHECK(s.faces[1].colour->g == 0.25);
  CHECK(s.faces[1].colour->b == 1.0);
  CHECK_FALSE(s.faces[2].colour);

  SECTION("counts on the header line, no header at all") {
    auto a = off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n");
    auto b = off("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n");
    CHECK(a.faces[0].vertices == idx({2, 1, 0}));
    CHECK(a.vertices == b.vertices);
    CHECK(a.faces[0].line == 5);
    CHECK(b.faces[0].line == 5);
  }
  SECTION("COFF: per-vertex colours after x y z are ignored") {
    auto c = off("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
    CHECK(c.vertices[1] == P(1, 0, 0));
    CHECK_FALSE(c.faces[0].colour);
  }
  SECTION("no faces is a valid, empty scene") {
    auto e = off("OFF\n0 0 0\n");
    CHECK(e.vertices.empty());
    CHECK(e.faces.empty());
  }
}

TEST_CASE("OFF: every error names the file and the line", "[io][off]") {
  std::string const v3 = "0 0 0\n1 0 0\n0 1 0\n"; // lines 3-5 after "OFF" and the counts
  off_error("", 1, "empty file");
  off_error("# only a comment\n\n", 2, "empty file");
  off_error("OFF\n", 1, "missing the counts line");
  off_error("OFF\n# nothing\n", 2, "missing the counts line");
  off_error("OFF\n3 1\n" + v3 + "3 0 1 2\n", 2, "short counts line");
  off_error("OFF\n\n3\n", 3, "short counts line");
  off_error("OFF\n3 x 0\n", 2, "bad count 'x'");
  off_error("OFF\n-3 1 0\n", 2, "bad count '-3'");
  off_error("OFF\n3 1 0 7\n", 2, "after the counts");
  off_error("4OFF\n3 1 0\n", 1, "unsupported OFF variant");
  off_error("OFF BINARY\n", 1, "binary OFF");
  // Too few vertices or faces: the end of the file is reported at its last line.
  off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n\n# end\n", 6, "unexpected end of file: expected 3 vertices, found 2");
  off_error("OFF\n3 2 0\n" + v3 + "3 0 1 2\n", 6, "unexpected end of file: expected 2 faces, found 1");
  off_error("OFF\n3 1 0\n" + v3, 5, "expected 1 faces, found 0");
  // Vertices.
  off_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4, "vertex needs 3 coordinates");
  off_error("OFF\n3 1 0\n0 0 0\n1 0 0.1.2\n0 1 0\n3 0 1 2\n", 4, "not a number '0.1.2'");
  off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n", 5, "not a number 'zero'");
  // Faces.
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 3\n", 6, "vertex index 3 out of range (3 vertices)");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 -1 2\n", 6, "vertex index -1 out of range");
  off_error("OFF\n3 1 0\n" + v3 + "2 0 1\n", 6, "fewer than 3 vertices");
  off_error("OFF\n3 1 0\n" + v3 + "\n# c\n0\n", 8, "fewer than 3 vertices");
  off_error("OFF\n3 1 0\n" + v3 + "4 0 1 2\n", 6, "declares 4 vertices but lists 3");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1.5 2\n", 6, "bad vertex index '1.5'");
  off_error("OFF\n3 1 0\n" + v3 + "x 0 1 2\n", 6, "bad vertex count 'x'");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 2 1 1\n", 6, "colour of 3 or 4 numbers");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 2 300 0 0\n", 6, "outside 0..255");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 2 0.5 1.5 0\n", 6, "outside 0..1");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 2 red 0 0\n", 6, "not a number 'red'");
  off_error("OFF\n3 1 0\n" + v3 + "3 0 1 2\n\n3 0 1 2\n", 8, "unexpected data after the 1 faces");
}

// ---------------------------------------------------------------------------------------------- OBJ

TEST_CASE("OBJ: exact vertices, w, slashes, relative indices, ignored statements", "[io][obj]") {
  auto s = obj("# exported\n"
               "mtllib nowhere.mtl\n"
               "o thing\n"
               "v 0.1 0.2 0.3\n"
               "v 2 4 6 2\n"
               "v 1 1 1 1\n"
               "v 1 0 0 1 0 0\n" // x y z r g b: colours ignored
               "vt 0 0\n"
               "vn 0 0 1\n"
               "g group\n"
               "s off\n"
               "usemtl none\n"
               "f 1 2 3\n"
               "f 1/1 2/1 3/1\n"
               "f 1//1 2//1 3//1 4//1\n"
               "f 4/1/1 3/1/1 2/1/1\n"
               "f -4 -3 -1\n"
               "l 1 2\n"
               "curv 0 1 1 2\n"
               "f 1 2 \\\n"
               "  3 4\n"
               "v 5 5 5\n"
               "f -1 -2 -3\n");
  REQUIRE(s.vertices.size() == 5);
  CHECK(s.vertices[0] == P(Q(1, 10), Q(1, 5), Q(3, 10)));
  CHECK(s.vertices[1] == P(1, 2, 3));
  CHECK(s.vertices[2] == P(1, 1, 1));
  CHECK(s.vertices[3] == P(1, 0, 0));
  REQUIRE(s.faces.size() == 7);
  CHECK(s.faces[0].vertices == idx({0, 1, 2}));
  CHECK(s.faces[1].vertices == idx({0, 1, 2}));
  CHECK(s.faces[2].vertices == idx({0, 1, 2, 3}));
  CHECK(s.faces[3].vertices == idx({3, 2, 1}));
  CHECK(s.faces[4].vertices == idx({0, 1, 3}));
  CHECK(s.faces[5].vertices == idx({0, 1, 2, 3}));
  CHECK(s.faces[5].line == 20); // a continued statement is reported at its first line
  CHECK(s.faces[6].vertices == idx({4, 3, 2}));
  CHECK(s.faces[0].line == 13);
  for (auto const& f : s.faces) CHECK_FALSE(f.colour); // the .mtl does not exist: no colour, no error

  SECTION("w divides exactly") {
    auto t = obj("v 1 2 3 3\nv 0.5 0.25 1 0.5\n");
    CHECK(t.vertices[0] == P(Q(1, 3), Q(2, 3), 1));
    CHECK(t.vertices[1] == P(1, Q(1, 2), 2));
  }
  SECTION("positive indices may point forward") {
    auto t = obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    CHECK(t.faces[0].vertices == idx({0, 1, 2}));
  }
}

TEST_CASE("OBJ: every error names the file and the line", "[io][obj]") {
  std::string const v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  obj_error("v 1 2\n", 1, "vertex needs 3 coordinates");
  obj_error(v3 + "v 1 2 abc\n", 4, "not a number 'abc'");
  obj_error("\nv 1 2 3 0\n", 2, "w = 0");
  obj_error(v3 + "f 0 1 2\n", 4, "vertex index 0");
  obj_error(v3 + "f 1 2\n", 4, "fewer than 3 vertices");
  obj_error(v3 + "f 1/x 2 3\n", 4, "bad vertex reference '1/x'");
  obj_error(v3 + "f 1 2 3/1/1/1\n", 4, "bad vertex reference");
  obj_error(v3 + "f 1 2 a\n", 4, "bad vertex reference 'a'");
  obj_error(v3 + "f -1 -2 -4\n", 4, "relative vertex index -4 out of range (3 vertices so far)");
  obj_error(v3 + "f 1 2 3\n# more\nf 1 2 9\nv 1 1 1\n", 6, "vertex index 9 out of range (4 vertices)");
  obj_error(v3 + "f 1 2 \\\n 3 x\n", 4, "bad vertex reference 'x'");
}

TEST_CASE("OBJ: materials give face colours through usemtl", "[io][obj]") {
  temp_dir tmp;
  tmp.write("colours.mtl", "# materials\n"
                           "newmtl red\n"
                           "Ka 0 0 0\n"
                           "Kd 1 0 0\n"
                           "newmtl grey\n"
                           "Kd 0.5\n"
                           "newmtl plain\n"
                           "Ns 10\n"
                           "newmtl two words\n"
                           "Kd 0 0 1.2\n");
  auto path = tmp.write("scene.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                     "f 1 2 3\n"
                                     "usemtl red\n"
                                     "f 1 2 3\n"
                                     "usemtl grey\n"
                                     "f 1 2 3\n"
                                     "usemtl plain\n"
                                     "f 1 2 3\n"
                                     "usemtl unknown\n"
                                     "f 1 2 3\n"
                                     "usemtl two words\n"
                                     "f 1 2 3\n"
                                     "mtllib missing.mtl colours.mtl\n"); // after use, and one library missing
  auto s = io::read_scene(path);
  REQUIRE(s.faces.size() == 6);
  CHECK_FALSE(s.faces[0].colour);
  REQUIRE(s.faces[1].colour);
  CHECK(s.faces[1].colour->r == 1.0);
  CHECK(s.faces[1].colour->g == 0.0);
  REQUIRE(s.faces[2].colour);
  CHECK(s.faces[2].colour->g == 0.5);
  CHECK(s.faces[2].colour->b == 0.5);
  CHECK_FALSE(s.faces[3].colour);
  CHECK_FALSE(s.faces[4].colour);
  REQUIRE(s.faces[5].colour);
  CHECK(s.faces[5].colour->b == 1.0); // clamped

  SECTION("read_obj finds the .mtl through the name when it is a path") {
    std::ifstream in(path, std::ios::binary);
    auto t = io::read_obj(in, path.string());
    REQUIRE(t.faces[1].colour);
    CHECK(t.faces[1].colour->r == 1.0);
  }
  SECTION("a bad .mtl is reported at its own file and line") {
    auto bad = tmp.write("bad.mtl", "newmtl red\nKd 1 zero 0\n");
    auto p = tmp.write("bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    check_error([&] { io::read_scene(p); }, bad.string(), 2, "not a number 'zero'");
  }
}

// ---------------------------------------------------------------------------------------------- STL

TEST_CASE("STL: ASCII, exact decimals, one vertex entry per corner", "[io][stl]") {
  std::string text = "solid thing made by hand\n"
                     "  facet normal 0 0 1\n"
                     "    outer loop\n"
                     "      vertex 0.1 0 0\n"
                     "      vertex 1 0.2 0\n"
                     "      vertex 0 1 -3e-1\n"
                     "    endloop\n"
                     "  endfacet\n"
                     "  FACET NORMAL 0 0 0\n"
                     "    OUTER LOOP\n"
                     "      VERTEX 1 0.2 0\n"
                     "      VERTEX 1 1 0\n"
                     "      VERTEX 0 1 -3e-1\n"
                     "    ENDLOOP\n"
                     "  ENDFACET\n"
                     "endsolid thing\n";
  temp_dir tmp;
  auto s = io::read_scene(tmp.write("thing.STL", text));
  REQUIRE(s.vertices.size() == 6);
  CHECK(s.vertices[0] == P(Q(1, 10), 0, 0));
  CHECK(s.vertices[2] == P(0, 1, Q(-3, 10)));
  CHECK(s.vertices[3] == s.vertices[1]); // repeated, not shared
  REQUIRE(s.faces.size() == 2);
  CHECK(s.faces[0].vertices == idx({0, 1, 2}));
  CHECK(s.faces[1].vertices == idx({3, 4, 5}));
  CHECK(s.faces[0].line == 2);
  CHECK(s.faces[1].line == 9);
  CHECK(stl("solid empty\nendsolid empty\n").faces.empty());
}

TEST_CASE("STL: ASCII errors name the file and the line", "[io][stl]") {
  std::string const head = "solid x\nfacet normal 0 0 1\nouter loop\n"; // lines 1-3
  stl_error(head + "vertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n", 7, "fewer than 3 vertices (2)");
  stl_error(head + "vertex 0 0 0\nvertex 1 0\nvertex 0 1 0\n", 5, "vertex needs 3 coordinates");
  stl_error(head + "vertex 0 0 0\nvertex 1 0 0.5.5\n", 5, "not a number '0.5.5'");
  stl_error(head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n\n", 8, "unexpected end of file inside a facet");
  stl_error(head + "vertex 0 0 0\nbogus\n", 5, "unexpected 'bogus' inside a facet");
  stl_error("solid x\nvertex 0 0 0\n", 2, "expected 'facet' or 'endsolid'");
  stl_error("solid x\nendsolid x\nfacet\n", 3, "expected 'solid'");
  stl_error("this is not a mesh\n", 0, "not an STL file");
  stl_error("", 0, "not an STL file");
}

TEST_CASE("STL: binary, recognised by size even when the header starts with 'solid'", "[io][stl]") {
  std::vector<std::array<float, 9>> tris{{0.1f, 0, 0, 1, 0.2f, 0, 0, 1, -0.3f}, {1, 0.2f, 0, 1, 1, 0, 0, 1, -0.3f}};
  std::string data = binary_stl("solid pretending to be ASCII", tris);
  REQUIRE(data.size() == 84 + 50 * 2);
  temp_dir tmp;
  auto path = tmp.write("bin.stl", data);
  auto s = io::read_scene(path);
  REQUIRE(s.vertices.size() == 6);
  REQUIRE(s.faces.size() == 2);
  CHECK(s.faces[0].vertices == idx({0, 1, 2}));
  CHECK(s.faces[1].vertices == idx({3, 4, 5}));
  CHECK(s.faces[0].line == 0);
  // Floats converted exactly: 0.1f is a dyadic rational, not 1/10.
  CHECK(s.vertices[0].x() == Q(static_cast<double>(0.1f)));
  CHECK(s.vertices[0].x() != Q(1, 10));
  Q tenth_f = s.vertices[0].x();
  CHECK(tenth_f == Q(13421773, 134217728)); // 0.1f = 13421773 / 2^27
  CHECK(s.vertices[2] == P(0, 1, Q(static_cast<double>(-0.3f))));
  CHECK(s.vertices[3] == s.vertices[1]);

  SECTION("no triangles") { CHECK(stl(binary_stl("", {})).faces.empty()); }
  SECTION("a wrong size is not binary") {
    check_error([&] { stl(data + "x"); }, "mem.stl", 0, "not an STL file");
  }
  SECTION("a non-finite coordinate is an error") {
    auto bad = binary_stl("nan", {{0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0}});
    check_error([&] { stl(bad); }, "mem.stl", 0, "triangle 0: coordinate is not a finite number");
  }
}

// ------------------------------------------------------------------------------------------ read_scene

TEST_CASE("read_scene: dispatch by extension, and files it cannot open", "[io]") {
  temp_dir tmp;
  std::string const tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CHECK(io::read_scene(tmp.write("a.off", tri)).faces.size() == 1);
  CHECK(io::read_scene(tmp.write("b.OFF", tri)).faces.size() == 1);
  CHECK(io::read_scene(tmp.write("c.Obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).faces.size() == 1);

  auto bad = tmp.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  check_error([&] { io::read_scene(bad); }, bad.string(), 6, "vertex index 5 out of range");

  auto ply = tmp.write("x.ply", tri);
  check_error([&] { io::read_scene(ply); }, ply.string(), 0, "cannot open: unknown scene format '.ply'");
  auto none = tmp.write("noextension", tri);
  check_error([&] { io::read_scene(none); }, none.string(), 0, "cannot open: unknown scene format");
  auto missing = tmp.dir / "missing.off";
  check_error([&] { io::read_scene(missing); }, missing.string(), 0, "cannot open: no such file");
  fs::create_directories(tmp.dir / "dir.stl");
  check_error([&] { io::read_scene(tmp.dir / "dir.stl"); }, (tmp.dir / "dir.stl").string(), 0,
              "cannot open: is a directory");
}

} // namespace io_scene_tests
