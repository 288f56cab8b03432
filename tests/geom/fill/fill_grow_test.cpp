// Tests of the pass that spends the rest of the overshoot budget: steps that a larger budget
// repeats and extends, the contract kept, coverage bought where the corners are.
#include "geom/fill/fill_grow.h"
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/mesh/mesh_index.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

using namespace clumpkit;

namespace {

struct Grown {
  std::vector<Sphere> spheres;
  double covered = 0.0, ledger = 0.0;
  int steps = 0;
};

// The inscribed spheres (all inside, none on the ledger) grown under `budget`.
Grown grow_under(const Mesh& mesh, const std::vector<Sphere>& inscribed, FillOptions o,
                 double budget) {
  o.max_overshoot = budget;
  const MeshIndex index(mesh);
  const DistanceField field = make_distance_field(index, fill_field_options(mesh, o));
  CoverageGrid grid(field);
  FillContract contract(index, field, o, field.h, grid.interior());
  Grown g;
  g.spheres = inscribed;
  for (const Sphere& s : g.spheres) grid.cover(s);
  std::vector<char> recorded(g.spheres.size(), 0);
  g.steps = grow_spheres(g.spheres, recorded, grid, contract).steps;
  g.covered = grid.covered_fraction();
  g.ledger = contract.overshoot();
  return g;
}

}  // namespace

// The same inscribed octahedron fill grown under budgets 0.005 to 0.05: each larger budget grows
// every sphere at least as far as the smaller one did (it takes the same steps first), so the
// coverage never falls; the ledger stays within 0.9 of each budget and the independent count
// within the budget itself.
TEST(FillGrow, ALargerBudgetTakesTheSameStepsAndThenMore) {
  const Mesh mesh = make_octahedron(1.0);
  FillOptions o;
  o.spheres = 21;
  o.max_overshoot = 0.0;
  o.spend_budget = false;
  const FillResult inscribed = fill(mesh, o);
  ASSERT_EQ(inscribed.clump.spheres.size(), 21u);
  Grown last;
  last.spheres = inscribed.clump.spheres;
  for (double budget : {0.005, 0.01, 0.02, 0.05}) {
    const Grown g = grow_under(mesh, inscribed.clump.spheres, o, budget);
    EXPECT_GT(g.steps, last.steps) << budget;
    EXPECT_GT(g.covered, last.covered) << budget;
    for (std::size_t i = 0; i < g.spheres.size(); ++i) {
      EXPECT_EQ(g.spheres[i].center, inscribed.clump.spheres[i].center);
      EXPECT_GE(g.spheres[i].radius, last.spheres[i].radius) << budget << " sphere " << i;
    }
    EXPECT_LE(g.ledger, 0.9 * budget);
    EXPECT_GT(g.ledger, 0.7 * budget);  // spent, not left over
    const Fidelity f = assess_fidelity(mesh, Clump{g.spheres}, 0.01);
    EXPECT_LE(f.overshoot_fraction, budget);
    last = g;
  }
}

// The octahedron at 21 spheres, where the corners need the budget: the whole fill covers more
// for every larger --max-overshoot (the greedy pass differs between budgets, the growth makes up
// for it), and at a budget of 0.022 it covers at least 0.905 (a peer's 0.904 puts 2.2 % outside),
// at the default 0.01 at least 0.895, by the independent count at half the fill's voxel.
TEST(FillGrow, TheOctahedronsCornersCoverMoreForEveryLargerBudget) {
  const Mesh mesh = make_octahedron(1.0);
  double last = 0.0;
  for (double budget : {0.0, 0.005, 0.01, 0.02, 0.022, 0.05}) {
    FillOptions o;
    o.spheres = 21;
    o.max_overshoot = budget;
    const FillResult r = fill(mesh, o);
    const Fidelity f = assess_fidelity(mesh, r.clump, r.voxel / 2);
    EXPECT_GT(f.covered_fraction, last) << budget;
    EXPECT_LE(f.overshoot_fraction, budget + 1e-9) << budget;
    if (budget == 0.01) {
      EXPECT_GE(f.covered_fraction, 0.895);
    }
    if (budget == 0.022) {
      EXPECT_GE(f.covered_fraction, 0.905);
    }
    last = f.covered_fraction;
  }
}
