// Sphere fill: time per fill at the default resolution (one thread), and covered fraction versus
// sphere count on the Jin et al. 2017 block, greedy coverage fill against the biggest-sphere-first
// baseline in the same run. Prints a Markdown table for tests/bench/RESULTS.md.
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/shapes/block.h"
#include "geom/shapes/primitives.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>

using namespace clumpkit;

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
Mesh block(int seed) {
  Rng rng(seed);
  return make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
}
}  // namespace

int main() {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::printf("# fill_bench (one thread, default resolution: 40 voxels across S)\n\n");

  // Time per fill, field included, for 50 spheres: mean over seeds 1-5, each run 3 times.
  for (auto strategy : {FillOptions::Strategy::Coverage, FillOptions::Strategy::Largest}) {
    double t = 0;
    int n = 0;
    for (int seed = 1; seed <= 5; ++seed) {
      const Mesh b = block(seed);
      for (int rep = 0; rep < 3; ++rep) {
        FillOptions o;
        o.spheres = 50;
        o.strategy = strategy;
        const double t0 = now();
        const FillResult r = fill(b, o);
        t += now() - t0;
        ++n;
      }
    }
    std::printf("50-sphere fill (%s): %.4f s per fill\n",
                strategy == FillOptions::Strategy::Coverage ? "coverage greedy" : "biggest first",
                t / n);
  }

  std::printf(
      "\n| spheres | greedy covered | greedy overshoot | biggest-first covered | ratio "
      "|\n|---|---|---|---|---|\n");
  for (int count : {10, 25, 47, 93, 200, 344}) {
    double cg = 0, og = 0, cl = 0;
    for (int seed = 1; seed <= 5; ++seed) {
      const Mesh b = block(seed);
      FillOptions o;
      o.spheres = count;
      const FillResult g = fill(b, o);
      const Fidelity fg = assess_fidelity(b, g.clump, g.voxel / 2);
      o.strategy = FillOptions::Strategy::Largest;
      o.tolerance_relative = 0.0;
      const FillResult l = fill(b, o);
      const Fidelity fl = assess_fidelity(b, l.clump, l.voxel / 2);
      cg += fg.covered_fraction / 5;
      og += fg.overshoot_fraction / 5;
      cl += fl.covered_fraction / 5;
    }
    std::printf("| %d | %.4f | %.4f | %.4f | %.3f |\n", count, cg, og, cl, cg / cl);
  }

  const Mesh cube = make_box(Vec3(1, 1, 1));
  FillOptions o;
  o.spheres = 50;
  const FillResult g = fill(cube, o);
  const Fidelity fg = assess_fidelity(cube, g.clump, g.voxel / 2);
  o.strategy = FillOptions::Strategy::Largest;
  o.tolerance_relative = 0.0;
  const FillResult l = fill(cube, o);
  const Fidelity fl = assess_fidelity(cube, l.clump, l.voxel / 2);
  std::printf("\nunit cube, 50 spheres: greedy covered %.4f (overshoot %.4f), biggest first %.4f\n",
              fg.covered_fraction, fg.overshoot_fraction, fl.covered_fraction);
  return 0;
}
