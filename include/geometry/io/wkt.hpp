/// @file
/// Reading polygons from WKT (OGC simple features): `POLYGON`, `MULTIPOLYGON`
/// and `GEOMETRYCOLLECTION`s of them, `EMPTY` anywhere, keywords in any case.
/// Coordinates are exact; `Z`, `M` and `ZM` geometries are refused (they are
/// not planar polygons), as are other geometry types.
#pragma once

#include "planar.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace geometry::io {

namespace detail {

/// A WKT tokenizer: words, numbers, `(`, `)`, `,`, with line numbers.
class wkt_lexer {
public:
  wkt_lexer(std::string_view text, std::string name) : t_(text), name_(std::move(name)) {}

  [[noreturn]] void fail(std::string const& message) const { throw read_error(name_, line_, message); }

  /// The next token without taking it; empty at the end.
  std::string_view peek() {
    skip();
    if (i_ >= t_.size()) return {};
    char c = t_[i_];
    if (c == '(' || c == ')' || c == ',') return t_.substr(i_, 1);
    std::size_t j = i_;
    while (j < t_.size() && !is_space(t_[j]) && t_[j] != '\n' && t_[j] != '(' && t_[j] != ')' && t_[j] != ',') ++j;
    return t_.substr(i_, j - i_);
  }
  std::string_view next() {
    auto s = peek();
    i_ += s.size();
    return s;
  }
  void expect(std::string_view what) {
    auto s = next();
    if (s != what) fail(cat("expected '", std::string(what), "', found ", s.empty() ? "the end" : quoted(s)));
  }
  bool at_end() { return peek().empty(); }

private:
  void skip() {
    while (i_ < t_.size() && (is_space(t_[i_]) || t_[i_] == '\n')) {
      if (t_[i_] == '\n') ++line_;
      ++i_;
    }
  }
  std::string_view t_;
  std::string name_;
  std::size_t i_ = 0, line_ = 1;
};

inline rational wkt_number(wkt_lexer& lx) {
  auto s = lx.next();
  if (s.empty() || s == "(" || s == ")" || s == ",") lx.fail(cat("expected a coordinate, found ", s.empty() ? "the end" : quoted(s)));
  try {
    return parse_number<rational>(s);
  } catch (parse_error const& e) {
    lx.fail(e.what());
  }
}

/// `EMPTY`, or `(` … `)` read by `body`.
template <class F> void wkt_list(wkt_lexer& lx, F&& item) {
  if (iequals(lx.peek(), "empty")) {
    lx.next();
    return;
  }
  lx.expect("(");
  for (;;) {
    item();
    auto s = lx.next();
    if (s == ")") return;
    if (s != ",") lx.fail(cat("expected ',' or ')', found ", s.empty() ? "the end" : quoted(s)));
  }
}

/// A list of positions `(x y, …)`, or `EMPTY`.
inline ring wkt_positions(wkt_lexer& lx) {
  ring r;
  wkt_list(lx, [&] {
    rational x = wkt_number(lx), y = wkt_number(lx);
    auto s = lx.peek();
    if (s != "," && s != ")") lx.fail("a vertex has more than two coordinates");
    r.emplace_back(std::move(x), std::move(y));
  });
  return r;
}

inline ring wkt_ring(wkt_lexer& lx) {
  ring r = wkt_positions(lx);
  if (!r.empty() && r.size() < 4) lx.fail("a ring needs at least 4 positions (3 vertices and the first repeated)");
  if (!r.empty() && !(r.front() == r.back())) lx.fail("a ring is not closed: its last position differs from its first");
  if (!r.empty()) r.pop_back();
  return r;
}

inline void wkt_polygon(wkt_lexer& lx, multipolygon& out) {
  polygon_with_holes p;
  bool first = true;
  wkt_list(lx, [&] {
    ring r = wkt_ring(lx);
    if (first)
      p.outer = std::move(r);
    else if (!r.empty())
      p.holes.push_back(std::move(r));
    first = false;
  });
  if (!p.outer.empty()) out.push_back(std::move(p));
}

/// An open path: at least two positions.
inline ring wkt_path(wkt_lexer& lx) {
  ring r = wkt_positions(lx);
  if (r.size() == 1) lx.fail("a line string needs at least 2 positions");
  return r;
}

/// Polygons into `out`; line strings into `lines`, or an error when it is null.
inline void wkt_geometry(wkt_lexer& lx, multipolygon& out, std::vector<ring>* lines = nullptr) {
  auto kind = lx.next();
  auto dim = lx.peek();
  if (iequals(dim, "z") || iequals(dim, "m") || iequals(dim, "zm"))
    lx.fail(cat("only planar geometries are read, not ", std::string(kind), " ", std::string(dim)));
  auto path = [&] {
    ring r = wkt_path(lx);
    if (!r.empty()) lines->push_back(std::move(r));
  };
  if (iequals(kind, "polygon"))
    wkt_polygon(lx, out);
  else if (iequals(kind, "multipolygon"))
    wkt_list(lx, [&] { wkt_polygon(lx, out); });
  else if (iequals(kind, "geometrycollection"))
    wkt_list(lx, [&] { wkt_geometry(lx, out, lines); });
  else if (lines && iequals(kind, "linestring"))
    path();
  else if (lines && iequals(kind, "multilinestring"))
    wkt_list(lx, path);
  else if (lines)
    lx.fail(cat("expected POLYGON, MULTIPOLYGON, LINESTRING, MULTILINESTRING or GEOMETRYCOLLECTION, found ",
                kind.empty() ? "the end" : quoted(kind)));
  else
    lx.fail(cat("expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found ", kind.empty() ? "the end" : quoted(kind)));
}

} // namespace detail

/// The polygons of a WKT text (one geometry; `name` is used in messages).
/// Rings must be closed (first position repeated at the end) and have at
/// least three distinct positions; orientation is not checked here.
inline multipolygon read_wkt(std::string_view text, std::string const& name) {
  detail::wkt_lexer lx(text, name);
  multipolygon out;
  detail::wkt_geometry(lx, out);
  if (!lx.at_end()) lx.fail(detail::cat("unexpected ", detail::quoted(lx.peek()), " after the geometry"));
  return out;
}

/// The polygons and line strings of a WKT text.
inline multipolygon read_wkt(std::string_view text, std::string const& name, std::vector<ring>& lines) {
  detail::wkt_lexer lx(text, name);
  multipolygon out;
  detail::wkt_geometry(lx, out, &lines);
  if (!lx.at_end()) lx.fail(detail::cat("unexpected ", detail::quoted(lx.peek()), " after the geometry"));
  return out;
}

/// Reads a whole file as text, or throws `read_error` naming it.
inline std::string read_text(std::filesystem::path const& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::error_code ec;
    throw read_error(path.string(), 0, "cannot open the file", std::filesystem::exists(path, ec) ? EACCES : ENOENT);
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace geometry::io
