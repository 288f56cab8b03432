// Lean DEM speed against the LAMMPS baseline decks of ../shared/baselines/lammps: the same
// three cases built with our World, timed on 1 and 2 threads, in
// sphere-steps per second (spheres × steps / loop seconds, the figure run.sh prints).
//  (a) 20,000 falling spheres (in.spheres): d = 10 mm, ρ = 2700, kn = ks = 1e6 N/m, μ = 0.8,
//      normal damping ratio 0.3, dt = 5e-6 s, skin 2 mm, cylinder R = 0.15 m + floor, gravity;
//      a random 20,000 subset of a simple-cubic lattice (a = 1.15 d) in r < 0.15 − 0.65 d,
//      z in [0.006, 0.56], velocities uniform in ±0.05 m/s per component.
//  (b) 2,000 falling rigid 10-sphere clumps (in.clumps): molecule.clump's geometry (read from the
//      baseline folder, or regenerated exactly as make_clump.py does), ρ = 2870, lattice 0.0215 m
//      in r < 0.1385, z in [0.0115, 0.50], random orientations.
//  (c) the settled packing (in.dense): (a) settled for --settle steps (cached as a checkpoint in
//      $TMPDIR), then --dense steps timed, as settled (bodies in lattice order, already local)
//      and shuffled (the same bodies added in a random order, shear history dropped: the order a
//      specimen built from a shuffled library has), each unsorted and sorted every --sort steps
//      (WorldOptions::sort_every; LAMMPS's atom_modify sort is on by default every 1,000).
// Differences to LAMMPS: no tangential dashpot (LAMMPS uses 0.5·γn); wall dashpot with m_eff = m
// (LAMMPS: the same γn, i.e. √2 larger); clump spins start at zero.
//
// Usage: dem_bench [--steps N] [--settle N] [--dense N] [--sort N] [--threads 1,2] [--full]
//                  [--lammps FILE] [--cases spheres,clumps,dense] [--no-shuffled]
//   defaults: --steps 5000 --settle 40000 --dense 2000 (--full: 40000, 100000, 10000), a few
//   minutes on 2 cores (the settle runs once, then comes from the cached checkpoint). In.dense
//   starts from a 100,000-step settle: use --full (or --settle 100000) for the ratio.
//   --sort 1000 by default; 0 times the unsorted orders only. --no-shuffled leaves the shuffled
//   orders out (for profiling the settled packing alone).
//   FILE: output of run.sh (SUMMARY lines), for the ratio column. Env CLUMPKIT_DEM_BENCH_FULL=1
//   is --full.
//   --cases zoned (not in the default set): the neighbour-list build of a zoned chamber at size
//   ratio 3 (CTGU 2017: a 6 mm core to R/2, 18 mm spheres beyond, compressed to n = 0.36 away
//   from the walls) against a monodisperse 6 mm chamber of about the same count: the time of a
//   step that rebuilds the list minus that of one that does not, over 20 steps each.
#include "tests/bench/dem_bench_common.h"

#include "dem/core/state_hash.h"
#include "dem/core/world.h"
#include "dem/specimen/compression.h"
#include "geom/random.h"
#include "io/formats/checkpoint.h"

#include <tbb/global_control.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <time.h>

using namespace clumpkit;
using namespace clumpkit::dem;
using namespace clumpkit::dem::bench;

