// What a CPT reports from its curve, in clumpkit or in another engine: qc at its largest and the
// means over the push's second half, and the qc–depth plot.
#pragma once

#include "dem/lab/cpt.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// Adds qc_max and qc_mean_second_half, fs_mean_second_half (the rows at or below half the last
/// row's depth: the steady part once the cone is buried) to `report`.
void add_cpt_summary(nlohmann::ordered_json& report, const std::vector<dem::CptRow>& curve);

/// curve.png: qc (MPa) against depth (m) with `title`.
void write_cpt_plot(const std::string& path, const std::vector<dem::CptRow>& curve,
                    const std::string& title);

}  // namespace clumpkit
