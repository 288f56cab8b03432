// `clumpkit test KIND --specimen DIR --recipe T.toml --out DIR` (KIND: io/pipeline/test_kinds.h).
#include "geom/format.h"
#include "io/cli/common.h"
#include "io/pipeline/test_kinds.h"
#include "io/recipes/lab_recipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_test(CLI::App& app) {
  struct Opts {
    std::string kind, specimen;
    RecipeJobOptions run;
    bool allow_dynamic = false, save_consolidated = false;
  };
  auto o = std::make_shared<Opts>();
  std::string kinds;
  for (const TestKind& k : test_kinds())
    kinds += std::string(kinds.empty() ? "" : "; ") + k.name + ": " + k.summary;
  auto* c = app.add_subcommand(
      "test",
      "Element test or cone penetration test of a specimen (a `clumpkit specimen` directory) in a "
      "frictionless cylinder cell, gravity off: isotropic consolidation to [test] confining by "
      "servo-controlled walls, then the test of KIND (" +
          kinds +
          "). Writes DIR/curve.csv (compression positive), curve.png, report.json, manifest.json, "
          "in DIR.partial until the end (a checkpoint every --checkpoint-seconds and on Ctrl-C; "
          "continue with --resume). A crushable specimen (bonds.csv) adds breakage columns (bonds "
          "broken in mode I, II or mixed), grading.csv, the breakage plots and fragments.vtp "
          "(colour by particle or fragment). Same bytes for any --threads and after a resume.");
  c->add_option("KIND", o->kind, test_kind_names())->required();
  c->add_option("--specimen", o->specimen, "Specimen directory")->required();
  add_recipe_job_options(c, o->run, "Test recipe (see assets/recipes/test-*.toml)", JobKind::staged,
                         "Print report.json on stdout");
  c->add_flag("--allow-dynamic", o->allow_dynamic,
              "Run even when the strain rate gives an inertial number above 1e-2 (refused "
              "otherwise: not a quasi-static test)");
  c->add_flag("--save-consolidated", o->save_consolidated,
              "Also write DIR/consolidated: the consolidated specimen as a specimen directory "
              "(cell as container, bottom platen at z = 0, gravity 0) for `clumpkit export`, so "
              "another engine runs the same test from the same state (cylinder cells; for cpt "
              "the state the probe starts from: `clumpkit export lammps DIR/consolidated --test "
              "cpt --recipe RECIPE`)");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    const TestKind& kind = find_test_kind(o->kind);  // refused before anything is read
    const bool cpt = kind.path == nullptr;
    set_threads(o->run.job.threads);
    const TestRecipe recipe = read_test_recipe(o->run.recipe);
    ProgressBar bar("test", o->run.job.quiet);
    LabJobOptions jo;
    jo.resume = o->run.job.resume;
    jo.checkpoint_seconds = o->run.job.checkpoint_seconds;
    jo.allow_dynamic = o->allow_dynamic;
    jo.save_consolidated = o->save_consolidated;
    const LabJobResult job =
        kind.job(kind, o->specimen, recipe, o->run.out, jo, signal_interrupter(bar, "test"));
    bar.finish();
    if (!job.afresh_reason.empty()) note("started afresh: " + job.afresh_reason);
    const nlohmann::ordered_json& rep = job.report;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // A held inertial number is the rate the loading ran at (the start's is its floor).
    const bool held = rep.contains("inertial_number_held");
    const double inertial = rep[held ? "inertial_number_held" : "inertial_number"].get<double>();
    if (inertial > 1e-3)
      warning("inertial number " + format_number(inertial) +
              " > 1e-3: the test may not be quasi-static (check it at a lower rate); lower " +
              std::string(cpt    ? "probe.velocity"
                          : held ? "test.inertial_number"
                                 : "test.strain_rate"));
    if (cpt && rep["reached_bottom"].get<bool>())
      warning("the probe came within one diameter of the bottom platen before its depth");
    if (!rep["consolidated"].get<bool>())
      warning("consolidation did not reach equilibrium within its step limit");
    if (o->run.job.json) {
      std::cout << rep.dump(2) << "\n";
    } else {
      std::printf("wrote %s: %s test, %lld steps in %.1f s: curve.csv, curve.png, report.json\n",
                  o->run.out.c_str(), o->kind.c_str(), rep["steps"].get<long long>(), seconds);
    }
    finish_page(o->run);
  });
}

}  // namespace clumpkit::cli
