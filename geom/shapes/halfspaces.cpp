#include "geom/shapes/halfspaces.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/cgal_mesh.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>

namespace clumpkit {

Mesh intersect_halfspaces(const std::vector<Halfspace>& halfspaces, const Vec3& interior) {
  std::vector<double> offset(halfspaces.size());  // h − n·p: the plane's offset about p
  std::vector<Vec3> dual;
  std::map<std::array<double, 3>, int> plane_of;
  for (std::size_t i = 0; i < halfspaces.size(); ++i) {
    offset[i] = halfspaces[i].offset - halfspaces[i].normal.dot(interior);
    if (!(offset[i] > 0.0))
      throw InvalidInput(
          "half-space intersection: the interior point is not strictly inside "
          "half-space " +
          std::to_string(i) + " (offset " + format_number(offset[i]) + ")");
    dual.push_back(halfspaces[i].normal / offset[i]);
    plane_of.emplace(std::array<double, 3>{dual.back().x(), dual.back().y(), dual.back().z()},
                     static_cast<int>(i));
  }
  const Mesh dual_hull = convex_hull(dual);
  std::vector<int> plane(dual_hull.vertices.size());
  for (std::size_t i = 0; i < plane.size(); ++i) {
    const Vec3& d = dual_hull.vertices[i];
    plane[i] = plane_of.at({d.x(), d.y(), d.z()});
  }
  std::vector<Vec3> corners;
  corners.reserve(dual_hull.triangles.size());
  for (const auto& t : dual_hull.triangles) {
    std::array<int, 3> ids{plane[t[0]], plane[t[1]], plane[t[2]]};
    std::sort(ids.begin(), ids.end());
    Mat3 a;
    Vec3 b;
    for (int k = 0; k < 3; ++k) {
      a.row(k) = halfspaces[ids[k]].normal.transpose();
      b[k] = offset[ids[k]];
    }
    corners.push_back(a.fullPivLu().solve(b) + interior);
  }
  return convex_hull(corners);  // deduplicates corners shared by 4+ planes
}

}  // namespace clumpkit
