// What an element test on a crushable specimen writes besides its curve: the breakage columns,
// the input work, the grading before and after, and their plots.
#pragma once

#include "dem/lab/element_loading.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace clumpkit {

/// For a world with bonds (a crushable specimen), sets the settings' reference bodies (the
/// specimen as read), its grading (fragment_pieces) and Marsal's sieves (√2 steps from √2
/// times the largest piece down to a 64th of it); leaves them empty otherwise.
void track_breakage(const dem::World& world, dem::ElementTestSettings& settings);

/// The input work per unit volume W = ∫ σa dεa + 2 ∫ σr dεr (Pa = J/m³) at each row, from the
/// consolidated state (trapezoids; εr = (εv − εa)/2).
std::vector<double> input_work(const std::vector<dem::CurveRow>& curve);

/// curve.csv's breakage columns (names without units, with a leading comma; and one row's
/// values).
std::string breakage_header();
std::string breakage_values(const dem::CurveRow& row, double work);

/// grading.csv (sieve, passing_initial, passing_final; units in the header cells), grading.png
/// (both curves against log10 of the sieve in mm), breakage.png and breakage_work.png (Br against
/// the axial stress and against the work `work` of each row, input_work), fragments.vtp (the
/// spheres at the end with point data particle and fragment, each numbered from 1, besides body)
/// and the report's "breakage" entry; their names are added to `files`.
void write_breakage_outputs(const std::filesystem::path& out, const dem::World& world,
                            const dem::ElementTestSettings& settings,
                            const std::vector<dem::CurveRow>& curve,
                            const std::vector<double>& work, nlohmann::ordered_json& report,
                            std::vector<std::string>& files);

}  // namespace clumpkit
