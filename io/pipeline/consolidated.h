// A test's consolidated specimen as a specimen directory (`clumpkit test ... --save-consolidated`)
// that `clumpkit export` reads, so another engine runs the same test from the same state.
#pragma once

#include "dem/core/contact.h"
#include "dem/lab/cell.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace clumpkit {

/// Throws InvalidInput naming `report_path` for a cuboid container (the engine exports model
/// cylinders and, for the CPT, segments).
void check_consolidated_container(const nlohmann::json& spec_report,
                                  const std::string& report_path);

/// Writes `dir` (specimen.csv, report.json, manifest.json): the bodies shifted so the bottom
/// platen is the floor z = 0, the cylinder or segment cell as the container (its height the
/// platens' distance, so the top platen is at the container's height; a segment's angle as the
/// specimen's report gives it), no gravity (the tests have none),
/// porosity and coordination number now, the test's contact law with the specimen's dashpot
/// (engines without PFC's local damping need one to settle) and `test_friction`; the bodies'
/// masses as the test ran them (× `density_scaling`, recorded) and its time step
/// ("test_timestep"), so another engine runs the same dynamics.
void write_consolidated(const std::filesystem::path& dir, const dem::World& world,
                        const dem::TestCell& cell, const nlohmann::json& spec_report,
                        const dem::ContactParams& law, double test_friction, double confining,
                        double density_scaling);

}  // namespace clumpkit