namespace {

// The LAMMPS decks: $CLUMPKIT_LAMMPS_DECKS, else ../shared/baselines/lammps from the working
// directory (scripts/bench runs from the repository root).
std::string baseline_dir() {
  const char* env = std::getenv("CLUMPKIT_LAMMPS_DECKS");
  return env && *env ? env : "../shared/baselines/lammps";
}

double cpu_seconds() {  // process CPU time (all threads)
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void add_walls(World& w) {
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  w.add_wall(Wall::cylinder(0.0, 0.0, 0.150));
}

// Simple-cubic lattice points (i + ½)·a (LAMMPS `lattice sc a origin 0.5 0.5 0.5`) inside the
// box [−0.16, 0.16]² × [0, 0.9] and the cylinder r < rc, z in [z0, z1]; z-major order.
std::vector<Vec3> lattice(double a, double rc, double z0, double z1) {
  std::vector<Vec3> out;
  const int m = static_cast<int>(std::ceil(0.16 / a)) + 1;
  for (int k = 0; (k + 0.5) * a <= z1; ++k)
    for (int j = -m; j <= m; ++j)
      for (int i = -m; i <= m; ++i) {
        const Vec3 p((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a);
        if (p.z() < z0 || p.z() > z1 || std::abs(p.x()) > 0.16 || std::abs(p.y()) > 0.16) continue;
        if (p.x() * p.x() + p.y() * p.y() < rc * rc) out.push_back(p);
      }
  return out;
}

World spheres_world() {
  World w(options());
  add_walls(w);
  Rng rng(4711);
  const auto pts = subset(lattice(1.15 * kD, 0.150 - 0.65 * kD, 0.006, 0.56), 20000, rng);
  for (const Vec3& p : pts) {
    Body b = make_sphere_body(p, 0.5 * kD, 2700.0);
    b.velocity = random_velocity(rng);
    w.add_body(std::move(b));
  }
  return w;
}

// --- Clump template: molecule.clump, or make_clump.py ported (same MT19937 stream as Python).
struct Molecule {
  std::vector<Vec3> coords;  // centred on the COM
  double mass = 0.0;
  Mat3 inertia = Mat3::Zero();
  double volume = 0.0;
};

class PyRandom {  // CPython's random.Random(int seed): MT19937 init_by_array, random() 53 bits
 public:
  explicit PyRandom(std::uint32_t seed) {
    mt_[0] = 19650218u;
    for (mti_ = 1; mti_ < 624; ++mti_)
      mt_[mti_] = 1812433253u * (mt_[mti_ - 1] ^ (mt_[mti_ - 1] >> 30)) + mti_;
    std::uint32_t i = 1;
    for (int k = 624; k; --k) {  // key = {seed}, key length 1
      mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1664525u)) + seed;
      if (++i >= 624) mt_[0] = mt_[623], i = 1;
    }
    for (int k = 623; k; --k) {
      mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1566083941u)) - i;
      if (++i >= 624) mt_[0] = mt_[623], i = 1;
    }
    mt_[0] = 0x80000000u;
    mti_ = 624;
  }
  double random() {
    const std::uint32_t a = next() >> 5, b = next() >> 6;
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
  }
  double uniform(double a, double b) { return a + (b - a) * random(); }

 private:
  std::uint32_t next() {
    if (mti_ >= 624) {
      for (int k = 0; k < 624; ++k) {
        const std::uint32_t y = (mt_[k] & 0x80000000u) | (mt_[(k + 1) % 624] & 0x7fffffffu);
        mt_[k] = mt_[(k + 397) % 624] ^ (y >> 1) ^ ((y & 1u) ? 0x9908b0dfu : 0u);
      }
      mti_ = 0;
    }
    std::uint32_t y = mt_[mti_++];
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680u;
    y ^= (y << 15) & 0xefc60000u;
    y ^= y >> 18;
    return y;
  }
  std::uint32_t mt_[624];
  std::uint32_t mti_;
};

Molecule make_clump(int n, double d, double rho, std::uint32_t seed) {
  const double r = d / 2;
  const double ax[3] = {0.60 * d, 0.45 * d, 0.35 * d};
  PyRandom rng(seed);
  std::vector<Vec3> pts{Vec3::Zero()};
  while (static_cast<int>(pts.size()) < n) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = ax[k] * rng.uniform(-1, 1);
    double e = 0.0;
    for (int k = 0; k < 3; ++k) e += (p[k] / ax[k]) * (p[k] / ax[k]);
    if (e > 1) continue;
    double dm = 1e300;
    for (const Vec3& q : pts) dm = std::min(dm, (p - q).norm());
    if (0.25 * d <= dm && dm <= 0.8 * d) pts.push_back(p);
  }
  const double h = d / 60;
  Vec3 lo, hi;
  for (int k = 0; k < 3; ++k) {
    lo[k] = 1e300, hi[k] = -1e300;
    for (const Vec3& p : pts) lo[k] = std::min(lo[k], p[k] - r), hi[k] = std::max(hi[k], p[k] + r);
  }
  int nv[3];
  for (int k = 0; k < 3; ++k) nv[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / h));
  double V = 0.0;
  Vec3 S = Vec3::Zero();
  Mat3 S2 = Mat3::Zero();
  const double dv = h * h * h;
  for (int i = 0; i < nv[0]; ++i) {
    const double x = lo[0] + (i + 0.5) * h;
    for (int j = 0; j < nv[1]; ++j) {
      const double y = lo[1] + (j + 0.5) * h;
      std::vector<Vec3> near;
      for (const Vec3& p : pts)
        if ((x - p[0]) * (x - p[0]) + (y - p[1]) * (y - p[1]) <= r * r) near.push_back(p);
      if (near.empty()) continue;
      for (int k = 0; k < nv[2]; ++k) {
        const double z = lo[2] + (k + 0.5) * h;
        bool in = false;
        for (const Vec3& p : near)
          if ((x - p[0]) * (x - p[0]) + (y - p[1]) * (y - p[1]) + (z - p[2]) * (z - p[2]) <=
              r * r) {
            in = true;
            break;
          }
        if (!in) continue;
        V += dv;
        const Vec3 c(x, y, z);
        for (int a = 0; a < 3; ++a) {
          S[a] += c[a] * dv;
          for (int b = 0; b < 3; ++b) S2(a, b) += c[a] * c[b] * dv;
        }
      }
    }
  }
  Molecule m;
  const Vec3 com = S / V;
  Mat3 cov;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) cov(a, b) = S2(a, b) / V - com[a] * com[b];
  m.volume = V;
  m.mass = rho * V;
  m.inertia = m.mass * (cov.trace() * Mat3::Identity() - cov);
  for (const Vec3& p : pts) m.coords.push_back(p - com);
  return m;
}

