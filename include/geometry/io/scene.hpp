/// @file
/// Scene input: OFF, OBJ (with MTL diffuse colours) and STL (ASCII and binary)
/// read into exact rational vertices and indexed faces.
///
/// Exactness starts here (DESIGN.md §3): decimals in text files are read with
/// `parse_number<rational>`, so `0.1` is exactly 1/10, and the 32-bit floats
/// of binary STL are converted exactly (every float is a dyadic rational).
/// Faces keep their file order, because the face index is what the command
/// line reports (DESIGN.md §6).  Every error is a `read_error` whose `what()`
/// is one line `FILE:LINE: message`, ready for stderr.
#pragma once

#include "../e3/objects.hpp"
#include "../number.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace geometry::io {

/// A colour with components in [0, 1]: doubles, because colours only reach
/// the drawing and never a predicate.
struct rgb {
  double r; ///< red
  double g; ///< green
  double b; ///< blue
};

/// A polygon scene as read from a file: exact vertices and faces that index
/// them.  Faces are not checked for planarity or convexity here; that is the
/// job of `convex_polygons` (polygons.hpp), which keeps the face index.
struct scene {
  /// The vertices, exact: coordinates exactly as written in the file.
  std::vector<e3::point<rational>> vertices;

  /// One face of the file: a cycle of vertex indices, as written.
  struct face {
    std::vector<std::uint32_t> vertices; ///< 0-based indices into `scene::vertices`, in file order
    std::optional<rgb> colour;           ///< the face's colour when the file gives one
    std::size_t line = 0; ///< 1-based line of the face in the file, for messages; 0 when none (binary STL)
  };

  /// The faces in file order: a face's index is its position (0-based), the
  /// number every later stage reports.
  std::vector<face> faces;
};

/// Bad input: `what()` is exactly one line `FILE:LINE: message`, or
/// `FILE: message` when no line applies (`line == 0`: unreadable file,
/// unknown format, binary data), as DESIGN.md §6 asks of command-line errors.
struct read_error : std::runtime_error {
  std::string file;    ///< the file name as given by the caller
  std::size_t line;    ///< 1-based line number, 0 when the error concerns the whole file
  std::string message; ///< the message alone, without the `FILE:LINE: ` prefix
  int error_code = 0;  ///< a file that cannot be opened: its `errno` value (ENOENT, EACCES, EISDIR …); 0 for bad content

  /// The error `message` at `line` of `file_name` (`code`: see `error_code`).
  read_error(std::string file_name, std::size_t line_number, std::string text, int code = 0)
      : std::runtime_error(format(file_name, line_number, text)), file(std::move(file_name)), line(line_number),
        message(std::move(text)), error_code(code) {}

private:
  // Newlines are replaced so that a strange file name cannot break the one-line promise.
  static std::string format(std::string const& file, std::size_t line, std::string const& text) {
    std::string s = file;
    if (line) s.append(":").append(std::to_string(line));
    s.append(": ").append(text);
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    return s;
  }
};

