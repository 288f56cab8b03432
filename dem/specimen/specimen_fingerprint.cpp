// The resume fingerprint of a specimen spec (dem/specimen/specimen.h): a canonical text of every
// field, hashed with the program version.
#include "dem/specimen/specimen.h"

#include "geom/format.h"
#include "geom/hash.h"

#include <sstream>
#include <string>

namespace clumpkit::dem {

// The canonical text must name every field: these asserts fail to compile when a field is added
// to one of the structs, so it cannot be forgotten here (a forgotten contact parameter would let
// --resume mix two specs).
static_assert(sizeof(ContactParams) == 7 * sizeof(double), "add the new field to canonical_text");
static_assert(sizeof(ParticleClass) == 3 * sizeof(double) + sizeof(double),
              "add the new field to canonical_text");

std::string canonical_text(const SpecimenSpec& s) {
  std::ostringstream t;
  auto line = [&](const char* key, const std::string& value) { t << key << " " << value << "\n"; };
  auto vec = [&](const Vec3& v) {
    return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
  };
  line("radius", format_number(s.radius));
  line("height", format_number(s.height));
  line("layers", std::to_string(s.layers));
  line("soil_density", format_number(s.soil_density));
  line("rock_density", format_number(s.rock_density));
  line("contact.kn", format_number(s.contact.kn));
  line("contact.ks", format_number(s.contact.ks));
  line("contact.friction", format_number(s.contact.friction));
  line("contact.damping_ratio", format_number(s.contact.damping_ratio));
  line("contact.local_damping", format_number(s.contact.local_damping));
  // Written only when set, so the fingerprints of specimens made before scaling existed hold.
  if (s.contact.scaling != StiffnessScaling::none) {
    line("contact.scaling", "linear");
    line("contact.d_ref", format_number(s.contact.d_ref));
  }
  line("target_relative_density", format_number(s.target_relative_density));
  for (double f : s.calibration_frictions) line("calibration_friction", format_number(f));
  line("seed", std::to_string(s.seed));
  line("porosity_guess", format_number(s.porosity_guess));
  line("timestep_safety", format_number(s.timestep_safety));
  line("equilibrium_ratio", format_number(s.equilibrium_ratio));
  line("settle_window", std::to_string(s.settle_window));
  line("height_tolerance", format_number(s.height_tolerance));
  line("max_steps", std::to_string(s.max_steps));
  line("correction_rounds", std::to_string(s.correction_rounds));
  line("relative_density_tolerance", format_number(s.relative_density_tolerance));
  line("density_scaling", format_number(s.density_scaling));
  line("margin", format_number(s.margin));
  for (const ParticleClass& c : s.classes)
    line("class", format_number(c.min_size) + " " + format_number(c.max_size) + " " +
                      format_number(c.mass_percent) + " " + (c.rock ? "rock" : "soil"));
  for (const RockTemplate& tp : s.templates) {
    const ClumpTemplate& c = tp.clump;
    line("template", format_number(tp.sieve_size) + " " + std::to_string(c.spheres.size()));
    line("template.volume", format_number(c.mass.volume));
    line("template.centroid", vec(c.mass.centroid));
    line("template.inertia", vec(c.mass.inertia.row(0).transpose()) + " " +
                                 vec(c.mass.inertia.row(1).transpose()) + " " +
                                 vec(c.mass.inertia.row(2).transpose()));
    line("template.moments", vec(c.principal_moments));
    line("template.pose",
         format_number(c.orientation.w()) + " " + vec(c.orientation.vec()) + " " + vec(c.position));
    line("template.density_factor", format_number(c.density_factor));
    for (const Sphere& sp : c.spheres)
      line("sphere", vec(sp.center) + " " + format_number(sp.radius));
  }
  return t.str();
}

std::string spec_fingerprint(const SpecimenSpec& spec) {
  Fnv1a h;
  h.add(std::string_view("clumpkit " CLUMPKIT_VERSION "\n"));
  h.add(std::string_view(canonical_text(spec)));
  return h.hex();
}

}  // namespace clumpkit::dem
