// `clumpkit import lammps RUN_DIR --specimen DIR --out DIR2`: an engine's run back into a
// specimen directory, measured as clumpkit measures its own.
#include "io/pipeline/import.h"
#include "io/base/units.h"
#include "io/cli/common.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_import(CLI::App& app) {
  struct Opts {
    std::string engine, run_dir, specimen, out;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "import",
      "The final dump of a run of an exported deck (positions and orientations by body id) "
      "back into a specimen directory: specimen.csv, specimen.vtp, slices/ and report.json with "
      "porosity, relative density, per-layer porosity and coordination number measured as "
      "`clumpkit specimen` measures; with the deck's oedometer.csv also oedometer.png. A run of "
      "the CPT deck (its cpt.csv) is read as `clumpkit test cpt` reports a push: curve.csv, "
      "curve.png and report.json (qc_max, the second half's mean qc and fs) beside the final "
      "state's bodies.");
  c->add_option("ENGINE", o->engine, "lammps")->required();
  c->add_option("RUN_DIR", o->run_dir, "Directory where the exported deck ran")->required();
  c->add_option("--specimen", o->specimen, "The specimen directory that was exported")->required();
  c->add_option("--out", o->out, "Output specimen directory")->required();
  c->add_flag("--json", o->json, "Print the measurements and files as JSON");
  c->callback([o] {
    const ImportResult r = run_import(o->engine, o->run_dir, o->specimen, o->out);
    if (o->json) {
      nlohmann::ordered_json j{{"engine", r.engine},
                               {"bodies", r.bodies},
                               {"lost_bodies", r.lost},
                               {"porosity", r.porosity},
                               {"relative_density", r.relative_density},
                               {"source_relative_density", r.source_relative_density},
                               {"height", r.height},
                               {"fit_residual", r.fit_residual},
                               {"files", r.files}};
      add_units(j, si_length());
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf(
          "imported %zu bodies (%zu lost) from %s: porosity %.4f, relative density %.3f "
          "(clumpkit's specimen %.3f), height %.4f m -> %s\n",
          r.bodies, r.lost, o->run_dir.c_str(), r.porosity, r.relative_density,
          r.source_relative_density, r.height, o->out.c_str());
    }
  });
}

}  // namespace clumpkit::cli
