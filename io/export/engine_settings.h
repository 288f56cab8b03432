// What an engine deck needs besides the bodies: container, densities and contact law (SI).
#pragma once

#include "dem/contact.h"

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

struct EngineSettings {
  double container_radius = 0.15, container_height = 0.6;  ///< m
  double rock_density = 2870, soil_density = 2700;         ///< kg/m³
  dem::ContactParams contact;                              ///< the material friction
};

/// The settings recorded in a specimen's report.json ("container", "density", "contact").
/// Throws InvalidInput naming `path` and the missing field for a report without them.
EngineSettings engine_settings_from_report(const nlohmann::json& report, const std::string& path);

}  // namespace clumpkit