namespace detail {

/// Concatenates the pieces of a message.  Built by appending, because GCC 12
/// warns falsely about `"literal" + std::string` at -O3 (-Wrestrict, GCC bug
/// 105651), which -Werror turns into a build failure for users.
template <class... Piece> std::string cat(Piece const&... piece) {
  std::string s;
  (s.append(std::string_view(piece)), ...);
  return s;
}

/// A token quoted for a message, shortened so that a runaway token (a binary
/// file read as text) cannot flood the terminal.
inline std::string quoted(std::string_view t) {
  constexpr std::size_t max = 40;
  if (t.size() > max) return cat("'", t.substr(0, max), "...'");
  return cat("'", t, "'");
}

/// Token separators: `\r` among them, so that files with DOS line ends read alike.
inline bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// ASCII lower case, independent of the global locale (which `std::tolower` reads).
inline char lower(char c) noexcept { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

/// Case-insensitive comparison with a lower-case keyword (STL exporters write both cases).
inline bool iequals(std::string_view t, std::string_view keyword) noexcept {
  if (t.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (lower(t[i]) != keyword[i]) return false;
  return true;
}

/// A whole signed integer token (`+` allowed), or nothing: indices and counts
/// must be integers, and `3.0` or `3x` as an index is an error, not a 3.
inline std::optional<long long> to_integer(std::string_view t) {
  if (!t.empty() && t[0] == '+') {
    t.remove_prefix(1);
    if (!t.empty() && (t[0] == '+' || t[0] == '-')) return std::nullopt;
  }
  long long v = 0;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

/// Reads a text file line by line and splits each line into tokens, keeping
/// the line number for messages.  Comments (from `comment` to the end of the
/// line) and blank lines are skipped; with `continuation`, a line ending in
/// a backslash goes on in the next one (OBJ), and messages name its first line.
class line_reader {
public:
  line_reader(std::istream& in, std::string const& file, char comment, bool continuation = false)
      : in_(in), file_(file), comment_(comment), continuation_(continuation) {}

  /// Reads up to the next line with a token; false at the end of the input.
  bool next() {
    tokens_.clear();
    while (tokens_.empty()) {
      if (!read_statement()) return false;
      tokenize();
    }
    return true;
  }

  /// The tokens of the current line: views into it, valid until `next()`.
  std::vector<std::string_view> const& tokens() const noexcept { return tokens_; }

  /// The tokens from `i` on as one string, spaces inside kept (material names).
  std::string rest(std::size_t i) const {
    if (i >= tokens_.size()) return {};
    auto first = tokens_[i].data();
    auto last = tokens_.back().data() + tokens_.back().size();
    return std::string(first, last);
  }

  /// 1-based line of the current statement.
  std::size_t line() const noexcept { return first_; }

  /// The file name, for messages.
  std::string const& file() const noexcept { return file_; }

  /// Throws `message` at the current statement's line.
  [[noreturn]] void fail(std::string const& message) const {
    throw read_error(file_, std::max<std::size_t>(first_, 1), message);
  }

  /// Throws `message` at the last line of the file: what was missing would
  /// have come after it.
  [[noreturn]] void fail_at_end(std::string const& message) const {
    throw read_error(file_, std::max<std::size_t>(last_, 1), message);
  }

  /// The token `t` as an exact number, or the parser's reason at this line.
  rational number(std::string_view t) const {
    try {
      return parse_number<rational>(t);
    } catch (parse_error const& e) {
      fail(e.what());
    }
  }

private:
  bool read_line(std::string& s) {
    if (!std::getline(in_, s)) {
      if (in_.bad()) throw read_error(file_, last_, "read error");
      return false;
    }
    ++last_;
    if (last_ == 1 && s.starts_with("\xEF\xBB\xBF")) s.erase(0, 3); // a UTF-8 byte-order mark is not a token
    return true;
  }

  bool read_statement() {
    if (!read_line(text_)) return false;
    first_ = last_;
    strip_comment(text_);
    while (continuation_ && ends_with_backslash(text_)) {
      text_.pop_back();
      std::string more;
      if (!read_line(more)) break;
      strip_comment(more);
      text_ += ' ';
      text_ += more;
    }
    return true;
  }

  void strip_comment(std::string& s) const {
    if (auto p = s.find(comment_); p != std::string::npos) s.erase(p);
  }

  static bool ends_with_backslash(std::string& s) {
    while (!s.empty() && is_space(s.back())) s.pop_back();
    return !s.empty() && s.back() == '\\';
  }

  void tokenize() {
    std::string_view s = text_;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_space(s[i])) ++i;
      std::size_t j = i;
      while (j < s.size() && !is_space(s[j])) ++j;
      if (j > i) tokens_.push_back(s.substr(i, j - i));
      i = j;
    }
  }

  std::istream& in_;
  std::string const& file_;
  char comment_;
  bool continuation_;
  std::string text_;
  std::vector<std::string_view> tokens_;
  std::size_t first_ = 0; // line where the current statement starts
  std::size_t last_ = 0;  // last line read
};

/// Whether `t` is an OFF header keyword, `[ST][C][N][4][n]OFF` (Geomview's
/// variants); sets `unsupported` for the homogeneous (4) and n-dimensional (n)
/// ones, which do not describe points of E3.
inline bool is_off_keyword(std::string_view t, bool& unsupported) {
  if (!t.ends_with("OFF")) return false;
  t.remove_suffix(3);
  unsupported = false;
  if (t.starts_with("ST")) t.remove_prefix(2);
  for (char c : {'C', 'N', '4', 'n'})
    if (!t.empty() && t[0] == c) {
      if (c == '4' || c == 'n') unsupported = true;
      t.remove_prefix(1);
    }
  return t.empty();
}

/// A face colour of 3 or 4 OFF tokens: integers mean 0..255, anything else
/// 0..1 (Geomview's convention); alpha is checked and dropped.
inline rgb off_colour(line_reader const& r, std::vector<std::string_view> const& t, std::size_t first) {
  bool integers = true;
  for (std::size_t i = first; i < t.size(); ++i) integers = integers && to_integer(t[i]).has_value();
  double c[4] = {0, 0, 0, 1};
  for (std::size_t i = first; i < t.size(); ++i) {
    double x = 0;
    try {
      x = parse_number<double>(t[i]);
    } catch (parse_error const& e) {
      r.fail(e.what());
    }
    double max = integers ? 255 : 1;
    if (!(x >= 0 && x <= max))
      r.fail(detail::cat("colour component ", quoted(t[i]), " outside ", (integers ? "0..255" : "0..1")));
    c[i - first] = integers ? x / 255 : x;
  }
  return {c[0], c[1], c[2]};
}

/// Materials of an MTL file: name → diffuse colour (none when it has no `Kd`).
using material_map = std::map<std::string, std::optional<rgb>>;

/// Reads the diffuse colours (`Kd`) of an MTL file into `out`.  Spectral and
/// CIE XYZ forms of `Kd` are skipped (no colour); components are clamped to
/// [0, 1], since some exporters write slightly out-of-range values.
inline void read_mtl(std::istream& in, std::string const& name, material_map& out) {
  line_reader r(in, name, '#', true);
  std::string current;
  bool have = false;
  while (r.next()) {
    auto const& t = r.tokens();
    if (t[0] == "newmtl") {
      current = r.rest(1);
      out[current] = std::nullopt;
      have = true;
    } else if (t[0] == "Kd" && have) {
      if (t.size() > 1 && (t[1] == "spectral" || t[1] == "xyz")) continue;
      if (t.size() != 2 && t.size() != 4)
        r.fail(detail::cat("Kd needs 1 or 3 numbers, found ", std::to_string(t.size() - 1)));
      double c[3];
      for (std::size_t i = 0; i < 3; ++i) {
        auto tok = t[t.size() == 2 ? 1 : i + 1];
        try {
          c[i] = std::clamp(parse_number<double>(tok), 0.0, 1.0);
        } catch (parse_error const& e) {
          r.fail(e.what());
        }
      }
      out[current] = rgb{c[0], c[1], c[2]};
    }
  }
}

/// Little-endian 32-bit word at `p`, independent of the host's byte order.
inline std::uint32_t le32(char const* p) noexcept {
  auto b = [p](int i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(p[i])); };
  return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}

/// Binary STL is recognised by its size, 84 + 50·n bytes with n the count at
/// byte 80, and not by a missing `solid`: many binary exporters start their
/// 80-byte header with "solid".
inline bool is_binary_stl(std::string_view d) noexcept {
  if (d.size() < 84) return false;
  return (d.size() - 84) % 50 == 0 && (d.size() - 84) / 50 == le32(d.data() + 80);
}

/// The triangles of binary STL data `d` (already known to have the right size).
inline scene read_binary_stl(std::string_view d, std::string const& name) {
  scene s;
  std::size_t n = le32(d.data() + 80);
  s.vertices.reserve(3 * n);
  s.faces.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    char const* p = d.data() + 84 + 50 * t + 12; // the facet normal is ignored: orientation comes from the vertex order
    scene::face f;
    for (int v = 0; v < 3; ++v) {
      rational c[3];
      for (int k = 0; k < 3; ++k) {
        float x = std::bit_cast<float>(le32(p + 12 * v + 4 * k));
        if (!std::isfinite(x))
          throw read_error(name, 0, detail::cat("triangle ", std::to_string(t), ": coordinate is not a finite number"));
        c[k] = rational(static_cast<double>(x)); // exact: a float is a dyadic rational
      }
      f.vertices.push_back(static_cast<std::uint32_t>(s.vertices.size()));
      s.vertices.emplace_back(c[0], c[1], c[2]);
    }
    s.faces.push_back(std::move(f));
  }
  return s;
}

