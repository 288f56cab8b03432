// Signed distance field of a closed mesh on a regular voxel grid: ray-parity sign, exact narrow
// band, OpenVDB fast sweeping inside.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/mesh/mesh_index.h"
#include "geom/range.h"

#include <array>
#include <cstdint>
#include <vector>

namespace clumpkit {

/// The voxel budget of `clumpkit fill` at its default resolution: a 1:20 plate at 40 voxels
/// across its thickness would take 26e6.
inline constexpr double kDefaultMaxVoxels = 1e6;

/// The most voxels FieldOptions::count_voxel may add: at most this many times the grid of the
/// resolution asked (a fill's time grows with the voxels).
inline constexpr double kCountVoxelGrowth = 3.0;

/// FieldOptions::voxels: the resolutions a field is made at (ignored where voxel_size is given).
inline constexpr Range kFieldVoxels = integers(4, 2000);

/// Resolution of the voxel grid.
struct FieldOptions {
  /// Voxels across the smallest principal extent S of the mesh (ignored if voxel_size > 0; the
  /// smallest bounding-box extent when vote_sign is set), in kFieldVoxels.
  /// 40 resolves the corners of the Jin et al. 2017 blocks well enough for ~350-sphere clumps.
  int voxels = 40;
  double voxel_size = 0.0;  ///< explicit voxel edge length, units of the mesh
  /// The voxel a fill's sphere budget asks for (fill_field_options; 0: none): the voxel above
  /// (from `voxels` or `voxel_size`) is made this fine, but to at most kCountVoxelGrowth times
  /// its voxels and never finer than max_voxels (or, without one, kDefaultMaxVoxels) allows.
  double count_voxel = 0.0;
  /// Budget of the `voxels` resolution (0: none): voxels grow until the grid holds at most this
  /// many, so a platy or elongated shape costs about what a compact one does. `clumpkit fill`
  /// sets kDefaultMaxVoxels unless --voxels is given.
  double max_voxels = 0.0;
  /// Decide inside/outside by Embree ray-parity voting (RayInside) instead of OpenVDB's sign,
  /// for meshes that are not watertight (holes, cracks, flipped patches).
  bool vote_sign = false;
  /// Refuse, before allocating, a field whose fill_bytes_estimate exceeds this many bytes
  /// (0: no limit). The CLI sets it from --max-memory.
  double max_bytes = 0.0;
};

/// Dense signed distance samples at voxel centres: positive inside, negative outside, in the
/// units of the mesh. Each voxel inside and in the band around the surface also keeps its
/// nearest triangle (its feature), and its value is the exact distance to that triangle: exact
/// (not a voxel count) within two voxels of the surface, and deeper inside the distance to the
/// nearest of the triangles its neighbours keep — the true distance but where two features
/// compete (the medial surface), where it can run high by a rounding of the competition. Outside
/// beyond the band: −3 voxels and no feature (only the sign is meant).
struct DistanceField {
  Vec3 origin = Vec3::Zero();  ///< world position of voxel (0, 0, 0)'s centre
  double h = 1.0;              ///< voxel edge length
  std::array<int, 3> dims{0, 0, 0};
  std::vector<float> d;               ///< x fastest, then y, then z
  std::vector<std::int32_t> feature;  ///< nearest triangle per voxel, −1 where none is kept

  std::int64_t index(int i, int j, int k) const {
    return (std::int64_t(k) * dims[1] + j) * dims[0] + i;
  }
  float at(int i, int j, int k) const { return d[index(i, j, k)]; }
  Vec3 position(int i, int j, int k) const { return origin + h * Vec3(i, j, k); }
  /// Trilinear interpolation (clamped to the grid; outside the grid: -h, i.e. outside).
  double sample(const Vec3& p) const;
};

/// Distance from p to the mesh through the features of the 3 × 3 × 3 voxels around p: the
/// smallest exact distance to one of their triangles, so never below the true distance and equal
/// to it wherever one of them is p's nearest triangle (everywhere but where several features
/// compete at p). A few dozen point–triangle distances, whatever the mesh's triangle count;
/// where no feature is kept (far outside) the field's trilinear sample, negated to a magnitude.
double feature_distance(const DistanceField& field, const Mesh& mesh, const Vec3& p);

/// Voxel size implied by the options for this mesh: the fill's coverage lattice, made finer by
/// FieldOptions::count_voxel where the sphere budget asks.
double field_voxel_size(const Mesh& mesh, const FieldOptions& options);

/// Voxel size of the distances make_distance_field computes: the resolution asked, before
/// FieldOptions::count_voxel (distances that fine buy the fill nothing: its spheres take exact
/// radii from the mesh, and only their coverage is counted on the finer lattice).
double distance_voxel_size(const Mesh& mesh, const FieldOptions& options);

/// Voxels of the field make_distance_field would build for this mesh.
double field_voxel_count(const Mesh& mesh, const FieldOptions& options);

/// Estimated peak bytes of make_distance_field and a fill on its grid: 19 per voxel (the dense
/// float field, the sign and band masks, the coverage bits and counts, the medial candidates), 200
/// per triangle (the mesh as read, its Embree BVH) and 64 MiB for the program itself.
double fill_bytes_estimate(const Mesh& mesh, const FieldOptions& options);

/// Builds the field over the mesh bounding box plus two voxels, at distance_voxel_size. The cost
/// does not grow with the triangle count beyond the index's O(log n) queries:
///  1. sign: one ray per grid row along x, inside between crossings 1–2, 3–4, … (or, with
///     vote_sign, a 7-ray vote per voxel for meshes that are not closed);
///  2. exact distances (bounded nearest-triangle queries) in a band of two voxels around the
///     voxels whose face neighbours differ in sign;
///  3. the interior beyond the band: OpenVDB fast sweeping from the band (tools::maskSdf)
///     orders the voxels by depth, and in that order each takes, of the triangles its 26
///     neighbours keep, the nearest (a feature transform: exact point–triangle distances, a few
///     dozen per voxel, however many triangles the mesh has).
/// Throws InvalidInput for a bad resolution, a grid of more than 2e9 voxels (the index range of
/// the coverage grid's rows), or an estimate above options.max_bytes, before allocating.
DistanceField make_distance_field(const MeshIndex& index, const FieldOptions& options);

/// The same with an index built for the call.
DistanceField make_distance_field(const Mesh& mesh, const FieldOptions& options);

/// A field on the finer lattice of `options` (field_voxel_size: the sphere budget's voxel),
/// laid like make_distance_field's, whose values come from `coarse`'s features: the sign by step
/// 1 above, each inside voxel's value feature_distance(coarse, its centre), −h outside; no
/// features kept. What a fill needs of a finer field — its medial candidates and its inside
/// voxels — at a fraction of make_distance_field's cost on that lattice (no band, no sweep).
DistanceField make_finer_field(const MeshIndex& index, const DistanceField& coarse,
                               const FieldOptions& options);

}  // namespace clumpkit
