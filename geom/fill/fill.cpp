#include "geom/fill/fill.h"

#include "geom/errors.h"
#include "geom/fill/contract.h"
#include "geom/fill/coverage_grid.h"
#include "geom/fill/fill_grow.h"
#include "geom/fill/fill_refine.h"
#include "geom/fill/skeleton.h"
#include "geom/mesh/mesh_index.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <queue>
#include <string>

namespace clumpkit {

namespace {

struct Entry {
  std::int64_t gain;  // upper bound until evaluated at the current round
  int index;
  int round;  // round at which `gain` was computed exactly (-1 = bound)
  bool operator<(const Entry& o) const {
    return gain != o.gain ? gain < o.gain : index > o.index;  // max gain, then lowest index
  }
};

// The finer lattice the sphere budget asks for, or none where the field's own voxel is fine
// enough.
std::optional<DistanceField> finer_field(const MeshIndex& distance, const DistanceField& field,
                                         const FillOptions& options) {
  std::optional<DistanceField> finer;
  FieldOptions lattice = fill_field_options(distance.mesh(), options);
  lattice.voxel_size = field.h;
  const double h = field_voxel_size(distance.mesh(), lattice);
  if (h < field.h) {
    lattice.voxel_size = h;
    lattice.count_voxel = 0.0;
    finer.emplace(make_finer_field(distance, field, lattice));
  }
  return finer;
}

// The state the placement strategies share: the candidates, the lattices that rank and cover
// them, the contract that sizes the spheres, and the result being built.
struct FillState {
  const DistanceField& field;
  const DistanceField& lattice;
  const FillOptions& options;
  const Interrupter& interrupter;
  FillContract& contract;
  CoverageGrid& coarse;
  const std::optional<CoverageGrid>& fine;
  CoverageGrid& grid;
  FillResult& r;
  const int budget;
  std::vector<MedialCandidate> cand;
  std::vector<char> exact;
  // The greedy choice ranks candidates by what they would cover on `rank`: the field's lattice
  // first (cheap), then, once no candidate adds anything there, the finer lattice, then with the
  // medial candidates of a looser ridge, so a sphere budget larger than the medial axis supports
  // still buys spheres that cover something.
  const CoverageGrid* rank = nullptr;
  std::vector<char> used;  // placed, refused, or below min_radius
  std::priority_queue<Entry> queue;
  bool loosened = false;
  // Per sphere: whether the contract recorded it on the overshoot ledger (grown past the
  // surface), so a refinement can take it off again.
  std::vector<char> recorded;

  // Takes the candidates, none of whose radii is exact yet.
  FillState(const DistanceField& field, const DistanceField& lattice, const FillOptions& options,
            const Interrupter& interrupter, FillContract& contract, CoverageGrid& coarse,
            const std::optional<CoverageGrid>& fine, CoverageGrid& grid, FillResult& r, int budget,
            std::vector<MedialCandidate> cand)
      : field(field),
        lattice(lattice),
        options(options),
        interrupter(interrupter),
        contract(contract),
        coarse(coarse),
        fine(fine),
        grid(grid),
        r(r),
        budget(budget),
        cand(std::move(cand)),
        exact(this->cand.size(), 0) {}

  // Distances while searching come from the field's features (exact distances to the nearest
  // triangles of the voxels around a point: a few dozen point–triangle distances, whatever the
  // triangle count; never below the truth). The sphere a search ends with takes its radius from
  // an exact nearest-triangle search of the index, bounded by the feature distance.
  double near_distance(const Vec3& p) const { return contract.near_distance(p); }

  // The exact radius of candidate c, computed once.
  double exact_radius(int c) {
    if (!exact[c]) {
      cand[c].radius = contract.radius_at(cand[c].center, near_distance(cand[c].center));
      exact[c] = 1;
    }
    return cand[c].radius;
  }

  // The largest inscribed sphere first: exact radii of the candidates the field ranks near the
  // top, then the largest (lowest index among equals); -1 where there is no candidate.
  int largest_inscribed() {
    double field_max = 0.0;
    for (const auto& c : cand) field_max = std::max(field_max, c.radius);
    int first = -1;
    for (int c = 0; c < static_cast<int>(cand.size()); ++c)
      if (cand[c].radius >= field_max - 4.0 * field.h) {
        exact_radius(c);
        if (first < 0 || cand[c].radius > cand[first].radius) first = c;
      }
    return first;
  }

  // Queues every unused candidate with an upper bound of what it covers on `rank`.
  void push_unused() {
    const double h = rank->voxel();
    for (int c = 0; c < static_cast<int>(cand.size()); ++c) {
      if (used[c]) continue;
      // Lattice points in a ball of radius R (voxel units) number at most the volume of the
      // ball of radius R + √3/2. The field radius gets one field voxel of slack for its error.
      const double R = (cand[c].radius + (exact[c] ? 0.0 : field.h)) / h + 0.8660254037844386;
      queue.push(Entry{static_cast<std::int64_t>(std::ceil(4.18879020478639 * R * R * R)), c, -1});
    }
  }