/// The facets of ASCII STL: `solid` … (`facet` … `outer loop`, `vertex x y z` …,
/// `endloop`, `endfacet`) … `endsolid`, repeated; a facet may have more than 3
/// vertices (some exporters write polygons), never fewer.
inline scene read_ascii_stl(std::istream& in, std::string const& name) {
  line_reader r(in, name, '\0'); // STL has no comments; a NUL never occurs in text
  scene s;
  enum { outside, in_solid, in_facet } state = outside;
  scene::face f;
  bool first = true;
  while (r.next()) {
    auto const& t = r.tokens();
    if (first && !iequals(t[0], "solid"))
      throw read_error(name, 0, "not an STL file: neither binary (84 + 50 n bytes) nor ASCII (starting with 'solid')");
    first = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      auto tok = t[i];
      if (state == outside) {
        if (!iequals(tok, "solid")) r.fail(detail::cat("expected 'solid', found ", quoted(tok)));
        state = in_solid;
        break; // the rest of the line is the solid's name
      } else if (state == in_solid) {
        if (iequals(tok, "facet")) {
          state = in_facet;
          f = scene::face{};
          f.line = r.line();
          break; // "normal nx ny nz": the facet normal is ignored
        }
        if (iequals(tok, "endsolid")) {
          state = outside;
          break;
        }
        r.fail(detail::cat("expected 'facet' or 'endsolid', found ", quoted(tok)));
      } else {
        if (iequals(tok, "outer") || iequals(tok, "loop") || iequals(tok, "endloop")) continue;
        if (iequals(tok, "vertex")) {
          if (t.size() - i < 4) r.fail("vertex needs 3 coordinates x y z");
          rational x = r.number(t[i + 1]), y = r.number(t[i + 2]), z = r.number(t[i + 3]);
          f.vertices.push_back(static_cast<std::uint32_t>(s.vertices.size()));
          s.vertices.emplace_back(std::move(x), std::move(y), std::move(z));
          i += 3;
          continue;
        }
        if (iequals(tok, "endfacet")) {
          if (f.vertices.size() < 3)
            r.fail(detail::cat("facet with fewer than 3 vertices (", std::to_string(f.vertices.size()), ")"));
          s.faces.push_back(std::move(f));
          state = in_solid;
          continue;
        }
        r.fail(detail::cat("unexpected ", quoted(tok), " inside a facet"));
      }
    }
  }
  if (first) throw read_error(name, 0, "not an STL file: empty");
  if (state == in_facet) r.fail_at_end("unexpected end of file inside a facet (missing 'endfacet')");
  return s; // a missing final 'endsolid' is tolerated: nothing is lost
}

} // namespace detail