bool read_molecule(const std::string& path, Molecule& m) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    if (line.find("true volume") != std::string::npos) {
      const auto at = line.find("true volume") + 11;
      m.volume = std::stod(line.substr(at));
    } else if (line.find(" atoms") != std::string::npos && line[0] != '#') {
      s >> n;
    } else if (line.find(" mass") != std::string::npos && line[0] != '#') {
      s >> m.mass;
    } else if (line.find(" inertia") != std::string::npos) {
      double v[6];
      for (double& x : v) s >> x;
      m.inertia << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
    } else if (line.rfind("Coords", 0) == 0) {
      std::getline(in, line);
      for (int k = 0; k < n && std::getline(in, line); ++k) {
        std::istringstream c(line);
        int id;
        Vec3 p;
        c >> id >> p.x() >> p.y() >> p.z();
        m.coords.push_back(p);
      }
    }
  }
  return n > 0 && static_cast<int>(m.coords.size()) == n && m.mass > 0.0;
}

Molecule clump_molecule(bool verbose) {
  Molecule m;
  const std::string file = baseline_dir() + "/molecule.clump";
  if (read_molecule(file, m)) {
    if (verbose) std::printf("clump template: %s\n", file.c_str());
    return m;
  }
  if (verbose) std::printf("clump template: regenerated (make_clump.py 10 0.010 2870 7)\n");
  return make_clump(10, kD, 2870.0, 7);
}

World clumps_world(const Molecule& m) {
  World w(options());
  add_walls(w);
  Eigen::SelfAdjointEigenSolver<Mat3> eig(m.inertia);
  Mat3 axes = eig.eigenvectors();  // principal frame -> template frame
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  Body proto;
  for (const Vec3& p : m.coords) proto.spheres.push_back(Sphere{axes.transpose() * p, 0.5 * kD});
  proto.mass = m.mass;
  proto.moments = eig.eigenvalues();
  const Eigen::Quaterniond frame(axes);
  Rng rng(4718);
  const auto pts = subset(lattice(0.0215, 0.1385, 0.0115, 0.50), 2000, rng);
  for (const Vec3& p : pts) {
    Body b = proto;
    Eigen::Quaterniond q = rng.normal_quaternion();
    q.normalize();
    b.position = p;
    b.orientation = (q * frame).normalized();
    b.velocity = random_velocity(rng);
    w.add_body(std::move(b));
  }
  return w;
}

struct Row {
  std::string name;
  std::string lammps_case;
  int threads;
  long steps;
  double rate;
  std::uint64_t hash;
};

Row timed(const std::string& name, const std::string& lcase, World w, int threads, long steps) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const double t0 = now();
  const double c0 = cpu_seconds();
  w.step(static_cast<int>(steps));
  const double t = now() - t0;
  const double cpu = (cpu_seconds() - c0) / t;  // CPU time / wall time, all threads
  const double rate = static_cast<double>(w.sphere_count()) * static_cast<double>(steps) / t;
  std::printf(
      "  %-16s threads %d steps %ld: %.2f s, %.3e sphere-steps/s, cpu use %.0f %%, contacts %zu + "
      "%zu wall, builds %lld, filters %lld, zmax %.4f, state %016llx\n",
      name.c_str(), threads, steps, t, rate, 100.0 * cpu, w.contacts().size(),
      w.wall_contacts().size(), static_cast<long long>(w.neighbour_builds()),
      static_cast<long long>(w.near_filters()), max_top(w),
      static_cast<unsigned long long>(state_hash(w)));
  std::fflush(stdout);
  return Row{name, lcase, threads, steps, rate, state_hash(w)};
}

