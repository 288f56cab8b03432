#include "io/recipes/specimen_build.h"

#include "dem/specimen/deposition.h"

#include <utility>

namespace clumpkit {

dem::SpecimenSpec specimen_spec(const SpecimenRecipe& r, std::vector<dem::RockTemplate> templates) {
  dem::SpecimenSpec s;
  s.radius = 0.5 * r.container_diameter;
  s.height = r.container_height;
  s.layers = r.layers;
  s.soil_density = r.soil_density;
  s.rock_density = r.rock_density;
  s.contact = dem::deposition_contact();
  s.contact.kn = r.kn;
  s.contact.ks = r.ks;
  s.contact.friction = r.friction;
  s.contact.damping_ratio = r.damping_ratio;
  s.contact.local_damping = r.local_damping;
  if (r.linear_scaling) {
    s.contact.scaling = dem::StiffnessScaling::linear;
    s.contact.d_ref = r.d_ref;
  }
  s.target_relative_density = r.target_relative_density;
  s.calibration_frictions = r.calibration_frictions;
  s.seed = r.seed;
  s.templates = std::move(templates);
  std::vector<dem::SieveClass> gradation;
  for (const SizeClass& c : r.classes) gradation.push_back({c.min, c.max, c.percent});
  s.classes =
      dem::replace_fines(gradation, r.fines_below, r.fines_min, r.fines_max, r.soil_rock_threshold);
  return s;
}

dem::CompressionSpec compression_spec(const SpecimenRecipe& r,
                                      std::vector<dem::RockTemplate> templates) {
  const dem::SpecimenSpec s = specimen_spec(r, std::move(templates));
  dem::CompressionSpec c;
  c.shape = r.cuboid    ? dem::CompressionSpec::Shape::cuboid
            : r.segment ? dem::CompressionSpec::Shape::segment
                        : dem::CompressionSpec::Shape::cylinder;
  c.angle = r.segment ? r.segment_angle_deg * M_PI / 180.0 : 0.0;
  c.size = r.cuboid ? Vec3(r.container_size[0], r.container_size[1], r.container_size[2])
                    : Vec3(r.container_diameter, r.container_diameter, r.container_height);
  c.porosity = r.compression_porosity;
  c.friction = r.compression_friction;
  c.classes = s.classes;
  c.templates = s.templates;
  c.soil_density = r.soil_density;
  c.rock_density = r.rock_density;
  c.contact = s.contact;
  c.seed = r.seed;
  c.zones = r.zones;
  c.mixed_porosity = r.mixed_porosity;
  if (r.crushable) {
    c.crushable = r.crushable_material;
    c.cohesive = r.bond;
  }
  return c;
}

}  // namespace clumpkit