/// Reads an OFF scene from `in`; `name` is the file name used in messages.
///
/// Accepted: an optional header `OFF` (or a Geomview variant `COFF`, `NOFF`,
/// `STOFF`, … — per-vertex extras after x y z are ignored), the counts line
/// `nv nf ne` (it may follow the header on the same line), `nv` vertex lines
/// `x y z` read exactly, and `nf` face lines `k i0 … ik-1 [r g b [a]]` whose
/// optional colour is integers 0..255 or decimals 0..1.  Comments run from
/// `#` to the end of a line, anywhere; blank lines are skipped.
///
/// Strict where leniency would lose data silently: a short counts line, a
/// missing vertex or face (reported at the last line), an index out of range,
/// a face of fewer than 3 indices, a bad number, and data after the declared
/// faces are all `read_error`s at the offending line.
inline scene read_off(std::istream& in, std::string const& name) {
  detail::line_reader r(in, name, '#');
  scene s;
  if (!r.next()) r.fail_at_end("empty file: expected 'OFF' and the counts line 'vertices faces edges'");
  std::size_t first = 0;
  bool unsupported = false;
  if (detail::is_off_keyword(r.tokens()[0], unsupported)) {
    if (unsupported)
      r.fail(detail::cat("unsupported OFF variant ", detail::quoted(r.tokens()[0]), ": only 3D points are read"));
    if (r.tokens().size() > 1 && r.tokens()[1] == "BINARY") r.fail("binary OFF is not supported");
    first = 1;
    if (r.tokens().size() == 1) {
      if (!r.next()) r.fail_at_end("unexpected end of file: missing the counts line 'vertices faces edges'");
      first = 0;
    }
  }
  auto const& c = r.tokens();
  if (c.size() - first < 3)
    r.fail(detail::cat("short counts line: expected 'vertices faces edges', found ", std::to_string(c.size() - first),
                       " number(s)"));
  if (c.size() - first > 3)
    r.fail(detail::cat("unexpected ", detail::quoted(c[first + 3]), " after the counts 'vertices faces edges'"));
  std::size_t counts[3];
  for (std::size_t i = 0; i < 3; ++i) {
    auto v = detail::to_integer(c[first + i]);
    if (!v || *v < 0)
      r.fail(detail::cat("bad count ", detail::quoted(c[first + i]), ": expected a non-negative integer"));
    counts[i] = static_cast<std::size_t>(*v);
  }
  std::size_t nv = counts[0], nf = counts[1];
  if (nv > std::numeric_limits<std::uint32_t>::max()) r.fail("too many vertices for 32-bit indices");
  // Bogus counts must not allocate: reserve at most what a sane file would hold.
  s.vertices.reserve(std::min<std::size_t>(nv, 1 << 20));
  s.faces.reserve(std::min<std::size_t>(nf, 1 << 20));

  for (std::size_t i = 0; i < nv; ++i) {
    if (!r.next())
      r.fail_at_end(
          detail::cat("unexpected end of file: expected ", std::to_string(nv), " vertices, found ", std::to_string(i)));
    auto const& t = r.tokens();
    if (t.size() < 3) r.fail(detail::cat("vertex needs 3 coordinates x y z, found ", std::to_string(t.size())));
    s.vertices.emplace_back(r.number(t[0]), r.number(t[1]), r.number(t[2]));
  }

  for (std::size_t j = 0; j < nf; ++j) {
    if (!r.next())
      r.fail_at_end(
          detail::cat("unexpected end of file: expected ", std::to_string(nf), " faces, found ", std::to_string(j)));
    auto const& t = r.tokens();
    auto k = detail::to_integer(t[0]);
    if (!k || *k < 0) r.fail(detail::cat("bad vertex count ", detail::quoted(t[0]), " at the start of a face"));
    if (*k < 3) r.fail(detail::cat("face with fewer than 3 vertices (", std::to_string(*k), ")"));
    std::size_t n = static_cast<std::size_t>(*k);
    if (t.size() - 1 < n)
      r.fail(detail::cat("face declares ", std::to_string(n), " vertices but lists ", std::to_string(t.size() - 1)));
    scene::face f;
    f.line = r.line();
    f.vertices.reserve(n);
    for (std::size_t i = 1; i <= n; ++i) {
      auto v = detail::to_integer(t[i]);
      if (!v) r.fail(detail::cat("bad vertex index ", detail::quoted(t[i])));
      if (*v < 0 || static_cast<unsigned long long>(*v) >= nv)
        r.fail(detail::cat("vertex index ", std::to_string(*v), " out of range (", std::to_string(nv), " vertices)"));
      f.vertices.push_back(static_cast<std::uint32_t>(*v));
    }
    std::size_t extra = t.size() - 1 - n;
    if (extra == 3 || extra == 4)
      f.colour = detail::off_colour(r, t, n + 1);
    else if (extra != 0)
      r.fail(detail::cat("expected a colour of 3 or 4 numbers after the face's ", std::to_string(n), " indices, found ",
                         std::to_string(extra)));
    s.faces.push_back(std::move(f));
  }
  // More data means the counts are wrong: stopping here would drop faces silently.
  if (r.next())
    r.fail(detail::cat("unexpected data after the ", std::to_string(nf), " faces declared in the counts line"));
  return s;
}