  // What the greedy pass does once the queue runs dry: false when nothing is left to try.
  static constexpr double kLooserRidge = 0.9;
  bool widen() {
    if (fine && rank != &grid) {
      rank = &grid;
    } else if (!loosened) {
      loosened = true;
      std::vector<char> known(lattice.d.size(), 0);
      for (const auto& c : cand) known[lattice.index(c.i, c.j, c.k)] = 1;
      for (const auto& c : medial_candidates(lattice, kLooserRidge,
                                             std::max(0.0, options.min_radius - 3.0 * field.h)))
        if (!known[lattice.index(c.i, c.j, c.k)]) {
          cand.push_back(c);
          exact.push_back(0);
          used.push_back(0);
        }
    } else {
      return false;
    }
    queue = {};
    push_unused();
    return true;
  }

  // Starts the greedy choice with `first` placed and every other candidate queued on the
  // field's lattice.
  void start(int first) {
    rank = &coarse;
    used.assign(cand.size(), 0);
    used[first] = 1;
    push_unused();
    loosened = options.ridge >= kLooserRidge;
    accept(first);
  }

  // Pattern search around a chosen centre: 26 directions, shrinking step.
  // A sphere that kept its inscribed radius (`grow` false) stays so while it moves; a grown one
  // is re-checked where it ends.
  template <class Gain>
  Sphere search(Vec3 c, double rad, bool grow, Gain&& gain) {
    std::int64_t best = gain(Sphere{c, rad});
    for (double step = 0.5 * r.voxel; step > 0.2 * r.voxel; step *= 0.5) {
      for (int iter = 0; iter < 4; ++iter) {
        bool moved = false;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              if (dx == 0 && dy == 0 && dz == 0) continue;
              const Vec3 q = c + step * Vec3(dx, dy, dz);
              const double dq = near_distance(q);
              const double rq = grow ? contract.grown(dq) : dq;
              if (rq < options.min_radius || dq <= 0.0) continue;
              const std::int64_t g = gain(Sphere{q, rq});
              if (g > best) {
                best = g;
                c = q;
                rad = rq;
                moved = true;
              }
            }
        if (!moved) break;
      }
    }
    return Sphere{c, rad};
  }

  // Adds a placed sphere to the clump and the coverage.
  void keep(const PlacedSphere& p) {
    grid.cover(p.sphere);
    if (fine) coarse.cover(p.sphere);
    r.clump.spheres.push_back(p.sphere);
    recorded.push_back(p.recorded);
    r.coverage_curve.push_back(grid.covered_fraction());
  }

  // Places candidate c where its search ends; false, leaving everything as it was, where the
  // sphere the contract allows there covers nothing new. The search reckons with the grown
  // radius, which the contract may refuse (the sphere does not fit, or the ledger is full): on a
  // 2:1:1 ellipsoid at 460 spheres, 229 spheres lay inside others before this check.
  bool accept(int c) {
    const bool grow = cand[c].radius > near_distance(cand[c].center);
    const Sphere found = options.refine
                             ? search(cand[c].center, cand[c].radius, grow,
                                      [&](const Sphere& b) { return grid.uncovered_in(b); })
                             : Sphere{cand[c].center, cand[c].radius};
    const PlacedSphere placed = contract.place(found.center, grow);
    if (grid.uncovered_in(placed.sphere) == 0) {
      if (placed.recorded) contract.release(placed.sphere);
      return false;
    }
    keep(placed);
    return true;
  }

  // The sphere budget and the coverage target end either strategy; sets stopped_by.
  bool budget_or_coverage_met() {
    const double placed = static_cast<double>(r.clump.spheres.size());
    const double reached =
        options.coverage > 0 && !r.coverage_curve.empty()
            ? std::max(placed / budget, r.coverage_curve.back() / options.coverage)
            : placed / budget;
    if (interrupted(interrupter, "fill", std::min(1.0, reached)))
      throw Interrupted("fill: interrupted after " + std::to_string(r.clump.spheres.size()) +
                        " spheres");
    if (static_cast<int>(r.clump.spheres.size()) >= budget) {
      r.stopped_by = "spheres";
      return true;
    }
    if (options.coverage > 0 && r.coverage_curve.back() >= options.coverage) {
      r.stopped_by = "coverage";
      return true;
    }
    return false;
  }

  // The Largest strategy: the remaining candidates by exact radius, largest first, each placed
  // unless its centre lies inside a sphere already placed.
  void place_largest(int first) {
    std::vector<int> order;
    for (int c = 0; c < static_cast<int>(cand.size()); ++c)
      if (c != first) order.push_back(c);
    for (int c : order) exact_radius(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return cand[a].radius > cand[b].radius; });
    r.stopped_by = "candidates";  // unless the budget, coverage or min_radius ends it first
    for (int c : order) {
      if (budget_or_coverage_met()) break;
      if (cand[c].radius < options.min_radius) {
        r.stopped_by = "min-radius";
        break;
      }
      bool inside = false;
      for (const auto& s : r.clump.spheres) inside |= (cand[c].center - s.center).norm() < s.radius;
      if (!inside)
        keep(contract.place(cand[c].center, cand[c].radius > near_distance(cand[c].center)));
    }
    r.greedy = r.clump;
    r.overshoot = contract.overshoot();
  }

