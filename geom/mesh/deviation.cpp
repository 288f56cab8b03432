#include "geom/mesh/deviation.h"

#include "geom/mesh/mesh_index.h"

#include <vector>

namespace clumpkit {

SurfaceDeviation surface_deviation(const Mesh& from, const Mesh& to) {
  SurfaceDeviation d;
  if (from.triangles.empty() || to.triangles.empty()) return d;
  std::vector<Vec3> samples = from.vertices;
  samples.reserve(from.vertices.size() + 4 * from.triangles.size());
  for (const auto& t : from.triangles) {
    const Vec3 &a = from.vertices[std::size_t(t[0])], &b = from.vertices[std::size_t(t[1])],
               &c = from.vertices[std::size_t(t[2])];
    samples.push_back((a + b + c) / 3.0);
    // Each edge's midpoint once: from the triangle that walks it in increasing vertex order.
    if (t[0] < t[1]) samples.push_back(0.5 * (a + b));
    if (t[1] < t[2]) samples.push_back(0.5 * (b + c));
    if (t[2] < t[0]) samples.push_back(0.5 * (c + a));
  }
  const MeshIndex index(to);
  double sum = 0;
  for (const Vec3& p : samples) {
    const double dist = index.distance(p);
    sum += dist;
    if (dist > d.max) d.max = dist, d.at = p;
  }
  d.samples = static_cast<int>(samples.size());
  d.mean = sum / static_cast<double>(samples.size());
  return d;
}

}  // namespace clumpkit