/// Reads a Wavefront OBJ scene from `in`; `name` is the file name used in
/// messages and, when it names an existing file, the place next to which the
/// `mtllib` files are looked for.
///
/// Read: `v x y z [w]` (exact; w ≠ 1 divides exactly, w = 0 is an error;
/// extra vertex colours are ignored), `f` with `a`, `a/t`, `a//n`, `a/t/n`
/// references and negative (relative) indices, `mtllib` and `usemtl` (the
/// material's diffuse colour `Kd` becomes the face colour).  Every other
/// statement (`vt`, `vn`, `g`, `o`, `s`, `l`, …) is ignored, as the format
/// allows.  A missing `.mtl` file or an unknown material is not an error: the
/// face has no colour.  Positive indices may refer to vertices defined later
/// in the file; they are checked at the end, at the face's line.
inline scene read_obj(std::istream& in, std::string const& name) {
  detail::line_reader r(in, name, '#', true);
  scene s;
  std::vector<std::string> libraries;
  std::vector<std::pair<std::size_t, std::string>> materials_used; // (face, material), resolved at the end
  std::string current;
  while (r.next()) {
    auto const& t = r.tokens();
    if (t[0] == "v") {
      if (t.size() < 4) r.fail(detail::cat("vertex needs 3 coordinates x y z, found ", std::to_string(t.size() - 1)));
      rational x = r.number(t[1]), y = r.number(t[2]), z = r.number(t[3]);
      if (t.size() == 5) { // x y z w; 6 or more numbers are x y z r g b (vertex colours), ignored
        rational w = r.number(t[4]);
        if (w == 0) r.fail("vertex with w = 0 (a point at infinity)");
        if (w != 1) x /= w, y /= w, z /= w;
      }
      if (s.vertices.size() > std::numeric_limits<std::uint32_t>::max()) r.fail("too many vertices for 32-bit indices");
      s.vertices.emplace_back(std::move(x), std::move(y), std::move(z));
    } else if (t[0] == "f") {
      if (t.size() < 4) r.fail(detail::cat("face with fewer than 3 vertices (", std::to_string(t.size() - 1), ")"));
      scene::face f;
      f.line = r.line();
      for (std::size_t i = 1; i < t.size(); ++i) {
        // a, a/t, a//n, a/t/n: only the vertex a matters; t and n must still be indices.
        std::string_view ref = t[i];
        std::size_t slash = ref.find('/');
        auto a = detail::to_integer(ref.substr(0, slash));
        bool ok = a.has_value();
        if (ok && slash != std::string_view::npos) {
          std::string_view tail = ref.substr(slash + 1);
          std::size_t s2 = tail.find('/');
          std::string_view tex = tail.substr(0, s2);
          ok = tex.empty() ? s2 != std::string_view::npos : detail::to_integer(tex).has_value();
          if (ok && s2 != std::string_view::npos) ok = detail::to_integer(tail.substr(s2 + 1)).has_value();
        }
        if (!ok) r.fail(detail::cat("bad vertex reference ", detail::quoted(ref), ": expected a, a/t, a//n or a/t/n"));
        long long v = *a;
        long long nv = static_cast<long long>(s.vertices.size());
        if (v == 0) r.fail("vertex index 0: OBJ indices start at 1");
        if (v < 0) {
          if (-v > nv)
            r.fail(detail::cat("relative vertex index ", std::to_string(v), " out of range (", std::to_string(nv),
                               " vertices so far)"));
          v = nv + v;
        } else {
          if (v - 1 > static_cast<long long>(std::numeric_limits<std::uint32_t>::max()))
            r.fail(detail::cat("vertex index ", std::to_string(v), " out of range"));
          v = v - 1;
        }
        f.vertices.push_back(static_cast<std::uint32_t>(v));
      }
      if (!current.empty()) materials_used.emplace_back(s.faces.size(), current);
      s.faces.push_back(std::move(f));
    } else if (t[0] == "usemtl") {
      current = r.rest(1);
    } else if (t[0] == "mtllib") {
      for (std::size_t i = 1; i < t.size(); ++i) libraries.emplace_back(t[i]);
    }
  }
  for (auto const& f : s.faces)
    for (auto v : f.vertices)
      if (v >= s.vertices.size())
        throw read_error(name, f.line,
                         detail::cat("vertex index ", std::to_string(std::uint64_t{v} + 1), " out of range (",
                                     std::to_string(s.vertices.size()), " vertices)"));

  if (!materials_used.empty() && !libraries.empty()) {
    std::error_code ec;
    std::filesystem::path self(name);
    if (std::filesystem::is_regular_file(self, ec)) {
      detail::material_map materials;
      for (auto const& lib : libraries) {
        auto path = self.parent_path() / lib;
        std::ifstream mtl(path, std::ios::binary);
        if (mtl) detail::read_mtl(mtl, path.string(), materials);
      }
      for (auto const& [face, material] : materials_used)
        if (auto it = materials.find(material); it != materials.end()) s.faces[face].colour = it->second;
    }
  }
  return s;
}

