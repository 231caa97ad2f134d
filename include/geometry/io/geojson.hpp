/// @file
/// Reading polygons from GeoJSON (RFC 7946): `Polygon`, `MultiPolygon`,
/// `GeometryCollection`, `Feature` and `FeatureCollection` (the set is the
/// union of all polygons found; features without polygons are skipped).
///
/// A small JSON parser of its own, because numbers must stay exact (a JSON
/// library would round `0.1` to a double) and errors must name the line.
/// Positions are `[x, y]` or `[longitude, latitude]`; a third coordinate
/// (altitude) is allowed and ignored, as the RFC allows.
#pragma once

#include "planar.hpp"
#include "wkt.hpp"

#include <cctype>
#include <map>
#include <memory>
#include <string>

namespace geometry::io {

namespace detail {

/// A JSON value with the line it starts on; numbers keep their text.
struct json_value {
  enum class kind { null, boolean, number, string, array, object } type = kind::null;
  std::string text; ///< a number's text, a string's value, `true`/`false`
  std::vector<json_value> items;
  struct member; // a key and its value (a pair would need json_value complete here)
  std::vector<member> members;
  std::size_t line = 0;

  json_value const* find(std::string_view key) const;
};

struct json_value::member {
  std::string key;
  json_value value;
};

inline json_value const* json_value::find(std::string_view key) const {
  for (auto const& [k, v] : members)
    if (k == key) return &v;
  return nullptr;
}

class json_parser {
public:
  json_parser(std::string_view text, std::string name) : t_(text), name_(std::move(name)) {}

  json_value parse_document() {
    json_value v = value(0);
    skip();
    if (i_ < t_.size()) fail("unexpected text after the JSON value");
    return v;
  }

  [[noreturn]] void fail(std::string const& message) const { throw read_error(name_, line_, message); }

private:
  void skip() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\r' || t_[i_] == '\n')) {
      if (t_[i_] == '\n') ++line_;
      ++i_;
    }
  }
  char peek() {
    skip();
    return i_ < t_.size() ? t_[i_] : '\0';
  }
  void expect(char c) {
    if (peek() != c) fail(cat("expected '", std::string(1, c), "'", i_ < t_.size() ? cat(", found '", std::string(1, t_[i_]), "'") : ", found the end"));
    ++i_;
  }
  json_value value(int depth) {
    if (depth > 64) fail("JSON nested too deeply");
    json_value v;
    char c = peek();
    v.line = line_;
    if (c == '{') {
      v.type = json_value::kind::object;
      ++i_;
      if (peek() == '}') return ++i_, v;
      for (;;) {
        if (peek() != '"') fail("expected a member name in quotes");
        std::string key = string_body();
        expect(':');
        v.members.push_back({std::move(key), value(depth + 1)});
        if (peek() == ',') {
          ++i_;
          continue;
        }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      v.type = json_value::kind::array;
      ++i_;
      if (peek() == ']') return ++i_, v;
      for (;;) {
        v.items.push_back(value(depth + 1));
        if (peek() == ',') {
          ++i_;
          continue;
        }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.type = json_value::kind::string;
      v.text = string_body();
      return v;
    }
    std::size_t j = i_;
    while (j < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[j])) || t_[j] == '-' || t_[j] == '+' || t_[j] == '.'))
      ++j;
    std::string_view word = t_.substr(i_, j - i_);
    if (word.empty()) fail(i_ < t_.size() ? cat("unexpected '", std::string(1, t_[i_]), "'") : "unexpected end of the file");
    i_ = j;
    if (word == "null") return v;
    if (word == "true" || word == "false") {
      v.type = json_value::kind::boolean;
      v.text = word;
      return v;
    }
    v.type = json_value::kind::number;
    v.text = word;
    return v;
  }
  std::string string_body() {
    ++i_; // the opening quote
    std::string s;
    while (i_ < t_.size() && t_[i_] != '"') {
      if (t_[i_] == '\n') fail("a string runs past the end of the line");
      if (t_[i_] == '\\' && i_ + 1 < t_.size()) {
        s += t_[i_ + 1] == 'n' ? '\n' : t_[i_ + 1]; // names only matter up to escapes
        i_ += t_[i_ + 1] == 'u' ? 6 : 2;
        continue;
      }
      s += t_[i_++];
    }
    if (i_ >= t_.size()) fail("a string is not closed");
    ++i_;
    return s;
  }
  std::string_view t_;
  std::string name_;
  std::size_t i_ = 0, line_ = 1;
};

class geojson_reader {
public:
  explicit geojson_reader(std::string name) : name_(std::move(name)) {}

  void object(json_value const& v, multipolygon& out) {
    if (v.type != json_value::kind::object) fail(v, "expected a GeoJSON object");
    auto const* type = v.find("type");
    if (!type || type->type != json_value::kind::string) fail(v, "a GeoJSON object has no \"type\"");
    auto const& t = type->text;
    if (t == "FeatureCollection") {
      for (auto const& f : array(v, "features").items) object(f, out);
    } else if (t == "Feature") {
      auto const* g = v.find("geometry");
      if (g && g->type != json_value::kind::null) geometry(*g, out, false);
    } else {
      geometry(v, out, true);
    }
  }

private:
  [[noreturn]] void fail(json_value const& at, std::string const& message) const { throw read_error(name_, at.line, message); }

