// `clumpkit specimen-scale DIR --factor λ --out DIR2`: a specimen copied at length scale λ.
#include "io/pipeline/specimen_scale.h"
#include "geom/format.h"
#include "io/cli/common.h"

#include <cstdio>
#include <memory>

namespace clumpkit::cli {

void register_specimen_scale(CLI::App& app) {
  struct Opts {
    std::string specimen, out;
    double factor = 0;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "specimen-scale",
      "Copy of a specimen at length scale λ (CTGU 2017 eqs. 1-3: x -> λx, r -> λr, the same "
      "fabric): masses λ³ (same density), moments λ⁵, the container and report lengths λ, and "
      "the contact stiffnesses λ·kn, λ·ks, so that `clumpkit test` on the copy gives the same "
      "stresses at the same strains (on the time axis t -> λt). Writes specimen.csv, "
      "specimen.vtp, report.json (scaled_from, scale_factor) and manifest.json.");
  c->add_option("SPECIMEN", o->specimen, "Specimen directory")->required();
  c->add_option("--factor", o->factor, "Length scale λ (> 0)")->required();
  c->add_option("--out", o->out, "Output directory")->required();
  c->callback([o] {
    run_specimen_scale(o->specimen, o->factor, o->out);
    std::printf("wrote %s: %s scaled by %s\n", o->out.c_str(), o->specimen.c_str(),
                format_number(o->factor).c_str());
  });
}

}  // namespace clumpkit::cli
