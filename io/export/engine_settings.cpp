#include "io/export/engine_settings.h"

#include "geom/errors.h"

namespace clumpkit {

EngineSettings engine_settings_from_report(const nlohmann::json& report, const std::string& path) {
  auto field = [&](const char* section, const char* key) {
    if (!report.contains(section) || !report[section].contains(key) ||
        !report[section][key].is_number())
      throw InvalidInput(path + ": field " + section + "." + key +
                         " missing (a report of an older clumpkit; build the specimen again)");
    return report[section][key].get<double>();
  };
  EngineSettings s;
  s.container_radius = 0.5 * field("container", "diameter");
  s.container_height = field("container", "height");
  s.rock_density = field("density", "rock");
  s.soil_density = field("density", "soil");
  s.contact.kn = field("contact", "kn");
  s.contact.ks = field("contact", "ks");
  s.contact.friction = field("contact", "friction");
  s.contact.damping_ratio = field("contact", "damping_ratio");
  s.contact.local_damping = field("contact", "local_damping");
  return s;
}

}  // namespace clumpkit
