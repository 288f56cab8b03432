#include "geom/template/clump_template.h"

#include "geom/volume/union_of_balls.h"

#include <Eigen/Eigenvalues>

namespace clumpkit {

Mat3 principal_axes(const Mat3& inertia, Vec3& moments) {
  Eigen::SelfAdjointEigenSolver<Mat3> es(inertia);
  Mat3 axes = es.eigenvectors();  // ascending eigenvalues
  for (int k = 0; k < 3; ++k) {
    int big = 0;
    for (int q = 1; q < 3; ++q)
      if (std::abs(axes(q, k)) > std::abs(axes(big, k))) big = q;
    if (axes(big, k) < 0) axes.col(k) *= -1.0;
  }
  if (axes.determinant() < 0) axes.col(2) *= -1.0;
  moments = es.eigenvalues();
  return axes;
}

ClumpTemplate make_clump_template(const Clump& clump, double mesh_volume) {
  const UnionProperties u = union_properties(clump);
  ClumpTemplate t;
  const Mat3 axes = principal_axes(u.mass.inertia, t.principal_moments);
  t.orientation = Eigen::Quaterniond(axes).normalized();
  t.position = u.mass.centroid;
  t.mass.volume = u.mass.volume;
  t.mass.centroid = Vec3::Zero();
  t.mass.inertia = t.principal_moments.asDiagonal();
  for (const auto& s : clump.spheres)
    t.spheres.push_back(Sphere{axes.transpose() * (s.center - u.mass.centroid), s.radius});
  if (mesh_volume > 0.0) t.density_factor = mesh_volume / u.mass.volume;
  return t;
}

}  // namespace clumpkit
