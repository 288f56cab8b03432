#include "io/pipeline/consolidated.h"

#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/formats/specimen_csv.h"

namespace clumpkit {

namespace fs = std::filesystem;

void check_consolidated_container(const nlohmann::json& spec_report,
                                  const std::string& report_path) {
  if (spec_report.contains("container") &&
      spec_report["container"].value("shape", std::string("cylinder")) == "cuboid")
    throw InvalidInput(report_path +
                       ": container.shape: \"cuboid\": --save-consolidated writes cylinder and "
                       "segment cells only (the engine exports model cylinders)");
}

void write_consolidated(const fs::path& dir, const dem::World& world, const dem::TestCell& cell,
                        const nlohmann::json& spec_report, const dem::ContactParams& law,
                        double test_friction, double confining, double density_scaling) {
  const double floor = world.walls()[cell.bottom].point.z();
  std::vector<SpecimenBody> bodies = specimen_bodies(world);
  std::size_t spheres = 0;
  for (SpecimenBody& b : bodies) {
    b.position.z() -= floor;
    for (Sphere& sp : b.spheres) sp.center.z() -= floor;
    spheres += b.spheres.size();
  }
  fs::create_directories(dir);
  write_specimen_csv((dir / "specimen.csv").string(), bodies);
  nlohmann::ordered_json rep;
  rep["source"] = "consolidated state of clumpkit test";
  rep["bodies"] = bodies.size();
  rep["spheres"] = spheres;
  rep["confining_stress"] = confining;
  double solid = 0;
  for (const dem::Body& b : world.bodies()) solid += b.volume;
  rep["porosity"] = 1.0 - solid / cell_volume(world, cell);
  rep["coordination_number"] = dem::coordination_number(world);
  rep["gravity"] = 0.0;
  // The masses are the test's (× its density_scaling), and so is its step: another engine
  // pushing from here runs the same dynamics.
  rep["density_scaling"] = density_scaling;
  rep["test_timestep"] = world.options().timestep;
  rep["container"] = {{"diameter", 2.0 * world.walls()[cell.lateral.front()].radius},
                      {"height", cell_height(world, cell)}};
  // A segment keeps the specimen's angle as its recipe gave it (degrees, no round trip).
  if (cell.shape == dem::TestCell::Shape::segment)
    rep["container"] = {{"shape", "segment"},
                        {"diameter", 2.0 * world.walls()[cell.lateral.front()].radius},
                        {"height", cell_height(world, cell)},
                        {"angle_deg", spec_report.at("container").at("angle_deg")}};
  rep["density"] = spec_report.at("density");
  if (spec_report.contains("zones")) rep["zones"] = spec_report["zones"];  // the probe's core
  rep["contact"] = {
      {"kn", law.kn},
      {"ks", law.ks},
      {"friction", test_friction},
      {"damping_ratio", spec_report.at("contact").value("damping_ratio", 0.0)},
      {"local_damping", law.local_damping},
      {"stiffness_scaling", law.scaling == dem::StiffnessScaling::linear ? "linear" : "none"},
      {"d_ref", law.d_ref}};
  add_units(rep, si_length());
  write_file_atomically((dir / "report.json").string(),
                        [&](std::ostream& f) { f << rep.dump(2) << "\n"; });
  nlohmann::ordered_json m;
  m["command"] = "test";
  m["files"] = {"specimen.csv", "report.json"};
  add_units(m, si_length());
  write_file_atomically((dir / "manifest.json").string(),
                        [&](std::ostream& f) { f << m.dump(2) << "\n"; });
}

}  // namespace clumpkit
