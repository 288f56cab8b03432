// The text helpers and the polygon triangulation that the mesh readers share
// (io/formats/mesh_formats.h).
#include "geom/errors.h"
#include "io/base/text.h"
#include "io/formats/mesh_formats.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>

namespace clumpkit::mesh_format {

void bad(const std::string& path, const std::string& what) {
  throw InvalidInput(path + ": " + what);
}

std::string at_line(const std::string& path, int line) {
  return path + ": line " + std::to_string(line);
}

std::string plural(std::size_t n, const std::string& noun) {
  if (n == 1) return "1 " + noun;
  // "copy" -> "copies" (a consonant before the y), "key" -> "keys".
  const std::size_t k = noun.size();
  if (k >= 2 && noun[k - 1] == 'y' &&
      std::string_view("aeiou").find(noun[k - 2]) == std::string_view::npos)
    return std::to_string(n) + " " + noun.substr(0, k - 1) + "ies";
  return std::to_string(n) + " " + noun + "s";
}

std::string shown(std::string_view token) {
  std::string s;
  for (const char ch : token.substr(0, 40)) {
    const auto c = static_cast<unsigned char>(ch);
    char buf[8];
    std::snprintf(buf, sizeof buf, c >= 0x20 && c < 0x7f ? "%c" : "\\x%02x", c);
    s += buf;
  }
  return token.size() > 40 ? s + "..." : s;
}

double parse_number(std::string_view tok, const std::string& where) {
  const std::optional<double> v = to_number(tok);
  if (!v) throw InvalidInput(where + ": cannot parse '" + shown(tok) + "' as a number");
  return *v;
}

long long parse_integer(std::string_view tok, const std::string& where) {
  const std::optional<long long> v = to_integer(tok);
  if (!v) throw InvalidInput(where + ": cannot parse '" + shown(tok) + "' as an integer");
  return *v;
}

bool Lines::next(std::vector<std::string_view>& tokens) {
  if (pos_ >= text_.size()) return false;
  tokens.clear();
  bool more = true;
  while (more && pos_ < text_.size()) {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const std::size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    more = false;
    // OBJ's line continuation: a backslash at the end of the line (alone or on the last token).
    if (continuation_ && !tokens.empty() && tokens.back().back() == '\\') {
      tokens.back().remove_suffix(1);
      if (tokens.back().empty()) tokens.pop_back();
      more = true;
    }
  }
  return true;
}

std::size_t Lines::offset() const {
  return std::min(pos_, text_.size());
}

namespace {

// Twice the signed area of the 2-D triangle (a, b, c).
double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

}  // namespace

void triangulate_polygon(const std::vector<Vec3>& vertices, const std::vector<int>& face,
                         std::vector<std::array<int, 3>>& triangles) {
  const std::size_t n = face.size();
  const auto fan = [&](const std::vector<int>& f) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) triangles.push_back({f[0], f[k], f[k + 1]});
  };
  if (n <= 3) return fan(face);
  // Newell's normal: robust for any planar (or nearly planar) polygon, convex or not.
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = vertices[face[i]];
    const Vec3& b = vertices[face[(i + 1) % n]];
    normal += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                   (a.x() - b.x()) * (a.y() + b.y()));
  }
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  if (!(std::abs(normal[axis]) > 0)) return fan(face);  // no plane: nothing better to do
  // The polygon in the plane that drops the normal's largest component, turned so that it runs
  // counter-clockwise there.
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const double turn = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> p(n);
  for (std::size_t i = 0; i < n; ++i)
    p[i] = Eigen::Vector2d(vertices[face[i]][u], turn * vertices[face[i]][w]);
  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i)
    convex = cross2(p[i], p[(i + 1) % n], p[(i + 2) % n]) >= 0;
  if (convex) return fan(face);
  // Ear clipping: cut off a convex corner whose triangle holds no other corner, until three
  // are left (O(n²) per polygon; file polygons are small).
  std::vector<std::size_t> left(n);
  for (std::size_t i = 0; i < n; ++i) left[i] = i;
  while (left.size() > 3) {
    const std::size_t m = left.size();
    bool cut = false;
    for (std::size_t k = 0; k < m && !cut; ++k) {
      const std::size_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
      if (!(cross2(p[a], p[b], p[c]) > 0)) continue;  // reflex or flat corner
      bool empty = true;
      for (std::size_t q : left) {
        if (q == a || q == b || q == c) continue;
        if (cross2(p[a], p[b], p[q]) >= 0 && cross2(p[b], p[c], p[q]) >= 0 &&
            cross2(p[c], p[a], p[q]) >= 0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      triangles.push_back({face[a], face[b], face[c]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if (!cut) break;  // a self-overlapping polygon: fan what is left
  }
  std::vector<int> rest;
  for (std::size_t i : left) rest.push_back(face[i]);
  fan(rest);
}

}  // namespace clumpkit::mesh_format