  json_value const& array(json_value const& v, char const* key) {
    auto const* a = v.find(key);
    if (!a) fail(v, cat("missing \"", key, "\""));
    if (a->type != json_value::kind::array) fail(*a, cat("\"", key, "\" is not an array"));
    return *a;
  }

  void geometry(json_value const& v, multipolygon& out, bool top) {
    auto const* type = v.find("type");
    if (!type || type->type != json_value::kind::string) fail(v, "a geometry has no \"type\"");
    auto const& t = type->text;
    if (t == "Polygon") {
      polygon(array(v, "coordinates"), out);
    } else if (t == "MultiPolygon") {
      for (auto const& p : array(v, "coordinates").items) polygon(p, out);
    } else if (t == "GeometryCollection") {
      for (auto const& g : array(v, "geometries").items) geometry(g, out, false);
    } else if (lines_ && t == "LineString") {
      path(array(v, "coordinates"));
    } else if (lines_ && t == "MultiLineString") {
      for (auto const& p : array(v, "coordinates").items) path(p);
    } else if (lines_ && !(t == "Point" || t == "MultiPoint")) {
      fail(v, cat("expected a Polygon, MultiPolygon, LineString, MultiLineString, GeometryCollection, Feature or FeatureCollection, found \"", t, "\""));
    } else if (!lines_ && (top || !(t == "Point" || t == "MultiPoint" || t == "LineString" || t == "MultiLineString"))) {
      fail(v, cat("expected a Polygon, MultiPolygon, GeometryCollection, Feature or FeatureCollection, found \"", t, "\""));
    }
  }

  void path(json_value const& v) {
    if (v.type != json_value::kind::array) fail(v, "a line string's coordinates are not an array of positions");
    ring r;
    for (auto const& pos : v.items) r.push_back(position(pos));
    if (r.size() == 1) fail(v, "a line string needs at least 2 positions");
    if (!r.empty()) lines_->push_back(std::move(r));
  }

  point2 position(json_value const& pos) {
    if (pos.type != json_value::kind::array || pos.items.size() < 2 || pos.items.size() > 3)
      fail(pos, "a position is not an array of 2 or 3 numbers");
    rational c[2];
    for (std::size_t k = 0; k < 2; ++k) {
      if (pos.items[k].type != json_value::kind::number) fail(pos, "a coordinate is not a number");
      try {
        c[k] = parse_number<rational>(pos.items[k].text);
      } catch (parse_error const& e) {
        fail(pos, e.what());
      }
    }
    return point2(c[0], c[1]);
  }

public:
  /// Line strings go to `lines` instead of being skipped (or refused at the top).
  void keep_lines(std::vector<ring>* lines) { lines_ = lines; }

private:

  void polygon(json_value const& v, multipolygon& out) {
    if (v.type != json_value::kind::array) fail(v, "a polygon's coordinates are not an array of rings");
    polygon_with_holes p;
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      ring r = ring_of(v.items[i]);
      if (i == 0)
        p.outer = std::move(r);
      else
        p.holes.push_back(std::move(r));
    }
    if (!p.outer.empty()) out.push_back(std::move(p));
  }

  ring ring_of(json_value const& v) {
    if (v.type != json_value::kind::array) fail(v, "a ring is not an array of positions");
    ring r;
    for (auto const& pos : v.items) r.push_back(position(pos));
    if (r.empty()) return r;
    if (r.size() < 4) fail(v, "a ring needs at least 4 positions (3 vertices and the first repeated)");
    if (!(r.front() == r.back())) fail(v, "a ring is not closed: its last position differs from its first");
    r.pop_back();
    return r;
  }

  std::string name_;
  std::vector<ring>* lines_ = nullptr;
};

} // namespace detail

/// The polygons of a GeoJSON text (`name` is used in messages).
inline multipolygon read_geojson(std::string_view text, std::string const& name) {
  detail::json_parser p(text, name);
  auto doc = p.parse_document();
  multipolygon out;
  detail::geojson_reader(name).object(doc, out);
  return out;
}

/// Polygons and line strings of a plane scene (2D visibility's walls).
struct plane_walls {
  multipolygon polygons;
  std::vector<ring> lines; ///< open paths, each of at least 2 positions
};

/// The polygons and line strings of a WKT or GeoJSON file.
inline plane_walls read_walls(std::filesystem::path const& path) {
  std::string text = read_text(path);
  plane_walls out;
  auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') {
    detail::json_parser p(text, path.string());
    auto doc = p.parse_document();
    detail::geojson_reader r(path.string());
    r.keep_lines(&out.lines);
    r.object(doc, out.polygons);
  } else {
    out.polygons = read_wkt(text, path.string(), out.lines);
  }
  return out;
}

/// The polygons of a WKT or GeoJSON file, told apart by their first
/// character (`{` starts GeoJSON).
inline multipolygon read_polygons(std::filesystem::path const& path) {
  std::string text = read_text(path);
  auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return read_geojson(text, path.string());
  return read_wkt(text, path.string());
}

} // namespace geometry::io
