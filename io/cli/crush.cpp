// `clumpkit crush --recipe R.toml --out DIR`: sets of crushable particles crushed between
// platens, with Weibull strength statistics and the size law (Hu et al. 2023).
#include "io/pipeline/crush.h"
#include "io/base/units.h"
#include "io/cli/common.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_crush(CLI::App& app) {
  struct Opts {
    RecipeJobOptions run;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "crush",
      "Single-particle crushing tests from a recipe (TOML, SI; see assets/recipes/crush-*.toml): "
      "per sample a parent particle cut into Voronoi cells bonded by the mixed-mode cohesive law "
      "of Hu et al. 2023, crushed between rigid platens at a constant strain rate; the peak at a "
      "35 % load drop with the particle split or collapsed, strength Fp/D². Writes "
      "DIR/particles/NNNNN.json and .csv (force-travel curve) and .cells.json (the cells before "
      "and "
      "after, for clumpkit page), results.csv, report.json (Weibull "
      "sigma0 and modulus per set with bootstrap 90 % intervals, size law sigma0 = k D^-alpha in "
      "SI), weibull.png, size.png, curves_SET.png and manifest.json, in DIR.partial renamed at "
      "the end. A killed or interrupted run restarted with the same command resumes; same seed, "
      "same bytes, for any --threads.");
  add_recipe_job_options(c, o->run, "Crushing recipe (see assets/recipes/crush-*.toml)",
                         JobKind::parallel, "Print report.json on stdout");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    set_threads(o->run.job.threads);
    const CrushRecipe recipe = read_crush_recipe(o->run.recipe);
    ProgressBar bar("crush", o->run.job.quiet);
    const CrushJobResult r = run_crush(recipe, o->run.out, signal_interrupter(bar, "crush"));
    bar.finish();
    warn_redone(o->run.out, r.redone);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o->run.job.json) {
      nlohmann::ordered_json j = r.report;
      j["resumed"] = r.resumed;
      j["seconds"] = seconds;
      add_units(j, si_length());
      std::cout << j.dump(2) << "\n";
      finish_page(o->run);
      return;
    }
    std::printf("wrote %zu crushed particles to %s (%zu kept from an earlier run) in %.1f s\n",
                r.particles, o->run.out.c_str(), r.resumed, seconds);
    for (const auto& s : r.report["sets"]) {
      if (s["sigma0"].is_null()) {
        std::printf("  %s: %d of %d failed, no fit\n", s["name"].get<std::string>().c_str(),
                    s["failed"].get<int>(), s["samples"].get<int>());
        continue;
      }
      std::printf(
          "  %s: D %.2f mm, %d of %d failed, sigma0 %.3g MPa [%.3g, %.3g], m %.3g "
          "[%.3g, %.3g]\n",
          s["name"].get<std::string>().c_str(), s["diameter"].get<double>() * 1e3,
          s["failed"].get<int>(), s["samples"].get<int>(), s["sigma0"].get<double>() * 1e-6,
          s["sigma0_ci90"][0].get<double>() * 1e-6, s["sigma0_ci90"][1].get<double>() * 1e-6,
          s["weibull_modulus"].get<double>(), s["weibull_modulus_ci90"][0].get<double>(),
          s["weibull_modulus_ci90"][1].get<double>());
    }
    if (!r.report["size_exponent"].is_null())
      std::printf(
          "  size law sigma0 = k D^-alpha: alpha %.3g, 90 %% [%.3g, %.3g], k %.4g (SI), Spearman "
          "%.3f\n",
          r.report["size_exponent"].get<double>(), r.report["size_exponent_ci90"][0].get<double>(),
          r.report["size_exponent_ci90"][1].get<double>(),
          r.report["size_coefficient"].get<double>(), r.report["spearman"].get<double>());
    finish_page(o->run);
  });
}

}  // namespace clumpkit::cli
