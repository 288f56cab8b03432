// `clumpkit compare-curves A.csv B.csv --x COL --y COL`: residual of curve B against A.
#include "io/pipeline/compare_curves.h"
#include "geom/format.h"
#include "io/cli/common.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_compare_curves(CLI::App& app) {
  struct Opts {
    CompareCurvesOptions job;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "compare-curves",
      "Residual of curve B against the reference A (CTGU 2017, eq. 4) at --points equally spaced "
      "x over the overlap of their x ranges, ends included, each curve linearly interpolated: "
      "residual_abs = mean (b - a)^2 and residual_rel = mean ((b - a)/a)^2 (over the points where "
      "a != 0). The paper's printed equation is garbled between the two, so both are given. "
      "Columns are picked by their header names, with or without their unit (depth or depth[m]; "
      "the names of files written before units, depth_m or qc_pa, read as depth and qc); the "
      "JSON's units give from and to in x's unit and residual_abs in y's squared. x must "
      "increase strictly in each file. --from "
      "and --to narrow the range compared (e.g. --from 0.018 leaves out a push's first cone "
      "diameter, where qc near zero dominates residual_rel).");
  c->add_option("A", o->job.a, "Reference curve (CSV with a header line)")->required();
  c->add_option("B", o->job.b, "Curve compared with it")->required();
  c->add_option("--x", o->job.x, "Column of x")->capture_default_str();
  c->add_option("--y", o->job.y, "Column of y")->capture_default_str();
  c->add_option("--points", o->job.points, "Equally spaced points (at least 2)")
      ->capture_default_str();
  c->add_option("--from", o->job.from,
                "Compare only where x >= this (default: the overlap's start)");
  c->add_option("--to", o->job.to, "Compare only where x <= this (default: the overlap's end)");
  c->add_option("--png", o->job.png,
                "Also draw both whole curves on one plot here (A blue, B red, labelled with "
                "their files)");
  c->add_flag("--json", o->json, "Print the result as one JSON object");
  c->callback([o] {
    const nlohmann::ordered_json r = compare_curves(o->job);
    if (o->json) {
      std::cout << r.dump(2) << "\n";
      return;
    }
    std::printf("%s against %s, %s over %s in [%s, %s], %d points:\n", o->job.b.c_str(),
                o->job.a.c_str(), o->job.y.c_str(), o->job.x.c_str(),
                format_number(r["from"].get<double>()).c_str(),
                format_number(r["to"].get<double>()).c_str(), r["points"].get<int>());
    std::printf("  residual_abs %s\n  residual_rel %s (%d points with a != 0)\n",
                format_number(r["residual_abs"].get<double>()).c_str(),
                format_number(r["residual_rel"].get<double>()).c_str(),
                r["relative_points"].get<int>());
  });
}

}  // namespace clumpkit::cli
