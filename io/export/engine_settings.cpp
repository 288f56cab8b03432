#include "io/export/engine_settings.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace clumpkit {

EngineSettings engine_settings_from_report(const nlohmann::json& report, const std::string& path) {
  auto field = [&](const char* section, const char* key) {
    if (!report.contains(section) || !report[section].contains(key) ||
        !report[section][key].is_number())
      throw InvalidInput(path + ": field " + section + "." + key +
                         " missing (a report of an older clumpkit; build the specimen again)");
    return report[section][key].get<double>();
  };
  // What the decks cannot carry yet is refused rather than dropped silently.
  if (report.contains("container") && report["container"].value("shape", "") == "cuboid")
    throw InvalidInput(path +
                       ": container.shape: \"cuboid\" specimens are not exported yet (the decks "
                       "model a cylinder container): export a cylinder specimen");
  EngineSettings s;
  s.container_radius = 0.5 * field("container", "diameter");
  s.container_height = field("container", "height");
  if (report["container"].value("shape", "") == "segment") {
    s.segment_angle_deg = field("container", "angle_deg");
    if (!(s.segment_angle_deg > 0 && s.segment_angle_deg <= 180))
      throw InvalidInput(path + ": container.angle_deg must be in (0, 180], got " +
                         format_number(s.segment_angle_deg));
  }
  s.rock_density = field("density", "rock");
  s.soil_density = field("density", "soil");
  s.contact.kn = field("contact", "kn");
  s.contact.ks = field("contact", "ks");
  s.contact.friction = field("contact", "friction");
  s.contact.damping_ratio = field("contact", "damping_ratio");
  s.contact.local_damping = field("contact", "local_damping");
  // Linear scaling (kn ∝ d): only the LAMMPS CPT deck carries it (io/pipeline/export.cpp).
  if (report["contact"].value("stiffness_scaling", "") == "linear") {
    s.contact.scaling = dem::StiffnessScaling::linear;
    s.contact.d_ref = field("contact", "d_ref");
    if (!(s.contact.d_ref > 0) || !std::isfinite(s.contact.d_ref))
      throw InvalidInput(path + ": contact.d_ref must be positive, got " +
                         format_number(s.contact.d_ref));
  }
  if (report.contains("gravity") && report["gravity"].is_boolean()) {
    // A compression specimen's report says whether gravity was on: false, prepared without it.
    if (!report["gravity"].get<bool>()) s.gravity = 0.0;
  } else if (report.contains("gravity")) {
    const auto& g = report["gravity"];
    if (!g.is_number() || !(g.get<double>() >= 0.0) || !std::isfinite(g.get<double>()))
      throw InvalidInput(path + ": field gravity: " + g.dump() +
                         " is not a non-negative number (m/s²)");
    s.gravity = g.get<double>();
  }
  if (report.contains("test_timestep")) {
    const auto& t = report["test_timestep"];
    if (!t.is_number() || !(t.get<double>() > 0.0) || !std::isfinite(t.get<double>()))
      throw InvalidInput(path + ": field test_timestep: " + t.dump() +
                         " is not a positive number (s)");
    s.test_timestep = t.get<double>();
  }
  return s;
}

SpecimenExtents specimen_extents(const std::vector<SpecimenBody>& bodies) {
  SpecimenExtents e;
  std::vector<double> masses;
  for (const SpecimenBody& b : bodies) {
    masses.push_back(b.mass);
    e.m_min = std::min(e.m_min, b.mass);
    for (const Sphere& s : b.spheres) {
      e.r_min = std::min(e.r_min, s.radius);
      e.r_max = std::max(e.r_max, s.radius);
      e.reach = std::max(e.reach, (s.center - b.position).norm() + s.radius);
      e.bottom = std::min(e.bottom, s.center.z() - s.radius);
      e.top = std::max(e.top, s.center.z() + s.radius);
    }
  }
  if (!masses.empty()) {
    std::nth_element(masses.begin(), masses.begin() + masses.size() / 2, masses.end());
    e.m_median = masses[masses.size() / 2];
  }
  return e;
}

std::vector<SpecimenBody> tile_bodies(const std::vector<SpecimenBody>& bodies, int nx, int ny,
                                      double spacing) {
  std::vector<SpecimenBody> out;
  out.reserve(bodies.size() * static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec3 shift((i - 0.5 * (nx - 1)) * spacing, (j - 0.5 * (ny - 1)) * spacing, 0);
      for (const SpecimenBody& b : bodies) {
        SpecimenBody c = b;
        c.id = static_cast<long>(out.size() + 1);
        c.position += shift;
        for (Sphere& s : c.spheres) s.center += shift;
        out.push_back(std::move(c));
      }
    }
  return out;
}

std::string format_xyz(const Vec3& v) {
  return format_number(v.x()) + " " + format_number(v.y()) + " " + format_number(v.z());
}

std::string write_export_file(const std::string& dir, const std::string& name,
                              const std::function<void(std::ostream&)>& fill) {
  const std::string path = (std::filesystem::path(dir) / name).string();
  write_file_atomically(path, fill);
  return path;
}

}  // namespace clumpkit
