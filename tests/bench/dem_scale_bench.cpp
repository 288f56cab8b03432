// Settled packings of 10⁴ to 10⁶ spheres: time per sphere-step on 1 and 2 threads and the
// process's peak memory per sphere (acceptance 3 of the dense-packing issue: the cost may not grow
// by more than 20 % from 10⁴ to 10⁶; run one size per process for the peak of that size).
// A tile of 10,000 spheres (the material of dem_bench's falling spheres) settled for --settle
// steps in a square box with smooth side walls (cached as a checkpoint in $TMPDIR), then copied
// side by side in mirror image with its contacts (tiled_world).
//
// Usage: dem_scale_bench [--settle N] [--sizes 10000,100000,1000000] [--threads 1,2]
//   The same 2·10⁸ sphere-steps at every size, after 20 steps that build the lists.
#include "tests/bench/dem_bench_common.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace clumpkit;
using namespace clumpkit::dem;
using namespace clumpkit::dem::bench;

namespace {

// --- Scale (case d): settled packings of 10⁴ to 10⁶ spheres. A tile of 10,000 spheres (the
// material of case a) settled in a square box of side kTile, then copied side by side in mirror
// image (tiled_world), so the packing is settled without settling 10⁶ spheres from a fall
// (10¹¹ sphere-steps). Walls: the floor and the outer box.
constexpr double kTile = 0.2;
constexpr int kTileSpheres = 10000;

// The floor, and frictionless side walls: a tile held up by the friction of its side walls would
// slump once they fall between copies (its image across a seam moves with it, so no friction
// takes their place: 4.1 contacts per sphere fell to 3.3 within 5,000 steps).
void add_box_walls(World& w, double lx, double ly) {
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  for (Wall side :
       {Wall::plane(Vec3::Zero(), Vec3::UnitX()), Wall::plane(Vec3(lx, 0, 0), -Vec3::UnitX()),
        Wall::plane(Vec3::Zero(), Vec3::UnitY()), Wall::plane(Vec3(0, ly, 0), -Vec3::UnitY())}) {
    side.friction = 0.0;
    w.add_wall(side);
  }
}

World tile_world() {
  World w(options());
  add_box_walls(w, kTile, kTile);
  const double a = 1.15 * kD;
  std::vector<Vec3> pts;  // simple-cubic points in the box, z-major, 4/3 of what is kept
  for (int k = 0; pts.size() < kTileSpheres * 4 / 3; ++k)
    for (int j = 0; (j + 0.5) * a + 0.5 * kD <= kTile; ++j)
      for (int i = 0; (i + 0.5) * a + 0.5 * kD <= kTile; ++i)
        pts.push_back(Vec3((i + 0.5) * a, (j + 0.5) * a, 0.006 + (k + 0.5) * a));
  Rng rng(4720);
  for (const Vec3& p : subset(pts, kTileSpheres, rng)) {
    Body b = make_sphere_body(p, 0.5 * kD, 2700.0);
    b.velocity = random_velocity(rng);
    w.add_body(std::move(b));
  }
  return w;
}

// mx × my copies of `tile`, every other one mirrored in x and in y so that copies meet in
// mirror image: a sphere that rested on a box wall faces its own image across the seam, at twice
// its wall overlap, where the wall pushed. Copies keep their contacts and shear history (a copy
// without them is no longer held by friction and slumps: 4.1 contacts per sphere fell to 1.9);
// contacts with the walls that remain (the floor, the outer box) are kept, those at the seams
// (frictionless: normal forces only) give way to the pair with the image.
// Tile-major order, each copy in its own order (local, as settled).
World tiled_world(const World& tile, int mx, int my) {
  World w(tile.options());
  add_box_walls(w, mx * kTile, my * kTile);
  const int n = tile.sphere_count();
  const std::size_t copies = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
  w.reserve(copies * tile.bodies().size(), copies * static_cast<std::size_t>(n));
  std::vector<PairContact> pairs;
  pairs.reserve(copies * tile.contacts().size());
  std::vector<WallContact> walls;
  for (int ty = 0; ty < my; ++ty)
    for (int tx = 0; tx < mx; ++tx) {
      const int first = (ty * mx + tx) * n;
      const double sx = tx % 2 ? -1.0 : 1.0, sy = ty % 2 ? -1.0 : 1.0;
      const Vec3 shift((tx + (tx % 2)) * kTile, (ty + (ty % 2)) * kTile, 0.0);
      const auto point = [&](const Vec3& p) -> Vec3 {
        return Vec3(sx * p.x(), sy * p.y(), p.z()) + shift;
      };
      const auto vec = [&](const Vec3& v) -> Vec3 { return Vec3(sx * v.x(), sy * v.y(), v.z()); };
      const auto axial = [&](const Vec3& v) -> Vec3 {
        return sx * sy * vec(v);
      };  // ω: a pseudovector
      for (const Body& b : tile.bodies()) {
        Body c = b;
        c.position = point(b.position);
        c.velocity = vec(b.velocity);
        c.angular_velocity = axial(b.angular_velocity);
        w.add_body(std::move(c));
      }
      const auto mirrored = [&](ContactState s) {
        s.normal = vec(s.normal);
        s.point = point(s.point);
        s.shear = vec(s.shear);
        return s;
      };
      for (PairContact c : tile.contacts()) {
        c.i += first;
        c.j += first;
        c.state = mirrored(c.state);
        pairs.push_back(c);
      }
      // Walls: 0 floor, 1 x = 0, 2 x = max, 3 y = 0, 4 y = max (add_box_walls); a tile's side
      // wall lands on the outer box or on a seam.
      for (WallContact c : tile.wall_contacts()) {
        if (c.wall > 0) {
          const bool along_x = c.wall <= 2;
          const Vec3 at = point(c.wall % 2 ? Vec3::Zero() : Vec3(kTile, kTile, 0.0));
          const double x = along_x ? at.x() : at.y(), end = along_x ? mx * kTile : my * kTile;
          if (std::abs(x) < 1e-12)
            c.wall = along_x ? 1 : 3;
          else if (std::abs(x - end) < 1e-9)
            c.wall = along_x ? 2 : 4;
          else
            continue;  // a seam
        }
        c.sphere += first;
        c.state = mirrored(c.state);
        walls.push_back(c);
      }
    }
  std::sort(walls.begin(), walls.end(), [](const WallContact& a, const WallContact& b) {
    return a.sphere != b.sphere ? a.sphere < b.sphere : a.wall < b.wall;
  });
  World::ListState lists;
  lists.steps = tile.steps();
  lists.time = tile.time();
  w.restore(std::move(lists), std::move(pairs), std::move(walls));
  return w;
}

long peak_rss_bytes() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return 1024 * std::atol(line.c_str() + 6);
  return -1;
}

