#include "geom/fill/fill.h"

#include "geom/errors.h"
#include "geom/fill/overshoot.h"
#include "geom/fill/skeleton.h"
#include "geom/mesh/mesh_index.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <string>

namespace clumpkit {

namespace {

// Uncovered interior voxels as one bit per voxel, rows along x packed in 64-bit words, so the
// voxels of a ball are counted or cleared a row span at a time with popcount.
class CoverageGrid {
 public:
  explicit CoverageGrid(const DistanceField& f) : f_(f), words_((f.dims[0] + 63) / 64) {
    bits_.assign(std::size_t(words_) * f.dims[1] * f.dims[2], 0);
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i)
          if (f.at(i, j, k) > 0.0f) {
            row(j, k)[i >> 6] |= std::uint64_t(1) << (i & 63);
            ++interior_;
          }
    uncovered_ = interior_;
  }

  std::int64_t interior() const { return interior_; }
  std::int64_t uncovered() const { return uncovered_; }

  /// Number of uncovered voxel centres inside the ball; clears them if `clear`.
  std::int64_t visit(const Vec3& c, double r, bool clear) {
    const Vec3 g = (c - f_.origin) / f_.h;
    const double rv = r / f_.h;
    const int k0 = std::max(0, int(std::ceil(g.z() - rv))),
              k1 = std::min(f_.dims[2] - 1, int(std::floor(g.z() + rv)));
    const int j0 = std::max(0, int(std::ceil(g.y() - rv))),
              j1 = std::min(f_.dims[1] - 1, int(std::floor(g.y() + rv)));
    std::int64_t n = 0;
    for (int k = k0; k <= k1; ++k) {
      const double dz = k - g.z();
      for (int j = j0; j <= j1; ++j) {
        const double dy = j - g.y();
        const double rem = rv * rv - dy * dy - dz * dz;
        if (rem < 0.0) continue;
        const double s = std::sqrt(rem);
        const int i0 = std::max(0, int(std::ceil(g.x() - s)));
        const int i1 = std::min(f_.dims[0] - 1, int(std::floor(g.x() + s)));
        if (i0 > i1) continue;
        n += span(row(j, k), i0, i1, clear);
      }
    }
    if (clear) uncovered_ -= n;
    return n;
  }

 private:
  std::uint64_t* row(int j, int k) { return &bits_[(std::size_t(k) * f_.dims[1] + j) * words_]; }

  static std::int64_t span(std::uint64_t* w, int i0, int i1, bool clear) {
    std::int64_t n = 0;
    const int w0 = i0 >> 6, w1 = i1 >> 6;
    for (int q = w0; q <= w1; ++q) {
      std::uint64_t mask = ~std::uint64_t(0);
      if (q == w0) mask &= ~std::uint64_t(0) << (i0 & 63);
      if (q == w1 && (i1 & 63) != 63) mask &= (std::uint64_t(1) << ((i1 & 63) + 1)) - 1;
      n += __builtin_popcountll(w[q] & mask);
      if (clear) w[q] &= ~mask;
    }
    return n;
  }

  const DistanceField& f_;
  int words_;
  std::vector<std::uint64_t> bits_;
  std::int64_t interior_ = 0, uncovered_ = 0;
};

struct Entry {
  std::int64_t gain;  // upper bound until evaluated at the current round
  int index;
  int round;  // round at which `gain` was computed exactly (-1 = bound)
  bool operator<(const Entry& o) const {
    return gain != o.gain ? gain < o.gain : index > o.index;  // max gain, then lowest index
  }
};

}  // namespace

void validate(const FillOptions& o) {
  if (o.spheres < 0)
    throw InvalidInput("--spheres must be at least 1, got " + std::to_string(o.spheres));
  if (!(o.coverage >= 0.0 && o.coverage <= 1.0))
    throw InvalidInput("--coverage must be in (0, 1], got " + std::to_string(o.coverage));
  if (!(o.min_radius >= 0.0) || !std::isfinite(o.min_radius))
    throw InvalidInput("--min-radius must be non-negative, got " + std::to_string(o.min_radius));
  if (!std::isfinite(o.tolerance) || !(o.tolerance_voxels >= 0.0) ||
      !std::isfinite(o.tolerance_voxels))
    throw InvalidInput("--tolerance must be finite and non-negative, got " +
                       std::to_string(o.tolerance));
  if (!(o.tolerance_relative >= 0.0 && o.tolerance_relative < 1.0))
    throw InvalidInput("--relative-tolerance must be in [0, 1), got " +
                       std::to_string(o.tolerance_relative));
  if (!(o.max_overshoot >= 0.0 && o.max_overshoot < 1.0))
    throw InvalidInput("--max-overshoot must be in [0, 1), got " + std::to_string(o.max_overshoot));
  if (!(o.ridge > 0.0 && o.ridge <= 1.0))
    throw InvalidInput("ridge threshold must be in (0, 1], got " + std::to_string(o.ridge));
}

