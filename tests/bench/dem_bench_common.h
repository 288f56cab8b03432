// What the DEM benchmarks share: the material and step of the LAMMPS baseline decks, lattice
// subsets, the clock, and settled packings cached as checkpoints between runs.
#pragma once

#include "dem/core/world.h"
#include "geom/random.h"
#include "io/formats/checkpoint.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace clumpkit::dem::bench {

constexpr double kD = 0.010;  ///< sphere diameter of the decks (m)

inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// The decks' contact law, time step, skin and gravity.
inline WorldOptions options() {
  WorldOptions o;
  o.gravity = Vec3(0.0, 0.0, -9.81);
  o.timestep = 5e-6;
  o.skin = 0.002;
  o.contact.kn = 1e6;
  o.contact.ks = 1e6;
  o.contact.friction = 0.8;
  o.contact.damping_ratio = 0.3;
  return o;
}

// A random subset of n points, kept in lattice order (locality).
inline std::vector<Vec3> subset(const std::vector<Vec3>& pts, std::size_t n, Rng& rng) {
  std::vector<std::size_t> idx(pts.size());
  for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
  for (std::size_t k = 0; k < n; ++k) std::swap(idx[k], idx[k + rng.below(idx.size() - k)]);
  idx.resize(n);
  std::sort(idx.begin(), idx.end());
  std::vector<Vec3> out;
  for (std::size_t k : idx) out.push_back(pts[k]);
  return out;
}

inline Vec3 random_velocity(Rng& rng) {
  return rng.uniform(Vec3::Constant(-0.05), Vec3::Constant(0.05));
}

inline double max_top(const World& w) {
  double z = 0.0;
  for (const Body& b : w.bodies())
    for (const Sphere& s : b.spheres)
      z = std::max(z, (b.position + b.orientation * s.center).z() + s.radius);
  return z;
}

// `start` settled for `settle` steps on `threads` threads, from the checkpoint
// $TMPDIR/clumpkit-dem-bench-NAME-SETTLE.ckpt when an earlier run saved it (`cached`), else
// settled (printing its progress) and saved there.
inline World settled_or_cached(World start, const std::string& name, long settle, int threads,
                               std::string& ckpt, bool& cached) {
  const char* tmp = std::getenv("TMPDIR");
  ckpt = std::string(tmp && *tmp ? tmp : "/tmp") + "/clumpkit-dem-bench-" + name + "-" +
         std::to_string(settle) + ".ckpt";
  cached = false;
  try {
    World w = load_checkpoint(ckpt);
    cached = true;
    return w;
  } catch (const std::exception&) {
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const double t0 = now();
  for (long done = 0; done < settle; done += 10000) {
    start.step(static_cast<int>(std::min(10000L, settle - done)));
    std::printf("  settling: step %lld, KE %.4g J, unbalanced ratio %.3g\n",
                static_cast<long long>(start.steps()), kinetic_energy(start),
                mean_unbalanced_force_ratio(start));
    std::fflush(stdout);
  }
  std::printf("  settled in %.1f s\n", now() - t0);
  save_checkpoint(ckpt, start);
  return start;
}

}  // namespace clumpkit::dem::bench
