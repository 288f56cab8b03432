// One fraction of a shape recipe (method, count, parameter distributions) and the generator
// that draws one particle of it.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/random.h"
#include "geom/range.h"
#include "geom/shapes/distribution.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {

/// The particles of a drawn fraction (FractionSpec::count; a mesh fraction has one per file).
inline constexpr Range kFractionCount = integers(0, 10000000);
/// The factor from a mesh fraction's length unit to the recipe's (FractionSpec::scale; finite).
inline constexpr Range kMeshScale = above(0);

/// A group of particles made by one method. Parameters are named as in the method's table
/// (see method_parameters) and each is a Distribution, so a recipe can fix or randomise any.
struct FractionSpec {
  std::string name;
  std::string method;  ///< block | hull | polyhedron | ellipsoid | mesh
  int count = 0;       ///< in kFractionCount
  std::map<std::string, Distribution> params;
  /// Method "mesh" (kMeshMethod): the mesh files, one particle each in this order (count is their
  /// number), and the factor from their length unit to the recipe's. Read by the io layer
  /// (io/pipeline/particle_shape.h), never generated. `scale` in kMeshScale.
  std::vector<std::string> files;
  double scale = 1.0;
};

/// The method of fractions whose particles are mesh files (scans, imported shapes).
inline const std::string kMeshMethod = "mesh";

/// A parameter a method accepts, with the default used when a recipe omits it.
struct ParameterInfo {
  std::string name;
  bool required = false;
  double default_value = 0.0;
  std::string help;
};

/// Methods known to the batch generator.
const std::vector<std::string>& shape_methods();

/// Parameter table of a method. Throws InvalidInput for an unknown method.
const std::vector<ParameterInfo>& method_parameters(const std::string& method);

/// Checks method, count (kFractionCount; a mesh fraction's scale: kMeshScale) and every parameter
/// (unknown names, missing required ones, invalid distributions, ranges that the generator would
/// reject for every draw). Messages start with `field_prefix` (e.g. "fraction[2]") and name the
/// field and value.
void validate(const FractionSpec& spec, const std::string& field_prefix);

/// One generated particle with the values drawn for it (in method-table order).
struct GeneratedShape {
  Mesh mesh;
  std::vector<std::pair<std::string, double>> sampled;
  int attempts = 1;  ///< draws needed (hull rejection sampling), 1 otherwise
};

/// Draws the parameters and builds the mesh (InvalidInput for a mesh fraction: its particles
/// are read, not drawn). For `block`, either L, W, H are given, or W with
/// L_over_H (Jin et al. 2017 Fig. 2: lognormal) and W_split, where W/H = (L/H)^W_split so that
/// H ≤ W ≤ L.
GeneratedShape generate_shape(const FractionSpec& spec, Rng& rng);

}  // namespace clumpkit