std::vector<long> parse_list(const std::string& text) {
  std::vector<long> out;
  std::stringstream s(text);
  std::string t;
  while (std::getline(s, t, ',')) out.push_back(std::atol(t.c_str()));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  long settle = 100000;
  std::vector<long> sizes{10000, 100000, 1000000};
  std::vector<int> threads{1, 2};
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (k + 1 >= argc) {
      std::fprintf(stderr,
                   "usage: dem_scale_bench [--settle N] [--sizes N,N,...] [--threads 1,2]\n");
      return 2;
    }
    const std::string v = argv[++k];
    if (a == "--settle")
      settle = std::atol(v.c_str());
    else if (a == "--sizes")
      sizes = parse_list(v);
    else if (a == "--threads") {
      threads.clear();
      for (long t : parse_list(v)) threads.push_back(static_cast<int>(t));
    } else {
      std::fprintf(stderr,
                   "usage: dem_scale_bench [--settle N] [--sizes N,N,...] [--threads 1,2]\n");
      return 2;
    }
  }
  std::string ckpt;
  bool cached = false;
  const World tile =
      settled_or_cached(tile_world(), "tile-smooth", settle,
                        *std::max_element(threads.begin(), threads.end()), ckpt, cached);
  std::printf(
      "tile of %zu spheres in a %.2f m box (%s %s), %lld steps settled, KE %.4g J, "
      "unbalanced ratio %.3g, zmax %.4f\n",
      tile.bodies().size(), kTile, cached ? "cached" : "saved", ckpt.c_str(),
      static_cast<long long>(tile.steps()), kinetic_energy(tile), mean_unbalanced_force_ratio(tile),
      max_top(tile));
  std::printf(
      "\n| spheres | tiles | threads | steps | ns per sphere-step | contacts per sphere "
      "| peak RSS [MB] | bytes per sphere |\n|---|---|---|---|---|---|---|---|\n");
  for (long n : sizes) {
    const long copies = std::max(1L, n / kTileSpheres);
    int mx = static_cast<int>(std::sqrt(static_cast<double>(copies)));
    while (copies % mx) --mx;
    const int my = static_cast<int>(copies / mx);
    // The same number of sphere-steps at every size (10⁹ / 5 per thread count), at least 100
    // steps, after 20 steps that build the lists.
    const long timed_steps = std::max(100L, 200000000L / (copies * kTileSpheres));
    for (int t : threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, t);
      World w = tiled_world(tile, mx, my);
      w.step(20);
      const double t0 = now();
      w.step(static_cast<int>(timed_steps));
      const double sec = now() - t0;
      const double spheres = static_cast<double>(w.sphere_count());
      const long peak = peak_rss_bytes();
      std::printf("| %d | %d × %d | %d | %ld | %.1f | %.2f | %.0f | %.0f |\n", w.sphere_count(), mx,
                  my, t, timed_steps, 1e9 * sec / (spheres * timed_steps),
                  2.0 * static_cast<double>(w.contacts().size()) / spheres, peak / 1048576.0,
                  peak / spheres);
      std::fflush(stdout);
    }
  }
  return 0;
}
