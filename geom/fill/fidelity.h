// How faithful a clump is to its mesh: covered and overshooting volume, surface gaps, and mass
// properties against the solid.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/mesh/mesh_index.h"
#include "geom/sphere.h"

namespace clumpkit {

/// Fidelity of a clump against the closed mesh it was made from (units of the mesh).
struct Fidelity {
  int spheres = 0;
  bool watertight = true;    ///< closed, manifold, consistently oriented
  double mesh_volume = 0.0;  ///< exact polyhedron volume (estimated if not watertight)
  const char* mesh_volume_method = "exact (divergence theorem)";
  double clump_volume = 0.0;  ///< exact union volume (union_properties)
  const char* clump_volume_method = "exact (power diagram)";
  double covered_fraction = 0.0;    ///< V(clump ∩ mesh) / V(mesh)
  double overshoot_fraction = 0.0;  ///< V(clump \ mesh) / V(mesh)
  double surface_mean_distance =
      0.0;  ///< mean |distance| from mesh surface points to the clump surface
  double surface_max_distance = 0.0;
  double centroid_offset = 0.0;  ///< |centroid(clump) − centroid(mesh)|
  double inertia_error = 0.0;    ///< max relative error of the principal moments
  double overshoot_depth_max =
      0.0;  ///< max over spheres of radius − centre-to-surface distance (≥ 0)
};

/// Calls visit(name, member pointer) for each field of the fidelity report, in its order: the
/// one list the JSON record (`clumpkit fill --json`, the library's records) and the Python
/// attributes are written from. `watertight` is not in it: the jobs report the mesh's own state.
template <class Visit>
void for_each_fidelity_field(Visit&& visit) {
  visit("spheres", &Fidelity::spheres);
  visit("mesh_volume", &Fidelity::mesh_volume);
  visit("mesh_volume_method", &Fidelity::mesh_volume_method);
  visit("clump_volume", &Fidelity::clump_volume);
  visit("clump_volume_method", &Fidelity::clump_volume_method);
  visit("covered_fraction", &Fidelity::covered_fraction);
  visit("overshoot_fraction", &Fidelity::overshoot_fraction);
  visit("surface_mean_distance", &Fidelity::surface_mean_distance);
  visit("surface_max_distance", &Fidelity::surface_max_distance);
  visit("centroid_offset", &Fidelity::centroid_offset);
  visit("inertia_error", &Fidelity::inertia_error);
  visit("overshoot_depth_max", &Fidelity::overshoot_depth_max);
}

/// Clump volume, centroid and inertia are exact (power diagram). The part of the clump outside
/// the mesh comes from exact 1-D integration along x of every row of a (y, z) lattice with spacing
/// `spacing` (mesh intervals from the row's surface crossings, clump intervals from sphere
/// chords), so only the 2-D midpoint rule in (y, z) approximates it. Surface distances at points
/// spread by area, four per spacing². A mesh that is not watertight is classified by Embree
/// ray-parity voting along each row instead, and its volume estimated the same way (labelled).
/// spacing ≤ 0 picks 1/200 of the mesh's largest extent.
Fidelity assess_fidelity(const Mesh& mesh, const Clump& clump, double spacing = 0.0);

/// The same for a mesh known to be watertight (read_mesh checked it), with its index: nothing
/// in it grows with the triangle count but the mesh's volume integrals.
Fidelity assess_fidelity(const MeshIndex& index, const Clump& clump, double spacing = 0.0);

/// The volumes alone (mesh and clump volume, covered and overshoot fractions, as
/// assess_fidelity gives them; the other fields stay 0): what a fill's figures before its
/// refinement need, without the surface samples and mass properties.
Fidelity assess_volumes(const Mesh& mesh, const Clump& clump, double spacing = 0.0);
Fidelity assess_volumes(const MeshIndex& index, const Clump& clump, double spacing = 0.0);

}  // namespace clumpkit
