// What every engine export shares: the container, densities and contact law of a deck (SI), the
// specimen's sizes, and bodies in their own frame.
#pragma once

#include "dem/core/contact.h"
#include "io/formats/specimen_csv.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace clumpkit {

struct EngineSettings {
  double container_radius = 0.15, container_height = 0.6;  ///< m
  /// A segment container's angle (degrees, in (0, 180]; its radial planes at φ = 0 and φ =
  /// angle); 0 for a whole cylinder. Only the CPT deck takes segments (io/pipeline/export.cpp).
  double segment_angle_deg = 0.0;
  double rock_density = 2870, soil_density = 2700;  ///< kg/m³
  dem::ContactParams contact;                       ///< the material friction
  /// m/s², downwards: report.json "gravity" when it has one (0 for the consolidated state of an
  /// element test, `clumpkit test --save-consolidated`; `false`, a compression specimen's, is
  /// 0 too), else Earth's.
  double gravity = 9.81;
  /// s: report.json "test_timestep" of a test's consolidated state (the step its test ran with,
  /// which the CPT deck takes, so both engines push with the same step); 0 otherwise.
  double test_timestep = 0.0;
};

/// The settings recorded in a specimen's report.json ("container", "density", "contact").
/// Throws InvalidInput naming `path` and the missing field for a report without them.
EngineSettings engine_settings_from_report(const nlohmann::json& report, const std::string& path);

/// Sizes a deck needs: smallest and largest sphere radius, largest body extent from its centroid,
/// lowest and highest sphere surface, smallest and median body mass.
struct SpecimenExtents {
  double r_min = INFINITY, r_max = 0, reach = 0, bottom = INFINITY, top = -INFINITY;
  double m_min = INFINITY, m_median = 0;
};
SpecimenExtents specimen_extents(const std::vector<SpecimenBody>& bodies);

/// nx × ny copies of the bodies side by side (a scale-out specimen): copy (i, j) shifted by
/// ((i − (nx − 1)/2)·spacing, (j − (ny − 1)/2)·spacing, 0); ids renumbered from 1, copy by copy.
std::vector<SpecimenBody> tile_bodies(const std::vector<SpecimenBody>& bodies, int nx, int ny,
                                      double spacing);

/// "x y z", each the shortest decimal that reads back exactly (geom/format.h).
std::string format_xyz(const Vec3& v);

/// Writes `dir`/`name` atomically with `fill` and returns its path (every engine file).
std::string write_export_file(const std::string& dir, const std::string& name,
                              const std::function<void(std::ostream&)>& fill);

}  // namespace clumpkit
