#include "geom/fill/fill_grow.h"

#include "geom/errors.h"

#include <cstdint>
#include <string>

namespace clumpkit {

namespace {

// One sphere's next step: the voxels it would add and the outside volume it would put on the
// ledger.
struct Step {
  std::int64_t gain = 0;
  double cost = 0.0;
};

// Whether step a buys more per volume outside than step b (gain / cost compared by
// cross-multiplying, so a step that costs nothing beats any that costs something).
bool better(const Step& a, const Step& b) {
  if (a.gain <= 0) return false;
  if (b.gain <= 0) return true;
  return double(a.gain) * b.cost > double(b.gain) * a.cost;
}

}  // namespace

GrowStats grow_spheres(std::vector<Sphere>& spheres, std::vector<char>& recorded,
                       CoverageGrid& grid, FillContract& contract, const Interrupter& interrupter) {
  GrowStats stats;
  const double h = contract.voxel(), delta = 0.25 * h;
  const std::size_t n = spheres.size();
  std::vector<Step> next(n);
  auto evaluate = [&](std::size_t i) {
    const Sphere grown{spheres[i].center, spheres[i].radius + delta};
    next[i] = Step{grid.uncovered_in(grown), contract.added(grown)};
  };
  for (std::size_t i = 0; i < n; ++i) evaluate(i);
  // Each step costs at least a little outside volume or adds a voxel; the cap only guards
  // against a ledger that stops growing (it cannot, but a pass must end).
  const int max_steps = static_cast<int>(64 * n + 64);
  while (stats.steps < max_steps) {
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i)
      if (best == n ? next[i].gain > 0 : better(next[i], next[best])) best = i;
    if (best == n || next[best].cost > contract.spare()) break;
    if (interrupted(interrupter, "fill", 1.0))
      throw Interrupted("fill: interrupted while spending the overshoot budget, step " +
                        std::to_string(stats.steps + 1));
    const Sphere old = spheres[best];
    const Sphere grown{old.center, old.radius + delta};
    grid.uncover(old);
    grid.cover(grown);
    if (recorded[best]) contract.release(old);
    contract.record(grown);
    spheres[best] = grown;
    recorded[best] = 1;
    ++stats.steps;
    // The grown ball changed the cover and the ledger only where it reaches: the steps of the
    // spheres within reach of it are counted again.
    for (std::size_t j = 0; j < n; ++j)
      if ((spheres[j].center - grown.center).norm() < spheres[j].radius + grown.radius + 2 * delta)
        evaluate(j);
  }
  return stats;
}

}  // namespace clumpkit
