#include "geom/mesh/refine.h"

#include "geom/errors.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace clumpkit {

Mesh refine(const Mesh& mesh, std::int64_t min_triangles) {
  if (min_triangles > 50000000)
    throw InvalidInput("--triangles must be at most 5e7, got " + std::to_string(min_triangles));
  if (mesh.triangles.empty()) throw InvalidInput("the mesh has no triangles");
  Mesh out = mesh;
  while (static_cast<std::int64_t>(out.triangles.size()) < min_triangles) {
    // Midpoint of edge (a, b), a < b, made once.
    std::unordered_map<std::uint64_t, int> mid;
    mid.reserve(out.triangles.size() * 2);
    auto midpoint = [&](int a, int b) {
      const std::uint64_t key =
          (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
      auto [it, inserted] = mid.emplace(key, static_cast<int>(out.vertices.size()));
      if (inserted) out.vertices.push_back(0.5 * (out.vertices[a] + out.vertices[b]));
      return it->second;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(4 * out.triangles.size());
    for (const auto& t : out.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      // Same orientation as the parent: three corners and the middle.
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    out.triangles = std::move(next);
  }
  return out;
}

}  // namespace clumpkit