// LAMMPS figures from run.sh output: "SUMMARY case=X np=N ... sphere_steps_per_s=R ...".
std::map<std::string, double> read_lammps(const std::string& path) {
  std::map<std::string, double> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("SUMMARY", 0) != 0) continue;
    auto field = [&](const std::string& key) {
      const auto at = line.find(" " + key + "=");
      if (at == std::string::npos) return std::string();
      const auto b = at + key.size() + 2;
      return line.substr(b, line.find(' ', b) - b);
    };
    const std::string c = field("case"), np = field("np"), r = field("sphere_steps_per_s");
    if (!c.empty() && !np.empty() && !r.empty()) out[c + "/" + np] = std::atof(r.c_str());
  }
  return out;
}

// A cylinder of 6 mm spheres compressed gravity-free: zoned (a core to r = 0.25·D, λ 3 beyond)
// or monodisperse, of diameter D and height H.
World compressed_chamber(bool zoned, double diameter, double height) {
  CompressionSpec s;
  s.shape = CompressionSpec::Shape::cylinder;
  s.size = Vec3(diameter, diameter, height);
  s.porosity = zoned ? 0.36 : 0.38;
  s.classes = {{0.00599, 0.00601, 100.0, false}};
  s.contact.kn = s.contact.ks = 5e5;
  s.contact.friction = 0.5;
  s.seed = 3;
  if (zoned) {
    s.zones.coordinate = ZoneCoordinate::radial;
    s.zones.regions = {{false, 0.25 * diameter, 1.0, 0, 0}, {false, diameter, 3.0, 0, 0}};
  }
  return compress_specimen(s).world;
}

