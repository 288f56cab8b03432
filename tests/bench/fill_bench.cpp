// Sphere fill: time per fill at the default resolution (one thread), covered fraction versus
// sphere count on the Jin et al. 2017 block (greedy coverage fill against the biggest-sphere-first
// baseline in the same run), and five test shapes at 5–460 spheres before (the greedy pass at 40
// voxels across) and after (resolution from the count and the refinement), each checked against
// an independent point count at twice the resolution. Prints Markdown tables for
// tests/bench/RESULTS.md. `fill_bench shapes` runs the last table only; `fill_bench budget` the
// coverage against the overshoot budget.
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/shapes/block.h"
#include "geom/shapes/primitives.h"
#include "io/pipeline/fill.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace clumpkit;

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
Mesh block(int seed) {
  Rng rng(seed);
  return make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
}
// Covered fraction counted on points of a lattice of spacing about δ: a point counts for the mesh
// when it lies between a row's surface crossings 1–2, 3–4, … and for the clump when it lies in
// some sphere. A 3-D point count, apart from the report's measure (lengths exact along x).
double point_coverage(const Mesh& mesh, const Clump& clump, double delta) {
  const MeshIndex index(mesh);
  const auto bb = bounding_box(mesh);
  // The midpoint rule on the box: a whole number of cells per axis (spacing about δ), a point at
  // each cell's centre, so no side of the mesh is sampled closer than another.
  Vec3 start, step;
  std::array<int, 3> n;
  for (int a = 0; a < 3; ++a) {
    const double extent = bb[1][a] - bb[0][a];
    n[a] = std::max(1, static_cast<int>(std::lround(extent / delta)));
    step[a] = extent / n[a];
    start[a] = bb[0][a] + 0.5 * step[a];
  }
  long inside = 0, covered = 0;
  for (int kz = 0; kz < n[2]; ++kz)
    for (int jy = 0; jy < n[1]; ++jy) {
      const double y = start.y() + jy * step.y(), z = start.z() + kz * step.z();
      const auto xs = index.even_crossings_x(y, z, 1e-6 * delta);
      if (xs.size() % 2) continue;
      std::vector<std::pair<double, double>> chords;
      for (const auto& s : clump.spheres) {
        const double w2 = s.radius * s.radius - (y - s.center.y()) * (y - s.center.y()) -
                          (z - s.center.z()) * (z - s.center.z());
        if (w2 > 0) chords.emplace_back(s.center.x() - std::sqrt(w2), s.center.x() + std::sqrt(w2));
      }
      for (std::size_t q = 0; q + 1 < xs.size(); q += 2)
        for (int ix = 0; ix < n[0]; ++ix) {
          const double x = start.x() + ix * step.x();
          if (x < xs[q].x || x > xs[q + 1].x) continue;
          ++inside;
          for (const auto& c : chords)
            if (x >= c.first && x <= c.second) {
              ++covered;
              break;
            }
        }
    }
  return inside > 0 ? double(covered) / double(inside) : 0.0;
}

// The five shapes of the fill's acceptance table, as the users who try fills test them.
std::vector<std::pair<std::string, Mesh>> test_shapes() {
  return {{"unit cube", make_box(Vec3(1, 1, 1))},
          {"octahedron", make_octahedron(1.0)},
          {"ellipsoid 2:1:1", make_ellipsoid(Vec3(2, 1, 1))},
          {"torus 3/1", make_torus(3.0, 1.0)},
          {"Jin block (seed 1)", block(1)}};
}

void shapes_table() {
  std::printf(
      "\n## Five shapes: before (greedy, 40 voxels across) and after (resolution from the count, "
      "refinement)\n\n| shape | spheres | covered before | overshoot before | s before | voxel "
      "after | covered after | overshoot after | s after | points at voxel/2 | |report − "
      "points| |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, mesh] : test_shapes())
    for (int count : {5, 21, 30, 50, 100, 200, 460}) {
      FillOptions before;
      before.spheres = count;
      before.field.max_voxels = kDefaultMaxVoxels;
      before.refine_iterations = 0;
      before.voxels_from_count = false;
      FillOptions after = before;
      after.refine_iterations = FillOptions{}.refine_iterations;
      after.voxels_from_count = true;
      auto quiet = [](const std::string&) {};
      double t0 = now();
      const SolidFill b = fill_solid(mesh, before, name, quiet);
      const double tb = now() - t0;
      t0 = now();
      const SolidFill a = fill_solid(mesh, after, name, quiet);
      const double ta = now() - t0;
      const double points = point_coverage(mesh, a.fill.clump, a.fill.voxel / 2);
      std::printf("| %s | %d | %.4f | %.4f | %.3f | %.4g | %.4f | %.4f | %.3f | %.4f | %.4f |\n",
                  name.c_str(), count, b.fidelity.covered_fraction, b.fidelity.overshoot_fraction,
                  tb, a.fill.voxel, a.fidelity.covered_fraction, a.fidelity.overshoot_fraction, ta,
                  points, std::abs(points - a.fidelity.covered_fraction));
      std::fflush(stdout);
    }
}

// Coverage against the overshoot budget (--max-overshoot) on the shapes where corners need it:
// the greedy pass and the refinement alone (a sphere d inside grows to d·(1 + 0.03), whatever the
// budget) beside the fill that then spends the rest of the budget (geom/fill/fill_grow.h).
// Covered fraction and overshoot by the independent count at half the fill's voxel.
void budget_table() {
  std::printf(
      "\n## Coverage against the overshoot budget\n\n| shape | spheres | budget | covered "
      "(refined) | overshoot | covered (budget spent) | overshoot | steps | s |\n"
      "|---|---|---|---|---|---|---|---|---|\n");
  // The five shapes of test_shapes() at their acceptance counts (the cube also at 100).
  const std::vector<std::vector<int>> counts = {{50, 100}, {21}, {50}, {30}, {47}};
  const auto shapes = test_shapes();
  for (std::size_t q = 0; q < shapes.size(); ++q)
    for (int count : counts[q]) {
      const auto& [name, mesh] = shapes[q];
      for (double budget : {0.0, 0.005, 0.01, 0.02, 0.022, 0.05}) {
        Fidelity f[2];
        int steps = 0;
        double seconds = 0;
        for (int spend = 0; spend < 2; ++spend) {
          FillOptions o;
          o.spheres = count;
          o.field.max_voxels = kDefaultMaxVoxels;
          o.max_overshoot = budget;
          o.spend_budget = spend;
          const double t0 = now();
          const FillResult r = fill(mesh, o);
          seconds = now() - t0;
          steps = r.grow_steps;
          f[spend] = assess_fidelity(mesh, r.clump, r.voxel / 2);
        }
        std::printf("| %s | %d | %.3f | %.4f | %.4f | %.4f | %.4f | %d | %.2f |\n", name.c_str(),
                    count, budget, f[0].covered_fraction, f[0].overshoot_fraction,
                    f[1].covered_fraction, f[1].overshoot_fraction, steps, seconds);
        std::fflush(stdout);
      }
    }
}

}  // namespace

int main(int argc, char** argv) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  if (argc > 1 && std::strcmp(argv[1], "shapes") == 0) {
    shapes_table();
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "budget") == 0) {
    budget_table();
    return 0;
  }
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
  shapes_table();
  return 0;
}
