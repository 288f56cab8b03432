#include "io/pipeline/particle_shape.h"

#include "geom/mesh/refine.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/repair.h"

namespace clumpkit {

ParticleShape particle_shape(const ShapeRecipe& recipe, std::size_t i, int fraction,
                             const RepairOptions* repair) {
  ParticleShape p;
  const FractionSpec& spec = recipe.fractions[std::size_t(fraction)];
  if (spec.method == kMeshMethod) {
    std::size_t first = 0;  // the id of the fraction's first particle
    for (int f = 0; f < fraction; ++f) first += std::size_t(recipe.fractions[std::size_t(f)].count);
    p.source = spec.files[i - first];
    if (repair) {
      RepairedMesh m = read_repaired_mesh(p.source, {}, *repair);
      p.shape.mesh = std::move(m.mesh);
      p.repair = repair_json(m.repair, m.read, *repair);
      validate_solid(p.shape.mesh, p.source);
    } else {
      p.shape.mesh = read_mesh(p.source);
    }
    if (spec.scale != 1.0)
      for (Vec3& v : p.shape.mesh.vertices) v *= spec.scale;
    p.shape.sampled = {{"scale", spec.scale}};
  } else {
    Rng rng = Rng::stream(recipe.seed, i);
    p.shape = generate_shape(spec, rng);
  }
  if (recipe.refine_triangles > 0) p.shape.mesh = refine(p.shape.mesh, recipe.refine_triangles);
  return p;
}

}  // namespace clumpkit
