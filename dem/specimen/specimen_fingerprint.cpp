// The resume fingerprints of a specimen spec (dem/specimen/specimen.h) and of a compression
// (dem/specimen/compression.h): a canonical text of every field, hashed with the program
// version.
#include "dem/specimen/compression.h"
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

namespace {

/// Writes one "key value" line of a canonical text.
class Lines {
 public:
  void operator()(const char* key, const std::string& value) { t_ << key << " " << value << "\n"; }
  std::string text() const { return t_.str(); }

 private:
  std::ostringstream t_;
};

std::string vec(const Vec3& v) {
  return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
}

void contact_lines(Lines& line, const ContactParams& c) {
  line("contact.kn", format_number(c.kn));
  line("contact.ks", format_number(c.ks));
  line("contact.friction", format_number(c.friction));
  line("contact.damping_ratio", format_number(c.damping_ratio));
  line("contact.local_damping", format_number(c.local_damping));
  // Written only when set, so the fingerprints of specimens made before scaling existed hold.
  if (c.scaling != StiffnessScaling::none) {
    line("contact.scaling", "linear");
    line("contact.d_ref", format_number(c.d_ref));
  }
}

void particle_lines(Lines& line, const std::vector<ParticleClass>& classes,
                    const std::vector<RockTemplate>& templates) {
  for (const ParticleClass& c : classes)
    line("class", format_number(c.min_size) + " " + format_number(c.max_size) + " " +
                      format_number(c.mass_percent) + " " + (c.rock ? "rock" : "soil"));
  for (const RockTemplate& tp : templates) {
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
}

std::string fingerprint(const std::string& canonical) {
  Fnv1a h;
  h.add(std::string_view("clumpkit " CLUMPKIT_VERSION "\n"));
  h.add(std::string_view(canonical));
  return h.hex();
}

}  // namespace

std::string canonical_text(const SpecimenSpec& s) {
  Lines line;
  line("radius", format_number(s.radius));
  line("height", format_number(s.height));
  line("layers", std::to_string(s.layers));
  line("soil_density", format_number(s.soil_density));
  line("rock_density", format_number(s.rock_density));
  contact_lines(line, s.contact);
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
  particle_lines(line, s.classes, s.templates);
  return line.text();
}

std::string spec_fingerprint(const SpecimenSpec& spec) {
  return fingerprint(canonical_text(spec));
}

std::string compression_fingerprint(const CompressionSpec& s) {
  Lines line;
  line("method", "compression");
  line("shape", s.shape == CompressionSpec::Shape::cuboid     ? "cuboid"
                : s.shape == CompressionSpec::Shape::cylinder ? "cylinder"
                                                              : "segment");
  if (s.shape == CompressionSpec::Shape::segment) line("angle", format_number(s.angle));
  line("size", vec(s.size));
  line("porosity", format_number(s.porosity));
  line("friction", format_number(s.friction));
  line("soil_density", format_number(s.soil_density));
  line("rock_density", format_number(s.rock_density));
  contact_lines(line, s.contact);
  line("seed", std::to_string(s.seed));
  line("loose_factor", format_number(s.loose_factor));
  line("strain_per_step", format_number(s.strain_per_step));
  line("timestep_safety", format_number(s.timestep_safety));
  line("relax_unbalanced", format_number(s.relax_unbalanced));
  line("relax_max_steps", std::to_string(s.relax_max_steps));
  particle_lines(line, s.classes, s.templates);
  if (!s.zones.regions.empty()) {  // absent for unzoned specimens: their fingerprints stay
    line("zones.coordinate", std::to_string(static_cast<int>(s.zones.coordinate)));
    line("zones.origin", vec(s.zones.origin));
    for (const ZoneRegion& z : s.zones.regions)
      line("zones.region", std::string(z.mixed ? "mixed " : "uniform ") + format_number(z.outer) +
                               " " + format_number(z.scale) + " " +
                               format_number(z.small_fraction) + " " +
                               format_number(z.small_fraction_outer));
    line("zones.mixed_porosity", format_number(s.mixed_porosity));
    line("zones.wall_excess", format_number(s.wall_excess));
  }
  if (s.crushable) {  // absent for rigid particles: their fingerprints stay
    const CrushableMaterial& m = *s.crushable;
    const auto numbers = [](std::initializer_list<double> v) {
      std::string t;
      for (double x : v) t += (t.empty() ? "" : " ") + format_number(x);
      return t;
    };
    line("crushable.shape",
         numbers({double(m.shape.planes), m.shape.E, m.shape.F, m.shape.offset_min,
                  m.shape.offset_max, double(m.shape.sphere_level)}));
    line("crushable.cells", numbers({double(m.cells.count), m.cells.cell_size,
                                     double(m.cells.lloyd), double(m.face_subdivision)}));
    line("crushable.strength", numbers({double(static_cast<int>(m.strength.kind)), m.strength.a,
                                        m.strength.b, m.strength.min, m.strength.max}));
    line("crushable.fill",
         numbers({double(m.fill.spheres), m.fill.coverage, m.fill.min_radius,
                  double(m.fill.field.voxels), m.fill.field.voxel_size, m.fill.field.max_voxels,
                  double(m.fill.voxels_from_count), m.fill.max_overshoot, double(m.fill.refine),
                  double(m.fill.refine_iterations)}));
    line("crushable.density", format_number(m.density));
    const CohesiveParams& c = s.cohesive;
    line("crushable.bond", numbers({c.kn, c.kt, c.sigma_n, c.sigma_t, c.g_n, c.g_t, c.friction}));
  }
  return fingerprint(line.text());
}

}  // namespace clumpkit::dem
