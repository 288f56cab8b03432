// The fill's overshoot contract: how far past the surface a sphere at a point may reach, and the
// ledger that keeps the clump's volume outside the mesh within --max-overshoot.
#pragma once

#include "geom/fill/distance_field.h"
#include "geom/fill/fill_options.h"
#include "geom/fill/overshoot.h"
#include "geom/mesh/mesh_index.h"

#include <vector>

namespace clumpkit {

/// A sphere the contract placed, and whether it went on the ledger (grown past the surface).
struct PlacedSphere {
  Sphere sphere;
  bool recorded = false;
};

/// The radius rules of FillOptions (tolerance, relative tolerance, max_overshoot) for one mesh
/// and its field. A sphere whose centre lies d inside may take radius grown(d) where it pokes out
/// at point contacts only (fits) and the ledger, on rows a third of a voxel apart, stays within
/// 0.9 of the budget (room for the ledger's midpoint-rule error); else it keeps radius d.
class FillContract {
 public:
  /// `voxel` is the coverage lattice's (the field's, or finer): the ledger's rows lie a third of
  /// it apart. `grid_interior` voxels of it stand for the mesh volume where the mesh is not
  /// closed (options.field.vote_sign, or no positive signed volume).
  FillContract(const MeshIndex& index, const DistanceField& field, const FillOptions& options,
               double voxel, std::int64_t grid_interior);

  /// Distance from p to the surface through the field's features: a few dozen point–triangle
  /// distances, never below the truth (geom/fill/distance_field.h).
  double near_distance(const Vec3& p) const { return feature_distance(field_, mesh_, p); }
  /// Radius of a sphere whose centre lies d inside, grown by the tolerances.
  double grown(double d) const { return d + tolerance_ + relative_ * d; }
  /// False where more than 15 % of 64 directions on the sphere end outside the field: the
  /// surface hugs it (an ellipsoid's waist, a cylinder), so growing would put a band outside.
  bool fits(const Vec3& c, double r) const;
  /// Radius at c, d inside: grown(d) where it fits, else d (the ledger not asked).
  double radius_at(const Vec3& c, double d) const {
    const double g = grown(d);
    return (g > d && !fits(c, g)) ? d : g;
  }
  /// Whether the ledger would stay within the budget with `s` recorded too.
  bool within_budget(const Sphere& s) const;
  /// Outside volume that recording `s` would add to the ledger.
  double added(const Sphere& s) const { return ledger_.added(s); }
  /// Outside volume the budget still allows.
  double spare() const { return outside_budget_ - ledger_.volume(); }
  /// The sphere at c: radius from the exact distance (the features can run high where several
  /// compete), grown if `grow`, it fits and the ledger holds it, and then recorded on the ledger.
  PlacedSphere place(const Vec3& c, bool grow);
  /// Records a sphere again that release() took off (a move undone).
  void record(const Sphere& s);
  /// Takes a recorded sphere off the ledger.
  void release(const Sphere& s);

  /// The ledger's outside volume over the mesh volume.
  double overshoot() const { return ledger_.volume() / mesh_volume_; }
  /// The coverage lattice's voxel.
  double voxel() const { return voxel_; }

 private:
  const MeshIndex& index_;
  const Mesh& mesh_;
  const DistanceField& field_;
  double voxel_, tolerance_, relative_;
  std::vector<Vec3> directions_;
  OvershootLedger ledger_;
  double mesh_volume_, outside_budget_;
};

}  // namespace clumpkit
