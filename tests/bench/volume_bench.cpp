// Union-of-spheres volume: speed of the exact engine against the other methods in the same
// run, Jin et al. 2017 Tables 1 and 2, and the voxel method's error against voxel size. Prints
// Markdown for tests/bench/RESULTS.md. One thread.
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/shapes/block.h"
#include "geom/volume/inclusion_exclusion.h"
#include "geom/volume/pixel_slicing.h"
#include "geom/volume/slicing.h"
#include "geom/volume/union_of_balls.h"
#include "geom/volume/voxel_volume.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>

using namespace clumpkit;

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
template <class F>
double seconds_per_call(F&& f, double budget = 1.0) {
  int n = 0;
  const double t0 = now();
  do {
    f();
    ++n;
  } while (now() - t0 < budget);
  return (now() - t0) / n;
}
Mesh block(int seed) {
  Rng rng(seed);
  return make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
}
Clump fill_block(const Mesh& b, int spheres) {
  FillOptions o;
  o.spheres = spheres;
  return fill(b, o).clump;
}
double pixel_error(const Clump& c, PixelRule rule, double exact) {
  PixelSliceOptions o;
  o.rule = rule;
  return pixel_slice_volume(c, o).volume / exact - 1.0;
}
}  // namespace

int main() {
  tbb::global_control single_thread(tbb::global_control::max_allowed_parallelism, 1);
  std::printf(
      "# volume_bench (one thread)\n\n"
      "## Speed, 50-sphere clump (fill of the Jin et al. 2017 block)\n\n");
  const Mesh b1 = block(1);
  const Clump c50 = fill_block(b1, 50);
  const double exact = seconds_per_call([&] { union_properties(c50); });
  const double ie = seconds_per_call([&] { union_measure_inclusion_exclusion(c50); });
  const double slice = seconds_per_call([&] { union_properties_by_slicing(c50); });
  const double vox = seconds_per_call([&] { voxel_volume(c50, 0.5); });
  std::printf("| method | time per call | ratio to exact |\n|---|---|---|\n");
  std::printf("| exact (power diagram), volume + centroid + inertia + area | %.3f ms | 1 |\n",
              1e3 * exact);
  std::printf("| inclusion-exclusion (volume + area) | %.3f ms | %.1f |\n", 1e3 * ie, ie / exact);
  std::printf("| analytic slicing (volume + moments) | %.3f ms | %.1f |\n", 1e3 * slice,
              slice / exact);
  std::printf("| voxel level set, h = 0.5 mm | %.3f ms | %.1f |\n", 1e3 * vox, vox / exact);

  // Specimen scale: 1e5 random balls in a box, moderate overlap.
  Rng rng(5);
  Clump big;
  const double side = 46.4;  // 1e5 balls at unit spacing
  for (int i = 0; i < 100000; ++i)
    big.spheres.push_back(
        Sphere{rng.uniform(Vec3::Constant(0), Vec3::Constant(side)), rng.uniform(0.25, 0.75)});
  double t0 = now();
  const UnionProperties ub = union_properties(big);
  std::printf(
      "\n1e5 random balls (radii 0.25-0.75, unit spacing): exact %.3f s, volume %.6f, hidden %d\n",
      now() - t0, ub.mass.volume, ub.hidden);

  std::printf(
      "\n## Voxel volume error against voxel size (50-sphere clump)\n\n| voxel h [mm] | error, "
      "level set | error, voxel count | time |\n|---|---|---|---|\n");
  const double v50 = union_properties(c50).mass.volume;
  for (double h : {2.0, 1.0, 0.5, 0.25, 0.125}) {
    t0 = now();
    const VoxelVolumeResult v = voxel_volume(c50, h);
    std::printf("| %.3f | %+.4f %% | %+.4f %% | %.3f s |\n", h, 100 * (v.volume_levelset / v50 - 1),
                100 * (v.volume_count / v50 - 1), now() - t0);
  }

  std::printf(
      "\n## Jin et al. 2017 Table 1: pixel slicing, 100 slices across the 7 mm sphere, "
      "pixel = spacing\n\n"
      "| model | exact [cm3] | touch rule | centre rule | paper |\n|---|---|---|---|---|\n");
  const Clump one{{{Vec3(0, 0, 0), 7.0}}};
  const Clump two{{{Vec3(0, 0, 0), 7.0}, {Vec3(10.003022114627893, 0, 0), 10.0}}};
  const Clump three{
      {{Vec3(0, 0, 0), 7.0}, {Vec3(10.0, 0, 0), 10.0}, {Vec3(28.15398847294012, 0, 0), 10.0}}};
  const char* paper[3] = {"+2.7 %", "+1.8 %", "+1.6 %"};
  const Clump* models[3] = {&one, &two, &three};
  for (int m = 0; m < 3; ++m) {
    const double v = union_properties(*models[m]).mass.volume;
    std::printf("| %d sphere(s) | %.6f | %+.3f %% | %+.3f %% | %s |\n", m + 1, v / 1000,
                100 * pixel_error(*models[m], PixelRule::Touch, v),
                100 * pixel_error(*models[m], PixelRule::Centre, v), paper[m]);
  }

  std::printf(
      "\n## Jin et al. 2017 Table 2: block 75.1 x 58.0 x 49.8, Nd 2, Sl 0.8, Su 1.2 (seed 1; "
      "mean of seeds 1-5)\n\n"
      "| spheres | geometric volume [cm3] | exact clump volume [cm3] | deviation | mean deviation "
      "seeds 1-5 "
      "| paper deviation |\n|---|---|---|---|---|---|\n");
  const int counts[3] = {344, 93, 47};
  const char* paper2[3] = {"6.2 %", "18.3 %", "23.7 %"};
  for (int q = 0; q < 3; ++q) {
    double mean = 0, v1 = 0, g1 = 0;
    for (int seed = 1; seed <= 5; ++seed) {
      const Mesh b = block(seed);
      const double g = signed_volume(b);
      const double v = union_properties(fill_block(b, counts[q])).mass.volume;
      mean += (1 - v / g) / 5;
      if (seed == 1) v1 = v, g1 = g;
    }
    std::printf("| %d | %.2f | %.2f | %.1f %% | %.1f %% | %s |\n", counts[q], g1 / 1000, v1 / 1000,
                100 * (1 - v1 / g1), 100 * mean, paper2[q]);
  }
  return 0;
}