/// Reads an STL scene, binary or ASCII, from `in`; `name` is the file name
/// used in messages.
///
/// Binary is recognised by size (84 + 50·n bytes), its floats converted
/// exactly; ASCII coordinates are read exactly from their decimals.  Each
/// triangle gets its own three vertex entries (STL shares none), facet normals
/// are ignored (the vertex order gives the orientation), and keywords are
/// matched in any case.
inline scene read_stl(std::istream& in, std::string const& name) {
  std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw read_error(name, 0, "read error");
  if (detail::is_binary_stl(data)) return detail::read_binary_stl(data, name);
  // Text never holds a NUL: this is binary STL of the wrong size, most likely cut short.
  if (data.find('\0') != std::string::npos)
    throw read_error(name, 0,
                     detail::cat("not an STL file: binary data of ", std::to_string(data.size()),
                                 " bytes, but binary STL has 84 + 50 n bytes",
                                 data.size() >= 84
                                     ? detail::cat(" with n = ", std::to_string(detail::le32(data.data() + 80)),
                                                   " triangles (truncated?)")
                                     : std::string()));
  std::istringstream text(std::move(data));
  return detail::read_ascii_stl(text, name);
}

/// Reads the scene in the file `path`, choosing the reader by its extension
/// (`.off`, `.obj`, `.stl`, in any case).  An unknown extension or a file that
/// cannot be opened is a `read_error` with line 0 (`FILE: cannot open …`).
inline scene read_scene(std::filesystem::path const& path) {
  std::string file = path.string();
  std::string ext = path.extension().string();
  for (char& ch : ext) ch = detail::lower(ch);
  scene (*reader)(std::istream&, std::string const&) = nullptr;
  if (ext == ".off")
    reader = read_off;
  else if (ext == ".obj")
    reader = read_obj;
  else if (ext == ".stl")
    reader = read_stl;
  else
    throw read_error(file, 0,
                     detail::cat("cannot open: unknown scene format ",
                                 (ext.empty() ? std::string("(no extension)") : detail::quoted(ext)),
                                 ", expected .off, .obj or .stl"));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw read_error(file, 0, "cannot open: is a directory", EISDIR);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    bool exists = std::filesystem::exists(path, ec);
    throw read_error(file, 0, exists ? "cannot open: not readable" : "cannot open: no such file", exists ? EACCES : ENOENT);
  }
  return reader(in, file);
}

} // namespace geometry::io
