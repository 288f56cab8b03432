// Particles per second for each shape method, generation plus all descriptors, one thread.
// Goal: >= 200 blocks per second per core. Baseline in the same run: the cost of the
// cheapest descriptor pass (volume + area) on the same meshes, so ratios survive noisy machines.
#include "geom/descriptors/descriptors.h"
#include "geom/shapes/block.h"
#include "geom/shapes/hull.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

using namespace clumpkit;

namespace {

void finish(benchmark::State& state) {
  state.SetItemsProcessed(state.iterations());
  state.counters["particles_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Block(benchmark::State& state) {
  const int nd = static_cast<int>(state.range(0));
  std::uint64_t i = 0;
  for (auto _ : state) {
    Rng rng = Rng::stream(1, i++);
    const Mesh m = make_block(BlockParams{75.1, 58.0, 49.8, nd, 0.8, 1.2}, rng);
    benchmark::DoNotOptimize(describe(m));
  }
  finish(state);
}

void BM_BlockBaselineVolumeArea(benchmark::State& state) {
  std::uint64_t i = 0;
  for (auto _ : state) {
    Rng rng = Rng::stream(1, i++);
    const Mesh m = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
    benchmark::DoNotOptimize(signed_volume(m) + surface_area(m));
  }
  finish(state);
}

void BM_Hull(benchmark::State& state) {
  const double bands[3][2] = {{1.1, 1.2}, {1.2, 1.4}, {1.4, 1.6}};
  const auto& band = bands[state.range(0)];
  std::uint64_t i = 0;
  long attempts = 0;
  for (auto _ : state) {
    Rng rng = Rng::stream(2, i++);
    HullParams p;
    p.diameter = 10;
    p.roundness_min = band[0];
    p.roundness_max = band[1];
    const HullResult r = make_hull(p, rng);
    attempts += r.attempts;
    benchmark::DoNotOptimize(describe(r.mesh));
  }
  finish(state);
  state.counters["attempts_per_grain"] = double(attempts) / double(state.iterations());
}

void BM_Polyhedron(benchmark::State& state) {
  std::uint64_t i = 0;
  for (auto _ : state) {
    Rng rng = Rng::stream(3, i++);
    PolyhedronParams p;
    p.diameter = 27.5;
    p.E = 2.0 / 3.0;
    const Mesh m = make_polyhedron(p, rng);
    benchmark::DoNotOptimize(describe(m));
  }
  finish(state);
}

void BM_Ellipsoid(benchmark::State& state) {
  for (auto _ : state) {
    const Mesh m = make_ellipsoid(Vec3(2, 1, 1), 3);
    benchmark::DoNotOptimize(describe(m));
  }
  finish(state);
}

}  // namespace

BENCHMARK(BM_BlockBaselineVolumeArea)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Block)->DenseRange(1, 4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Hull)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Polyhedron)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ellipsoid)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
