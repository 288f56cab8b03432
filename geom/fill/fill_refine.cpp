#include "geom/fill/fill_refine.h"

#include "geom/errors.h"

#include <limits>
#include <string>

namespace clumpkit {

RefineStats refine_spheres(std::vector<Sphere>& spheres, std::vector<char>& recorded,
                           CoverageGrid& grid, FillContract& contract, double min_radius,
                           int sweeps, double min_gain, std::int64_t max_work,
                           const Interrupter& interrupter) {
  RefineStats stats;
  const double h = contract.voxel();
  const std::size_t n = spheres.size();
  // A sphere whose neighbours did not move since it was last searched would search the same
  // voxels again: only spheres near a move (within the largest step of touching) are searched.
  std::vector<char> stale(n, 1);
  const std::int64_t work_limit =
      max_work > 0 ? grid.work() + max_work : std::numeric_limits<std::int64_t>::max();
  bool spent = false;
  auto mark_near = [&](const Sphere& s) {
    for (std::size_t j = 0; j < n; ++j)
      if ((spheres[j].center - s.center).norm() < spheres[j].radius + s.radius + 4.0 * h)
        stale[j] = 1;
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const std::int64_t uncovered_at_start = grid.uncovered();
    std::vector<char> searched(n, 0);
    searched.swap(stale);  // this sweep searches the spheres marked so far
    for (std::size_t i = 0; i < n && !spent; ++i) {
      if (!searched[i]) continue;
      if (grid.work() >= work_limit) {
        spent = true;
        break;
      }
      if (interrupted(interrupter, "fill", 1.0))
        throw Interrupted("fill: interrupted while refining sphere " + std::to_string(i + 1) +
                          " of " + std::to_string(n));
      const Sphere old = spheres[i];
      grid.uncover(old);
      if (recorded[i]) contract.release(old);
      const std::int64_t own = grid.uncovered_in(old);
      // Pattern search over the centre; each probe takes the largest radius allowed there.
      Vec3 c = old.center;
      std::int64_t best = own;
      for (double step = 2.0 * h; step > 0.2 * h; step *= 0.5) {
        for (int iter = 0; iter < 4; ++iter) {
          bool moved = false;
          const Vec3 from = c;
          for (int axis = 0; axis < 6; ++axis) {
            Vec3 u = Vec3::Zero();
            u[axis / 2] = axis % 2 ? 1.0 : -1.0;
            const Vec3 q = from + step * u;
            const double dq = contract.near_distance(q);
            if (!(dq > 0.0)) continue;
            double rq = contract.radius_at(q, dq);
            if (rq < min_radius) continue;
            std::int64_t g = grid.uncovered_in(Sphere{q, rq});
            // The ledger is asked only for a probe that would win (it is the slow part).
            if (g > best && rq > dq && !contract.within_budget(Sphere{q, rq})) {
              rq = dq;
              g = rq < min_radius ? 0 : grid.uncovered_in(Sphere{q, rq});
            }
            if (g > best) {
              best = g;
              c = q;
              moved = true;
            }
          }
          if (!moved) break;
        }
      }
      bool moved = false;
      if (c != old.center) {
        const PlacedSphere placed = contract.place(c, true);
        if (placed.sphere.radius >= min_radius && grid.uncovered_in(placed.sphere) > own) {
          spheres[i] = placed.sphere;
          recorded[i] = placed.recorded;
          moved = true;
          ++stats.moves;
        } else if (placed.recorded) {
          contract.release(placed.sphere);
        }
      }
      if (!moved && recorded[i]) contract.record(old);  // the move undone
      grid.cover(spheres[i]);
      if (moved) mark_near(old), mark_near(spheres[i]);
    }
    ++stats.sweeps;
    const double gained = double(uncovered_at_start - grid.uncovered()) / double(grid.interior());
    if (gained < min_gain || spent) break;
  }
  return stats;
}

}  // namespace clumpkit
