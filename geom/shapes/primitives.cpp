#include "geom/shapes/primitives.h"

#include "geom/errors.h"
#include "geom/limits.h"

#include <cmath>
#include <map>
#include <string>

namespace clumpkit {

namespace {
void require_positive(const Vec3& v, const char* what) {
  for (int k = 0; k < 3; ++k) check_size(v[k], what);
}
}  // namespace

Mesh make_box(const Vec3& size) {
  require_positive(size, "box size");
  Mesh m;
  const Vec3 h = 0.5 * size;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                            (i & 4) ? h.z() : -h.z());
  // Two triangles per face, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

Mesh make_cylinder(double diameter, double height, int sides) {
  check_size(diameter, "cylinder diameter");
  check_size(height, "cylinder height");
  require(kCylinderSides, sides, "cylinder sides");
  Mesh m;
  const double r = 0.5 * diameter, h = 0.5 * height;
  for (const double z : {-h, h})
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * M_PI * k / sides;
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
  const int bottom = 2 * sides, top = bottom + 1;
  m.vertices.emplace_back(0.0, 0.0, -h);
  m.vertices.emplace_back(0.0, 0.0, h);
  for (int k = 0; k < sides; ++k) {
    const int a = k, b = (k + 1) % sides;  // ring indices, counter-clockwise seen from +z
    m.triangles.push_back({bottom, b, a});
    m.triangles.push_back({top, sides + a, sides + b});
    m.triangles.push_back({a, b, sides + b});
    m.triangles.push_back({a, sides + b, sides + a});
  }
  return m;
}

Mesh make_icosphere(int level) {
  if (level < 0 || level > 8)
    throw InvalidInput("icosphere level must be in [0, 8], got " + std::to_string(level));
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : m.vertices) v.normalize();
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      const int id = static_cast<int>(m.vertices.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(m.triangles.size() * 4);
    for (const auto& f : m.triangles) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.push_back({f[0], a, c});
      next.push_back({f[1], b, a});
      next.push_back({f[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  return m;
}

Mesh make_ellipsoid(const Vec3& semi_axes, int level) {
  require_positive(semi_axes, "ellipsoid semi-axis");
  Mesh m = make_icosphere(level);
  for (auto& v : m.vertices) v = v.cwiseProduct(semi_axes);
  return m;
}

Mesh make_octahedron(double radius) {
  check_size(radius, "octahedron radius");
  Mesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      Vec3 v = Vec3::Zero();
      v[axis] = sign * radius;
      m.vertices.push_back(v);
    }
  // One face per octant, counter-clockwise seen from outside (x, y, z vertices of its signs).
  for (int octant = 0; octant < 8; ++octant) {
    const int x = (octant & 1), y = 2 + ((octant >> 1) & 1), z = 4 + ((octant >> 2) & 1);
    const int negatives = (octant & 1) + ((octant >> 1) & 1) + ((octant >> 2) & 1);
    if (negatives % 2 == 0)
      m.triangles.push_back({x, y, z});
    else
      m.triangles.push_back({x, z, y});
  }
  return m;
}

Mesh make_torus(double ring, double tube, int ring_sides, int tube_sides) {
  check_size(ring, "torus ring radius");
  check_size(tube, "torus tube radius");
  if (!(tube < ring))
    throw InvalidInput("torus: the tube radius must be below the ring radius, got " +
                       std::to_string(tube) + " and " + std::to_string(ring));
  require(kTorusSides, ring_sides, "torus ring_sides");
  require(kTorusSides, tube_sides, "torus tube_sides");
  Mesh m;
  for (int i = 0; i < ring_sides; ++i) {
    const double u = 2.0 * M_PI * i / ring_sides;
    for (int j = 0; j < tube_sides; ++j) {
      const double v = 2.0 * M_PI * j / tube_sides;
      const double rho = ring + tube * std::cos(v);
      m.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), tube * std::sin(v));
    }
  }
  for (int i = 0; i < ring_sides; ++i)
    for (int j = 0; j < tube_sides; ++j) {
      const int a = i * tube_sides + j, b = ((i + 1) % ring_sides) * tube_sides + j;
      const int c = ((i + 1) % ring_sides) * tube_sides + (j + 1) % tube_sides;
      const int d = i * tube_sides + (j + 1) % tube_sides;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

}  // namespace clumpkit