FillResult fill(const MeshIndex& distance, const DistanceField& field, const FillOptions& options,
                const Interrupter& interrupter) {
  validate(options);
  FillResult r;
  r.voxel = field.h;
  const int budget = options.spheres > 0 ? options.spheres : (options.coverage > 0 ? 1 << 30 : 50);
  // The field may be off by a few voxels deep inside: select candidates with a margin, then
  // apply min_radius to the exact radius.
  auto cand =
      medial_candidates(field, options.ridge, std::max(0.0, options.min_radius - 3.0 * field.h));
  r.candidates = static_cast<int>(cand.size());
  CoverageGrid grid(field);
  if (grid.interior() == 0)
    throw InvalidInput("the mesh has no interior voxel at voxel size " + std::to_string(field.h) +
                       ": use more --voxels");
  const double tolerance =
      options.tolerance >= 0 ? options.tolerance : options.tolerance_voxels * field.h;
  // Radius of a sphere whose centre lies `d` inside the surface: the tolerance lets it poke out.
  auto grown = [&](double d) { return d + tolerance + options.tolerance_relative * d; };
  // The tolerance is meant for point contacts (faces, edges, corners), where the part outside is
  // a small cap. Where the surface hugs the sphere (an ellipsoid's waist, a cylinder) a whole
  // band would poke out: if more than 15 % of 64 directions on the grown sphere end outside the
  // field, the sphere keeps its inscribed radius.
  std::vector<Vec3> directions(64);
  for (int q = 0; q < 64; ++q) {
    const double z = 1.0 - (2.0 * q + 1.0) / 64.0, rho = std::sqrt(1.0 - z * z);
    const double phi = q * 2.399963229728653;  // golden angle: a Fibonacci sphere
    directions[q] = Vec3(rho * std::cos(phi), rho * std::sin(phi), z);
  }
  auto fits = [&](const Vec3& c, double rad) {
    int outside = 0;
    for (const auto& u : directions) outside += field.sample(c + rad * u) < 0.0;
    return outside <= 9;
  };
  auto radius_at = [&](const Vec3& c, double d) {
    const double g = grown(d);
    return (g > d && !fits(c, g)) ? d : g;
  };
  std::vector<char> exact(cand.size(), 0);
  // Distances while searching come from the field's features (exact distances to the nearest
  // triangles of the voxels around a point: a few dozen point–triangle distances, whatever the
  // triangle count; never below the truth). The sphere a search ends with takes its radius from
  // an exact nearest-triangle search of the index, bounded by the feature distance.
  const Mesh& mesh = distance.mesh();
  auto near_distance = [&](const Vec3& p) { return feature_distance(field, mesh, p); };
  auto exact_radius = [&](int c) {
    if (!exact[c]) {
      cand[c].radius = radius_at(cand[c].center, near_distance(cand[c].center));
      exact[c] = 1;
    }
    return cand[c].radius;
  };

  // The largest inscribed sphere first: exact radii of the candidates the field ranks near the
  // top, then the largest (lowest index among equals).
  double field_max = 0.0;
  for (const auto& c : cand) field_max = std::max(field_max, c.radius);
  int first = -1;
  for (int c = 0; c < static_cast<int>(cand.size()); ++c)
    if (cand[c].radius >= field_max - 4.0 * field.h) {
      exact_radius(c);
      if (first < 0 || cand[c].radius > cand[first].radius) first = c;
    }
  if (first < 0 || cand[first].radius < options.min_radius) {
    r.stopped_by = "min-radius";
    return r;
  }

  std::priority_queue<Entry> queue;
  for (int c = 0; c < static_cast<int>(cand.size()); ++c) {
    if (c == first) continue;
    // Lattice points in a ball of radius R (voxel units) number at most the volume of the ball
    // of radius R + √3/2. The field radius gets one voxel of slack for its error.
    const double R = cand[c].radius / field.h + (exact[c] ? 0.0 : 1.0) + 0.8660254037844386;
    queue.push(Entry{static_cast<std::int64_t>(std::ceil(4.18879020478639 * R * R * R)), c, -1});
  }

  // Pattern search around a chosen centre: 26 directions, shrinking step.
  // A sphere that kept its inscribed radius (`grow` false) stays so while it moves; a grown one
  // is re-checked where it ends.
  auto search = [&](Vec3 c, double rad, bool grow, auto&& gain) {
    std::int64_t best = gain(Sphere{c, rad});
    for (double step = 0.5 * field.h; step > 0.2 * field.h; step *= 0.5) {
      for (int iter = 0; iter < 4; ++iter) {
        bool moved = false;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              if (dx == 0 && dy == 0 && dz == 0) continue;
              const Vec3 q = c + step * Vec3(dx, dy, dz);
              const double dq = near_distance(q);
              const double rq = grow ? grown(dq) : dq;
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
  };

  // The overshoot contract: grown spheres are recorded on a ledger of rows a third of a voxel
  // apart, over the field's box and a tenth more (a sphere grows past the surface by a few
  // percent of its radius), and one is grown only while the ledger stays within 0.9 of the
  // budget. The mesh volume: exact for a closed mesh, the interior voxels' for one that is not.
  const Vec3 field_hi =
      field.origin + field.h * Vec3(field.dims[0] - 1, field.dims[1] - 1, field.dims[2] - 1);
  const Vec3 margin = 0.1 * (field_hi - field.origin).maxCoeff() * Vec3::Ones();
  OvershootLedger ledger(distance, {field.origin - margin, field_hi + margin}, field.h / 3.0);
  const double closed_volume = signed_volume(mesh);
  const double mesh_volume = options.field.vote_sign || !(closed_volume > 0.0)
                                 ? double(grid.interior()) * field.h * field.h * field.h
                                 : closed_volume;
  const double outside_budget = 0.9 * options.max_overshoot * mesh_volume;

  // The radius a placed sphere keeps: from the exact distance at its centre (the features can
  // run high where several compete), grown unless a band of it would then poke out or the
  // overshoot budget would not hold it.
  auto exact_sphere = [&](const Vec3& c, bool grow) {
    const double d = distance.distance(c, near_distance(c) * (1.0 + 1e-9) + 1e-12 * field.h);
    const double g = grown(d);
    if (grow && g > d && fits(c, g)) {
      const Sphere big{c, g};
      if (ledger.volume() + ledger.added(big) <= outside_budget) {
        ledger.add(big);
        r.overshoot = ledger.volume() / mesh_volume;
        return big;
      }
    }
    return Sphere{c, d};
  };

  auto accept = [&](int c) {
    const bool grow = cand[c].radius > near_distance(cand[c].center);
    const Sphere found =
        options.refine
            ? search(cand[c].center, cand[c].radius, grow,
                     [&](const Sphere& b) { return grid.visit(b.center, b.radius, false); })
            : Sphere{cand[c].center, cand[c].radius};
    const Sphere s = exact_sphere(found.center, grow);
    grid.visit(s.center, s.radius, true);
    r.clump.spheres.push_back(s);
    r.coverage_curve.push_back(1.0 - double(grid.uncovered()) / double(grid.interior()));
  };
  accept(first);
  // The sphere budget and the coverage target end either strategy; sets stopped_by.
  auto budget_or_coverage_met = [&] {
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
  };
  if (options.strategy == FillOptions::Strategy::Largest) {
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
      if (!inside) {
        const Sphere s =
            exact_sphere(cand[c].center, cand[c].radius > near_distance(cand[c].center));
        grid.visit(s.center, s.radius, true);
        r.clump.spheres.push_back(s);
        r.coverage_curve.push_back(1.0 - double(grid.uncovered()) / double(grid.interior()));
      }
    }
    return r;
  }
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
        accept(e.index);
        placed = true;
        break;
      }
      if (exact_radius(e.index) < options.min_radius) {
        skipped_small = true;
        continue;
      }
      e.gain = grid.visit(cand[e.index].center, cand[e.index].radius, false);
      e.round = round;
      if (e.gain > 0) queue.push(e);
    }
    if (!placed) {
      // No candidate adds coverage: the medial candidates ran out, unless min_radius dropped
      // some of them.
      r.stopped_by = skipped_small ? "min-radius" : "candidates";
      break;
    }
    ++round;
  }

  return r;
}

FillResult fill(const Mesh& mesh, const FillOptions& options, const Interrupter& interrupter) {
  validate(options);
  const MeshIndex index(mesh);
  return fill(index, make_distance_field(index, options.field), options, interrupter);
}

}  // namespace clumpkit
