#include "dem/measure/fragment_sizes.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>

namespace clumpkit::dem {

Vec3 fragment_extents(const std::vector<Body>& bodies, const std::vector<int>& members) {
  double mass = 0;
  Vec3 centroid = Vec3::Zero();
  for (int k : members) {
    mass += bodies[k].mass;
    centroid += bodies[k].mass * bodies[k].position;
  }
  centroid /= mass;
  Mat3 inertia = Mat3::Zero();
  for (int k : members) {
    const Body& b = bodies[k];
    const Mat3 r = b.orientation.toRotationMatrix();
    const Vec3 d = b.position - centroid;
    inertia += r * b.moments.asDiagonal() * r.transpose() +
               b.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inertia);
  const Mat3 axes = eigen.eigenvectors();
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (int k : members) {
    const Body& b = bodies[k];
    for (const Sphere& s : b.spheres) {
      const Vec3 x = axes.transpose() * (b.position + b.orientation * s.center - centroid);
      low = low.cwiseMin(x - Vec3::Constant(s.radius));
      high = high.cwiseMax(x + Vec3::Constant(s.radius));
    }
  }
  Vec3 e = high - low;
  std::sort(e.data(), e.data() + 3, std::greater<double>());
  return e;
}

std::vector<SievedPiece> fragment_pieces(const std::vector<Body>& bodies,
                                         const std::vector<Bond>& bonds) {
  const int n = static_cast<int>(bodies.size());
  const std::vector<int> label = fragments(n, bonds);
  std::vector<std::vector<int>> members(n);
  for (int k = 0; k < n; ++k) {
    if (!(bodies[k].volume > 0))
      throw InvalidInput("fragments: body " + std::to_string(k) + " has volume " +
                         format_number(bodies[k].volume));
    members[label[k]].push_back(k);
  }
  std::vector<SievedPiece> pieces;
  for (int k = 0; k < n; ++k) {
    if (members[k].empty()) continue;
    SievedPiece p;
    for (int m : members[k]) p.volume += bodies[m].volume;
    p.size = fragment_extents(bodies, members[k])[1];
    pieces.push_back(p);
  }
  return pieces;
}

}  // namespace clumpkit::dem
