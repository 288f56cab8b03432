// What `clumpkit specimen` reports beside its bodies: report.json, the calibration table and
// plot, and horizontal slice images.
#pragma once

#include "dem/specimen/compression.h"
#include "dem/specimen/specimen.h"
#include "io/recipes/specimen_recipe.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// calibration.csv: friction, porosity, void_ratio, relative_density, steps, stopped_by.
void write_calibration_csv(const std::string& path, const dem::SpecimenResult& result);

/// calibration.png: porosity against friction with the target porosity and μ* marked.
void write_calibration_plot(const std::string& path, const dem::SpecimenResult& result,
                            double target_relative_density);

/// Horizontal slice images at the given heights: rock red, soil blue (Jin et al. 2017 Fig. 10), the
/// container grey; `pixels` across the container diameter. Returns the file names written.
std::vector<std::string> write_slices(const std::string& dir, const dem::SpecimenResult& result,
                                      double radius, const std::vector<double>& heights,
                                      int pixels = 600);

/// report.json content (see `clumpkit specimen --help`), with the container, densities and
/// contact law the exports put into the engines' decks.
nlohmann::ordered_json specimen_report(const SpecimenRecipe& recipe,
                                       const dem::SpecimenResult& result);

/// report.json of a compression specimen: method, container (shape; cuboid: size, lo, hi;
/// cylinder: diameter, height), porosity, coordination number, mean stress, the contact law
/// (with stiffness_scaling and d_ref), densities, counts, steps and time step.
nlohmann::ordered_json compression_report(const SpecimenRecipe& recipe,
                                          const dem::CompressionResult& result);

}  // namespace clumpkit
