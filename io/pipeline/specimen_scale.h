// The job of `clumpkit specimen-scale`: a specimen copied at length scale λ (CTGU 2017 eqs. 1–3).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

/// Copies the specimen in `specimen_dir` into `out_dir` at scale `factor` λ about the origin
/// (x → λx + shift, r → λr; CTGU 2017 eqs. 1–3: every branch vector scales by λ, the fabric is
/// the same): bodies' positions, spheres, volumes (λ³), masses (λ³, same density), moments (λ⁵)
/// and template scales (λ); report.json's lengths (container, height, layer height, measurement
/// region) with it, and its contact law scaled as the similarity needs (kn, ks → λ·kn, λ·ks:
/// stress-strain behaviour unchanged on the time axis t → λt), with
/// "scaled_from" and "scale_factor" added; porosities and fractions are unchanged. Writes
/// specimen.csv, specimen.vtp, report.json and manifest.json (DIR.partial renamed at the end).
/// Throws InvalidInput for a factor that is not positive and finite or that takes a length
/// beyond 1e30, and for an output that would replace the source.
nlohmann::ordered_json run_specimen_scale(const std::string& specimen_dir, double factor,
                                          const std::string& out_dir);

}  // namespace clumpkit
