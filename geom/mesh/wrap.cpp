#include "geom/mesh/wrap.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/cgal_surface.h"

#include <CGAL/alpha_wrap_3.h>

#include <array>
#include <cmath>
#include <vector>

namespace clumpkit {

Mesh alpha_wrap(const Mesh& soup, double alpha, double offset) {
  if (!(std::isfinite(alpha) && alpha > 0))
    throw InvalidInput("wrap: alpha must be positive, got " + format_number(alpha));
  if (!(std::isfinite(offset) && offset > 0))
    throw InvalidInput("wrap: offset must be positive, got " + format_number(offset));
  if (soup.triangles.empty()) throw InvalidInput("wrap: no triangle to wrap");
  std::vector<cgal_surface::Point> points;
  points.reserve(soup.vertices.size());
  for (const Vec3& p : soup.vertices) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles)
    faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  cgal_surface::SurfaceMesh wrap;
  CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
  return cgal_surface::from_surface_mesh(wrap);
}

}  // namespace clumpkit
