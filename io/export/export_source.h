// What `clumpkit export` reads: a specimen directory, a clump library's templates, or one clump or
// template CSV, as bodies with exact mass properties and the settings of the engine's deck.
#pragma once

#include "io/export/engine_settings.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace clumpkit {

/// How a library or clump CSV becomes bodies, as given on the command line (a specimen carries
/// its own masses and units, so it takes none of these).
struct TemplateSourceOptions {
  double density = NAN;     ///< kg/m³; required for a library or clump CSV
  std::string length_unit;  ///< "m" (default) or "mm": what the file's numbers are
  /// "clump" (default: density × V_clump) or "mesh": Jin et al. 2017 §2.2's mass equivalence,
  /// the body weighs density × V_mesh and its moments scale by the same V_mesh/V_clump.
  std::string mass;
};

struct ExportSource {
  std::string kind;  ///< "specimen", "library" or "clump"
  std::vector<SpecimenBody> bodies;
  EngineSettings settings;
  nlohmann::json manifest;  ///< the source's manifest.json (empty for a clump CSV)
  nlohmann::json report;    ///< a specimen's report.json (empty for the others)
  /// Template sources: each body is one template, at rest on a grid on the floor of a
  /// container made to hold them (layout_templates), ids from 1 in template order.
  bool templates = false;
};

/// Reads `source`: a specimen directory (specimen.csv, report.json, manifest.json of `clumpkit
/// specimen`), a library directory (library.csv and particles/NNNNN.template.csv of `clumpkit
/// library`; every particle, template id = library id) or one clump CSV (x,y,z,r, any frame; a
/// library's NNNNN.template.csv is one in its principal frame). A library's mass properties are
/// those it recorded (exact union volume and moments); a clump CSV's are computed the same way
/// (make_clump_template). Mass = density × V_clump (× V_mesh/V_clump with mass "mesh": the
/// library's density_factor, or for a clump CSV the mesh STEM.stl beside it, STEM being the file
/// name up to its first '.'), inertia = density × I (× the same factor); lengths are scaled by the
/// unit u (V ∝ u³, I ∝ u⁵). Throws InvalidInput naming the source, file or option for a source that
/// is none of these, a missing --density, options a specimen does not take, or a bad file (IoError
/// for one that cannot be read).
ExportSource read_export_source(const std::string& source, const TemplateSourceOptions& options);

/// One template's bodies-to-be: spheres in its principal frame (centroid at the origin) with
/// its mass and principal moments (SI).
struct TemplateBody {
  int template_id = 0;
  std::vector<Sphere> spheres;
  double mass = 0, volume = 0;
  Vec3 moments = Vec3::Zero();
};

/// Bodies of templates laid out for a deck: one per template, unrotated (principal axes along
/// x, y, z), on a square grid whose spacing is 1.2 × the largest template's diameter, a tenth of
/// the largest reach above the floor; the container is the cylinder around the grid with a
/// half a spacing to spare, two spacings tall; deposition_contact(), density = `density`.
std::vector<SpecimenBody> layout_templates(const std::vector<TemplateBody>& templates,
                                           double density, EngineSettings& settings);

}  // namespace clumpkit