// Seconds of a list build on `w`: a step after marking the list stale minus a plain step, the
// mean over `repeats` pairs.
double list_build_seconds(World w, int threads, int repeats) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  w.step(2);
  double rebuild = 0, plain = 0;
  for (int k = 0; k < repeats; ++k) {
    World::ListState s = w.list_state();
    s.stale = true;
    w.restore(s, w.contacts(), w.wall_contacts());
    double t0 = now();
    w.step(1);
    rebuild += now() - t0;
    t0 = now();
    w.step(1);
    plain += now() - t0;
  }
  return (rebuild - plain) / repeats;
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 5000, settle = 40000, dense = 2000;
  int sort_every = 1000;
  std::vector<int> threads{1, 2};
  std::string lammps, cases = "spheres,clumps,dense";
  bool with_shuffled = true;
  const char* full_env = std::getenv("CLUMPKIT_DEM_BENCH_FULL");
  bool full = full_env && std::string(full_env) == "1";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "dem_bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++k];
    };
    if (a == "--steps")
      steps = std::atol(value().c_str());
    else if (a == "--settle")
      settle = std::atol(value().c_str());
    else if (a == "--dense")
      dense = std::atol(value().c_str());
    else if (a == "--sort")
      sort_every = std::atoi(value().c_str());
    else if (a == "--no-shuffled")
      with_shuffled = false;
    else if (a == "--full")
      full = true;
    else if (a == "--lammps")
      lammps = value();
    else if (a == "--cases")
      cases = value();
    else if (a == "--threads") {
      threads.clear();
      std::stringstream s(value());
      std::string t;
      while (std::getline(s, t, ',')) threads.push_back(std::atoi(t.c_str()));
    } else {
      std::fprintf(stderr,
                   "usage: dem_bench [--steps N] [--settle N] [--dense N] [--sort N] "
                   "[--threads 1,2] [--full] [--lammps FILE] [--cases spheres,clumps,dense] "
                   "[--no-shuffled]\n");
      return 2;
    }
  }
  if (full) steps = 40000, settle = 100000, dense = 10000;
  auto wanted = [&](const char* c) { return cases.find(c) != std::string::npos; };

  std::printf("# dem_bench: lean DEM on the LAMMPS baseline cases\n\n");
  std::vector<Row> rows;
  if (wanted("spheres")) {
    const World w = spheres_world();
    std::printf("(a) falling spheres: %d spheres\n", w.sphere_count());
    for (int t : threads) rows.push_back(timed("falling spheres", "spheres", w, t, steps));
  }
  if (wanted("clumps")) {
    const Molecule m = clump_molecule(true);
    const World w = clumps_world(m);
    std::printf("(b) falling clumps: %zu bodies, %d spheres, clump mass %.6e kg\n",
                w.bodies().size(), w.sphere_count(), m.mass);
    for (int t : threads) rows.push_back(timed("falling clumps", "clumps", w, t, steps));
  }
  if (wanted("dense")) {
    std::string ckpt;
    bool cached = false;
    const World w =
        settled_or_cached(spheres_world(), "settled", settle,
                          *std::max_element(threads.begin(), threads.end()), ckpt, cached);
    std::printf(
        "(c) settled spheres (%s %s): %lld steps settled, KE %.4g J, unbalanced ratio "
        "%.3g, zmax %.4f\n",
        cached ? "cached" : "saved", ckpt.c_str(), static_cast<long long>(w.steps()),
        kinetic_energy(w), mean_unbalanced_force_ratio(w), max_top(w));
    const std::string name =
        settle >= 100000 ? "settled spheres" : "settling (" + std::to_string(settle) + ")";
    // The same bodies in a random order (a deterministic shuffle): what sorting is for.
    World shuffled(w.options());
    for (const Wall& wall : w.walls()) shuffled.add_wall(wall);
    std::vector<std::size_t> order(w.bodies().size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    Rng rng(4719);
    for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[rng.below(k)]);
    for (std::size_t k : order) shuffled.add_body(w.bodies()[k]);
    struct Variant {
      std::string label;
      const World* world;
      int sort;
    };
    std::vector<Variant> variants{{"", &w, 0}};
    if (sort_every > 0)
      variants.push_back(Variant{", sorted/" + std::to_string(sort_every), &w, sort_every});
    if (with_shuffled) {
      variants.push_back(Variant{", shuffled", &shuffled, 0});
      if (sort_every > 0)
        variants.push_back(
            Variant{", shuffled, sorted/" + std::to_string(sort_every), &shuffled, sort_every});
    }
    for (const Variant& v : variants) {
      World run = *v.world;
      run.options().sort_every = v.sort;
      for (int t : threads) rows.push_back(timed(name + v.label, "dense-spheres", run, t, dense));
    }
  }

  if (wanted("zoned")) {
    // 240 × 96 mm zoned: ~6,100 small + ~700 large spheres; the monodisperse chamber's size is
    // chosen for the same count (6 mm at n = 0.38 overall).
    const World zoned = compressed_chamber(true, 0.240, 0.096);
    const double count = double(zoned.bodies().size());
    const double volume = count * (kPi / 6 * 0.006 * 0.006 * 0.006) / (1 - 0.38);
    const double d = std::cbrt(volume / (kPi / 4 * 0.4));  // height 0.4 D
    const World mono = compressed_chamber(false, d, 0.4 * d);
    std::printf(
        "(z) neighbour-list build: zoned chamber %zu spheres (size ratio 3), "
        "monodisperse %zu spheres\n",
        zoned.bodies().size(), mono.bodies().size());
    for (int t : threads) {
      const double a = list_build_seconds(zoned, t, 20), b = list_build_seconds(mono, t, 20);
      std::printf(
          "  %d thread(s): build %.3f ms zoned, %.3f ms monodisperse; per sphere %.3f / "
          "%.3f us, ratio %.2f\n",
          t, 1e3 * a, 1e3 * b, 1e6 * a / count, 1e6 * b / double(mono.bodies().size()),
          (a / count) / (b / double(mono.bodies().size())));
    }
  }

  const auto ref = lammps.empty() ? std::map<std::string, double>{} : read_lammps(lammps);
  std::printf(
      "\n| case | threads | steps | ours [sphere-steps/s] | LAMMPS (ranks = threads) | "
      "ours / LAMMPS |\n|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const auto it = ref.find(r.lammps_case + "/" + std::to_string(r.threads));
    if (it != ref.end())
      std::printf("| %s | %d | %ld | %.3e | %.3e | %.2f |\n", r.name.c_str(), r.threads, r.steps,
                  r.rate, it->second, r.rate / it->second);
    else
      std::printf("| %s | %d | %ld | %.3e | – | – |\n", r.name.c_str(), r.threads, r.steps, r.rate);
  }
  bool same = true;
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (std::size_t b = a + 1; b < rows.size(); ++b)
      if (rows[a].name == rows[b].name && rows[a].steps == rows[b].steps)
        same = same && rows[a].hash == rows[b].hash;
  std::printf("\nbit-identical across thread counts: %s\n", same ? "yes" : "NO");
  return same ? 0 : 1;
}