  // The greedy strategy: rounds of lazy evaluation, each placing the candidate that covers the
  // most on `rank`, widening the ranking once no candidate covers anything.
  void place_greedy() {
    int round = 0;
    bool skipped_small = false;  // a candidate was dropped by min_radius
    while (true) {
      if (budget_or_coverage_met()) break;
      bool placed = false;
      while (!queue.empty()) {
        Entry e = queue.top();
        queue.pop();
        if (e.round == round) {
          if (e.gain <= 0) break;
          used[e.index] = 1;
          if (!accept(e.index)) continue;  // nothing changed: the other gains still hold
          placed = true;
          break;
        }
        if (exact_radius(e.index) < options.min_radius) {
          used[e.index] = 1;
          skipped_small = true;
          continue;
        }
        e.gain = rank->uncovered_in(Sphere{cand[e.index].center, cand[e.index].radius});
        e.round = round;
        if (e.gain > 0) queue.push(e);
      }
      if (!placed && widen()) continue;
      if (!placed) {
        // No candidate adds coverage: the medial candidates ran out, unless min_radius dropped
        // some of them.
        r.stopped_by = skipped_small ? "min-radius" : "candidates";
        break;
      }
      ++round;
    }
  }

  // After the greedy pass: refinement and growth of the placed spheres, then the ledger.
  void refine_and_grow() {
    r.candidates = static_cast<int>(cand.size());
    r.greedy = r.clump;
    if (options.refine_iterations > 0) {
      const auto budget_work = static_cast<std::int64_t>(
          options.refine_work * double(grid.work() + (fine ? coarse.work() : 0)));
      const RefineStats stats = refine_spheres(
          r.clump.spheres, recorded, grid, contract, options.min_radius, options.refine_iterations,
          options.refine_min_gain,
          options.refine_work > 0 ? std::max<std::int64_t>(1, budget_work) : 0, interrupter);
      r.refine_sweeps = stats.sweeps;
      r.refine_moves = stats.moves;
    }
    if (options.spend_budget && options.max_overshoot > 0)
      r.grow_steps = grow_spheres(r.clump.spheres, recorded, grid, contract, interrupter).steps;
    r.overshoot = contract.overshoot();
  }
};

}  // namespace

FillResult fill(const MeshIndex& distance, const DistanceField& field, const FillOptions& options,
                const Interrupter& interrupter) {
  validate(options);
  FillResult r;
  const int budget = options.spheres > 0 ? options.spheres : (options.coverage > 0 ? 1 << 30 : 50);
  // Coarse to fine: where the sphere budget asks for a finer voxel than the field's
  // (fill_field_options), the medial candidates and the coverage that places and measures the
  // spheres come from a lattice of that voxel whose distances are the field's features
  // (make_finer_field: the candidates a field that fine would give, at a fraction of its cost),
  // while the greedy choice ranks the candidates by what they cover on the field's own lattice
  // (`coarse`). Each chosen sphere's search, the refinement and the growth pass count on the
  // finer lattice (`grid`), which the result's voxel names.
  std::optional<DistanceField> finer = finer_field(distance, field, options);
  const DistanceField& lattice = finer ? *finer : field;
  // The field may be off by a few voxels deep inside: select candidates with a margin, then
  // apply min_radius to the exact radius.
  auto cand =
      medial_candidates(lattice, options.ridge, std::max(0.0, options.min_radius - 3.0 * field.h));
  r.candidates = static_cast<int>(cand.size());
  CoverageGrid coarse(field);
  std::optional<CoverageGrid> fine;
  if (finer) fine.emplace(*finer);
  CoverageGrid& grid = fine ? *fine : coarse;
  r.voxel = lattice.h;
  if (grid.interior() == 0 || coarse.interior() == 0)
    throw InvalidInput("the mesh has no interior voxel at voxel size " + std::to_string(field.h) +
                       ": use more --voxels");
  FillContract contract(distance, field, options, r.voxel, grid.interior());
  FillState s(field, lattice, options, interrupter, contract, coarse, fine, grid, r, budget,
              std::move(cand));
  const int first = s.largest_inscribed();
  if (first < 0 || s.cand[first].radius < options.min_radius) {
    r.stopped_by = "min-radius";
    return r;
  }
  s.start(first);
  if (options.strategy == FillOptions::Strategy::Largest) {
    s.place_largest(first);
    return r;
  }
  s.place_greedy();
  s.refine_and_grow();
  return r;
}

FillResult fill(const Mesh& mesh, const FillOptions& options, const Interrupter& interrupter) {
  validate(options);
  const MeshIndex index(mesh);
  return fill(index, make_distance_field(index, fill_field_options(mesh, options)), options,
              interrupter);
}

}  // namespace clumpkit
