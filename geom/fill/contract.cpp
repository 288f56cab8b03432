#include "geom/fill/contract.h"

#include <algorithm>
#include <cmath>

namespace clumpkit {

namespace {

// 64 directions of a Fibonacci sphere (golden-angle steps in longitude).
std::vector<Vec3> fibonacci_directions() {
  std::vector<Vec3> directions(64);
  for (int q = 0; q < 64; ++q) {
    const double z = 1.0 - (2.0 * q + 1.0) / 64.0, rho = std::sqrt(1.0 - z * z);
    const double phi = q * 2.399963229728653;
    directions[q] = Vec3(rho * std::cos(phi), rho * std::sin(phi), z);
  }
  return directions;
}

// The ledger's box: the field's and a tenth more (a sphere grows past the surface by a few
// percent of its radius).
std::array<Vec3, 2> ledger_box(const DistanceField& field) {
  const Vec3 hi =
      field.origin + field.h * Vec3(field.dims[0] - 1, field.dims[1] - 1, field.dims[2] - 1);
  const Vec3 margin = 0.1 * (hi - field.origin).maxCoeff() * Vec3::Ones();
  return {field.origin - margin, hi + margin};
}

}  // namespace

FillContract::FillContract(const MeshIndex& index, const DistanceField& field,
                           const FillOptions& options, double voxel, std::int64_t grid_interior)
    : index_(index),
      mesh_(index.mesh()),
      field_(field),
      voxel_(voxel),
      tolerance_(options.tolerance >= 0 ? options.tolerance : options.tolerance_voxels * voxel),
      relative_(options.tolerance_relative),
      directions_(fibonacci_directions()),
      ledger_(index, ledger_box(field), voxel / 3.0) {
  // The mesh volume: exact for a closed mesh, the interior voxels' for one that is not.
  const double closed_volume = signed_volume(mesh_);
  mesh_volume_ = options.field.vote_sign || !(closed_volume > 0.0)
                     ? double(grid_interior) * voxel * voxel * voxel
                     : closed_volume;
  outside_budget_ = 0.9 * options.max_overshoot * mesh_volume_;
}

bool FillContract::fits(const Vec3& c, double r) const {
  int outside = 0;
  for (const auto& u : directions_) outside += field_.sample(c + r * u) < 0.0;
  return outside <= 9;
}

bool FillContract::within_budget(const Sphere& s) const {
  return ledger_.volume() + ledger_.added(s) <= outside_budget_;
}

PlacedSphere FillContract::place(const Vec3& c, bool grow) {
  const double d = index_.distance(c, near_distance(c) * (1.0 + 1e-9) + 1e-12 * voxel_);
  const double g = grown(d);
  if (grow && g > d && fits(c, g)) {
    const Sphere big{c, g};
    if (within_budget(big)) {
      ledger_.add(big);
      return {big, true};
    }
  }
  return {Sphere{c, d}, false};
}

void FillContract::record(const Sphere& s) {
  ledger_.add(s);
}

void FillContract::release(const Sphere& s) {
  ledger_.remove(s);
}

}  // namespace clumpkit
