#include "dem/world.h"

#include "dem/parallel.h"
#include "dem/timestep.h"
#include "geom/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

namespace clumpkit::dem {

namespace {

// Rotation by the rotation vector phi (angle |phi| about phi/|phi|) as a unit quaternion.
Eigen::Quaterniond rotation_quaternion(const Vec3& phi) {
  const double angle = phi.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  const double h = 0.5 * angle;
  const Vec3 axis = phi * (std::sin(h) / angle);
  return Eigen::Quaterniond(std::cos(h), axis.x(), axis.y(), axis.z());
}

// v + ω × (p − x) and (p − x) × f written per component: Eigen's code for these expressions
// stores two scalars and reloads them as one packed pair, which defeats store forwarding and
// cost a third of the contact kernel (perf). Same formulas, same bits.
inline Vec3 point_velocity(const Vec3& v, const Vec3& w, const Vec3& p, const Vec3& x) {
  const double rx = p.x() - x.x(), ry = p.y() - x.y(), rz = p.z() - x.z();
  return Vec3(v.x() + (w.y() * rz - w.z() * ry), v.y() + (w.z() * rx - w.x() * rz),
              v.z() + (w.x() * ry - w.y() * rx));
}

inline Vec3 moment(const Vec3& p, const Vec3& x, const Vec3& f) {
  const double rx = p.x() - x.x(), ry = p.y() - x.y(), rz = p.z() - x.z();
  return Vec3(ry * f.z() - rz * f.y(), rz * f.x() - rx * f.z(), rx * f.y() - ry * f.x());
}

}  // namespace

namespace detail {

// The packed records of step(count) (see StepCache).
struct Kinematics {  // the translational and spin state of a body: what the contact kernels read
  Vec3 position, velocity, angular_velocity;
  double mass;
};

struct Wrench {  // a force and a torque
  Vec3 force, torque;
};

enum class Spin : std::uint8_t {
  plain_sphere,  // isotropic, one sphere on the origin: orientation not integrated
  isotropic,     // Ixx = Iyy = Izz: ω = L/I directly
  general,       // midpoint quaternion integration
  locked         // rotation_locked: translation only
};

struct Rotation {  // what the integrator reads of a body's rotation
  Eigen::Quaterniond orientation;
  Vec3 moments;
  Spin spin;
};

struct SlotOut {
  Vec3 force, point;
};

struct SlotForce {
  Vec3 shear;
  double normal_force;
};

struct SlotGeometry {
  Vec3 normal, point;
  double overlap;
};

}  // namespace detail

// What World::step derives from the persistent state and keeps between calls: the index of the
// near list, per-candidate contact slots, wall candidates and the packed body state. Never saved:
// every part is rebuilt from the persistent state when marked stale (a fresh cache is all stale).
struct detail::StepCache {
  NeighbourGrid grid_;                     // scratch of build_neighbours
  std::vector<std::size_t> cand_begin_;    // first candidate (i, ·) per sphere i
  std::vector<std::size_t> down_begin_;    // per sphere j: range in down_
  std::vector<std::size_t> down_;          // candidates (·, j) grouped by j, in order
  std::vector<std::size_t> body_begin_;    // per body: range in body_items_
  std::vector<std::uint64_t> body_items_;  // 2·candidate + (1 when the body holds j)
  // During step(count) the bodies' state lives in these packed arrays (loaded from bodies_ when
  // the call begins, stored back when it ends), so the per-step passes stream small records
  // instead of whole Body objects with their sphere vectors.
  std::vector<Kinematics> kinematics_;  // per body
  std::vector<Wrench> body_wrench_;     // per body: gravity + contacts of the last step
  std::vector<Rotation> rotation_;      // per body
  // Per candidate: the force on the body of j and its point of application, written by the
  // contact kernel in candidate order (zero while not touching); each body gathers its items
  // (body_items_) and forms ±force and the torque about its own centroid.
  std::vector<SlotOut> slot_out_;
  // Per body: one of its pairs touched in this step's contact pass (else its items are all zero
  // and the sum skips them: the sums start from gravity and +0 and never reach −0, so adding ±0
  // would change no bit). A per-body test, predictable both in free fall and in a packing.
  std::vector<std::uint8_t> body_touched_;
  // Per candidate: the normal dashpot 2·β·sqrt(m_eff·kn) (update_contact's formula), computed
  // when the candidates or the masses change instead of at every contact and step.
  std::vector<double> slot_damping_;
  bool damping_valid_ = false;
  // Per candidate, the contact state in two parts: what the contact law carries from step to
  // step (read and written every step), and the geometry (normal, point, overlap), which only
  // the contact lists report, so it is written on the last step of step(count) alone.
  std::vector<SlotForce> slot_force_;
  std::vector<SlotGeometry> slot_geometry_;
  bool record_geometry_ = true;                 // this step's contact pass writes slot_geometry_
  std::vector<std::uint8_t> slot_active_;       // per candidate: touching at the last step
  std::vector<std::pair<int, int>> wall_cand_;  // sorted (sphere, wall)
  std::vector<ContactState> wall_slot_state_;   // per wall candidate
  std::vector<std::uint8_t> wall_slot_active_;  // per wall candidate
  std::vector<std::size_t> body_wall_begin_;    // per body: range in wall_cand_
  std::vector<Wall> walls_at_build_;            // walls when wall_cand_ was built
  std::vector<std::size_t> scratch_;            // counts / offsets
  std::vector<std::uint8_t> filter_keep_;       // scratch of filter_candidates
  bool positions_fresh_ = false;  // sphere_world_ and moved_ set by integrate this call
  bool moved_ = true;             // a sphere moved more than sqrt(near_limit_) since the filter
  bool pairs_valid_ = false;      // slots mirror contacts_ for the current candidates_
  bool walls_valid_ = false;      // wall slots mirror wall_contacts_ for the current wall_cand_
};

namespace detail {
StepCacheHolder::StepCacheHolder() : cache_(std::make_unique<StepCache>()) {}
StepCacheHolder::~StepCacheHolder() = default;
StepCacheHolder::StepCacheHolder(const StepCacheHolder& other)
    : cache_(std::make_unique<StepCache>(other.get())) {}
StepCacheHolder& StepCacheHolder::operator=(const StepCacheHolder& other) {
  if (this != &other) cache_ = std::make_unique<StepCache>(other.get());
  return *this;
}
StepCacheHolder::StepCacheHolder(StepCacheHolder&& other) noexcept = default;
StepCacheHolder& StepCacheHolder::operator=(StepCacheHolder&& other) noexcept = default;
StepCache& StepCacheHolder::get() const {
  if (!cache_) cache_ = std::make_unique<StepCache>();
  return *cache_;
}
}  // namespace detail

using namespace detail;

World::World(WorldOptions options) : options_(options) {
  if (!(options_.timestep > 0.0) || !std::isfinite(options_.timestep))
    throw InvalidInput("DEM world: timestep must be positive, got " +
                       std::to_string(options_.timestep));
  if (!(options_.skin >= 0.0) || !std::isfinite(options_.skin))
    throw InvalidInput("DEM world: skin must be non-negative, got " +
                       std::to_string(options_.skin));
  if (!(options_.near_skin_fraction > 0.0 && options_.near_skin_fraction <= 1.0))
    throw InvalidInput("DEM world: near_skin_fraction must be in (0, 1], got " +
                       std::to_string(options_.near_skin_fraction));
  body_first_sphere_.push_back(0);
}

int World::add_body(Body body) {
  StepCache& sc = cache_.get();
  if (body.spheres.empty()) throw InvalidInput("DEM world: body has no spheres");
  if (!(body.mass > 0.0) || !(body.moments.minCoeff() > 0.0))
    throw InvalidInput("DEM world: body mass and moments must be positive");
  const int index = static_cast<int>(bodies_.size());
  for (const Sphere& s : body.spheres) {
    sphere_body_.push_back(index);
    sphere_local_.push_back(s.center);
    sphere_radius_.push_back(s.radius);
  }
  body_first_sphere_.push_back(static_cast<int>(sphere_body_.size()));
  body.orientation.normalize();
  bodies_.push_back(std::move(body));
  sphere_world_.resize(sphere_body_.size());
  dirty_ = true;
  sc.pairs_valid_ = sc.walls_valid_ = false;
  return index;
}

int World::add_wall(const Wall& wall) {
  StepCache& sc = cache_.get();
  walls_.push_back(wall);
  sc.walls_valid_ = false;
  return static_cast<int>(walls_.size()) - 1;
}

void World::update_sphere_positions() {
  parallel_items(sphere_body_.size(), [&](std::size_t k) {
    const Body& b = bodies_[sphere_body_[k]];
    sphere_world_[k] = b.position + b.orientation * sphere_local_[k];
  });
}

// Sphere world positions and the Verlet-list test (a sphere moved more than sqrt(near_limit_)
// since the last filter) in one parallel pass.
bool World::update_positions_and_check() {
  const std::size_t n = sphere_body_.size();
  const bool have_reference = !dirty_ && sphere_at_filter_.size() == n;
  const double limit = near_limit_;
  std::atomic<bool> moved{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      bool far = false;
                      for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        const Body& b = bodies_[sphere_body_[k]];
                        const Vec3& local = sphere_local_[k];
                        // q·0 is exactly +0 (Eigen's formula), so a centred sphere skips it.
                        const Vec3 x = local.isZero(0.0) ? Vec3(b.position + Vec3::Zero())
                                                         : Vec3(b.position + b.orientation * local);
                        sphere_world_[k] = x;
                        if (have_reference && (x - sphere_at_filter_[k]).squaredNorm() > limit)
                          far = true;
                      }
                      if (far) moved.store(true, std::memory_order_relaxed);
                    });
  return !have_reference || moved.load();
}

// The skin list (dem/neighbour_search.h): pairs of different bodies closer than
// r_i + r_j + skin at the current positions, which become the build positions.
void World::build_neighbours() {
  StepCache& sc = cache_.get();
  ++builds_;
  dirty_ = false;
  sphere_at_build_ = sphere_world_;
  find_skin_pairs(sphere_world_, sphere_radius_, sphere_body_, options_.skin, sc.grid_,
                  neighbours_);
}

// Called once a sphere has moved more than sqrt(near_limit_) since the last filter (or there is
// none). Let D be the largest displacement since the last build: the skin list still holds every
// pair that can touch while each sphere stays within skin/2 − D of where it is now, so when that
// leaves room for a fair step the near list is filtered again from it (a linear pass), else the
// grid search runs. Filtering at near skin s and allowing moves of min(s/2, skin/2 − D) keeps
// both lists complete, with as many builds as the one-list scheme when spheres move steadily.
// Returns true after a grid build (the wall candidates follow the build positions).
bool World::refresh_neighbours() {
  const std::size_t n = sphere_world_.size();
  const double skin = options_.skin;
  const double near = options_.near_skin_fraction * skin;
  double left = -1.0;  // how far every sphere may still move before neighbours_ expires
  if (!dirty_ && sphere_at_build_.size() == n) {
    const double moved2 = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 1024), 0.0,
        [&](const tbb::blocked_range<std::size_t>& r, double m) {
          for (std::size_t k = r.begin(); k != r.end(); ++k)
            m = std::max(m, (sphere_world_[k] - sphere_at_build_[k]).squaredNorm());
          return m;
        },
        [](double a, double b) { return std::max(a, b); });
    // A relative margin keeps the rounding of this bound on the safe side.
    left = (0.5 * skin - std::sqrt(moved2)) * (1.0 - 1e-9);
  }
  const bool build = !(left >= 0.25 * near);
  if (build) {
    build_neighbours();
    left = 0.5 * skin;
  }
  sphere_at_filter_ = sphere_world_;
  const double allowed = std::min(0.5 * near, left);
  near_limit_ = allowed * allowed;
  near_valid_ = false;
  return build;
}

// The near list: pairs of neighbours_ closer than r_i + r_j + near skin at sphere_at_filter_.
void World::filter_candidates() {
  StepCache& sc = cache_.get();
  ++filters_;
  filter_pairs(neighbours_, sphere_at_filter_, sphere_radius_,
               options_.near_skin_fraction * options_.skin, sc.filter_keep_, candidates_);
  near_valid_ = true;
}

// Index of the candidate list: per sphere its candidates as i (a range of candidates_) and as j
// (sc.down_), per body every candidate it takes part in, in candidate order — the order in which
// the serial sum of the reference implementation added them — and empty slots.
void World::derive_pair_index() {
  StepCache& sc = cache_.get();
  const std::size_t n = sphere_body_.size();
  const std::size_t m = candidates_.size();
  sc.cand_begin_.assign(n + 1, 0);
  sc.down_begin_.assign(n + 1, 0);
  for (const auto& [i, j] : candidates_) ++sc.cand_begin_[i + 1], ++sc.down_begin_[j + 1];
  for (std::size_t s = 0; s < n; ++s) {
    sc.cand_begin_[s + 1] += sc.cand_begin_[s];
    sc.down_begin_[s + 1] += sc.down_begin_[s];
  }
  sc.down_.resize(m);
  sc.scratch_.assign(sc.down_begin_.begin(), sc.down_begin_.end() - 1);
  for (std::size_t k = 0; k < m; ++k) sc.down_[sc.scratch_[candidates_[k].second]++] = k;

  const std::size_t nb = bodies_.size();
  sc.body_begin_.assign(nb + 1, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    std::size_t count = 0;
    for (int s = body_first_sphere_[b]; s < body_first_sphere_[b + 1]; ++s)
      count +=
          (sc.cand_begin_[s + 1] - sc.cand_begin_[s]) + (sc.down_begin_[s + 1] - sc.down_begin_[s]);
    sc.body_begin_[b + 1] = sc.body_begin_[b] + count;
  }
  sc.body_items_.resize(sc.body_begin_[nb]);
  parallel_items(nb, [&](std::size_t b) {
    std::size_t out = sc.body_begin_[b];
    for (int s = body_first_sphere_[b]; s < body_first_sphere_[b + 1]; ++s) {
      for (std::size_t d = sc.down_begin_[s]; d < sc.down_begin_[s + 1]; ++d)
        sc.body_items_[out++] = 2 * static_cast<std::uint64_t>(sc.down_[d]) + 1;  // holds j: +f
      for (std::size_t k = sc.cand_begin_[s]; k < sc.cand_begin_[s + 1]; ++k)
        sc.body_items_[out++] = 2 * static_cast<std::uint64_t>(k);  // holds i: −f
    }
    // One sphere: (i', s) with i' < s precede (s, j), already in order. A clump: sort.
    if (body_first_sphere_[b + 1] - body_first_sphere_[b] > 1)
      std::sort(sc.body_items_.begin() + static_cast<std::ptrdiff_t>(sc.body_begin_[b]),
                sc.body_items_.begin() + static_cast<std::ptrdiff_t>(sc.body_begin_[b + 1]));
  });
  sc.slot_out_.assign(m, SlotOut{Vec3::Zero(), Vec3::Zero()});
  sc.slot_force_.resize(m);
  sc.slot_geometry_.resize(m);
  sc.slot_active_.assign(m, 0);
  sc.slot_damping_.resize(m);
  sc.damping_valid_ = false;
}

// The dashpot of every candidate pair from the bodies' current (packed) masses.
void World::update_damping() {
  StepCache& sc = cache_.get();
  const ContactParams& p = options_.contact;
  parallel_items(candidates_.size(), [&](std::size_t k) {
    const double ma = sc.kinematics_[sphere_body_[candidates_[k].first]].mass;
    const double mb = sc.kinematics_[sphere_body_[candidates_[k].second]].mass;
    sc.slot_damping_[k] = normal_dashpot(ma * mb / (ma + mb), p);
  });
  sc.damping_valid_ = true;
}

// bodies_ -> packed state, at the start of step(count): the caller may have edited anything.
void World::load_bodies() {
  StepCache& sc = cache_.get();
  const std::size_t nb = bodies_.size();
  sc.kinematics_.resize(nb);
  sc.body_wrench_.resize(nb);
  sc.rotation_.resize(nb);
  sc.body_touched_.assign(nb, 0);
  parallel_items(nb, [&](std::size_t k) {
    const Body& b = bodies_[k];
    sc.kinematics_[k] = Kinematics{b.position, b.velocity, b.angular_velocity, b.mass};
    sc.body_wrench_[k] = Wrench{b.force, b.torque};
    Spin spin = Spin::general;
    if (b.rotation_locked)
      spin = Spin::locked;
    else if (b.moments.x() == b.moments.y() && b.moments.y() == b.moments.z())
      spin = b.spheres.size() == 1 && b.spheres[0].center.isZero(0.0) ? Spin::plain_sphere
                                                                      : Spin::isotropic;
    sc.rotation_[k] = Rotation{b.orientation, b.moments, spin};
  });
  sc.damping_valid_ = false;  // masses may have changed
}

// Packed state -> bodies_, at the end of step(count).
void World::store_bodies() {
  StepCache& sc = cache_.get();
  parallel_items(bodies_.size(), [&](std::size_t k) {
    Body& b = bodies_[k];
    b.position = sc.kinematics_[k].position;
    b.velocity = sc.kinematics_[k].velocity;
    b.angular_velocity = sc.kinematics_[k].angular_velocity;
    b.orientation = sc.rotation_[k].orientation;
    b.force = sc.body_wrench_[k].force;
    b.torque = sc.body_wrench_[k].torque;
  });
}

void World::import_pairs() {
  StepCache& sc = cache_.get();
  const int n = sphere_count();
  parallel_items(contacts_.size(), [&](std::size_t c) {
    const PairContact& pc = contacts_[c];
    if (pc.i < 0 || pc.i >= n) return;
    const auto first = candidates_.begin() + static_cast<std::ptrdiff_t>(sc.cand_begin_[pc.i]);
    const auto last = candidates_.begin() + static_cast<std::ptrdiff_t>(sc.cand_begin_[pc.i + 1]);
    const auto it = std::lower_bound(first, last, std::make_pair(pc.i, pc.j));
    if (it == last || it->second != pc.j) return;  // no longer a candidate: history dropped
    const auto k = static_cast<std::size_t>(it - candidates_.begin());
    sc.slot_force_[k] = SlotForce{pc.state.shear, pc.state.normal_force};
    sc.slot_geometry_[k] = SlotGeometry{pc.state.normal, pc.state.point, pc.state.overlap};
    sc.slot_active_[k] = 1;
    // The wrenches are written by the next contact pass (every active slot is refreshed there).
  });
}

void World::export_pairs() {
  StepCache& sc = cache_.get();
  contacts_.clear();
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (!sc.slot_active_[k]) continue;
    PairContact& c = contacts_.emplace_back();
    c.i = candidates_[k].first;
    c.j = candidates_[k].second;
    const SlotGeometry& g = sc.slot_geometry_[k];
    c.state.normal = g.normal;
    c.state.point = g.point;
    c.state.overlap = g.overlap;
    c.state.normal_force = sc.slot_force_[k].normal_force;
    c.state.shear = sc.slot_force_[k].shear;
  }
}

// Wall candidates: (sphere, wall) pairs with a gap below the skin at the spheres' build positions.
// A sphere moves at most skin/2 before the next build and a wall at most skin/2 before
// walls_moved() asks for new candidates, so every touching pair is a candidate.
bool World::walls_moved() const {
  StepCache& sc = cache_.get();
  if (walls_.size() != sc.walls_at_build_.size()) return true;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& a = walls_[w];
    const Wall& b = sc.walls_at_build_[w];
    if (a.kind != b.kind || a.radius != b.radius || a.normal != b.normal) return true;
    if (a.kind == Wall::Kind::cylinder) {
      if (a.point.x() != b.point.x() || a.point.y() != b.point.y()) return true;
    } else if (!(std::abs((a.point - b.point).dot(a.normal)) <= 0.5 * options_.skin)) {
      return true;
    }
  }
  return false;
}

void World::build_wall_candidates() {
  StepCache& sc = cache_.get();
  const std::size_t n = sphere_body_.size();
  const std::size_t nw = walls_.size();
  sc.walls_at_build_ = walls_;
  const double skin = options_.skin;
  auto candidate = [&](std::size_t s, std::size_t w) {
    const Wall& wall = walls_[w];
    const Vec3& x = sphere_at_build_[s];
    const double r = sphere_radius_[s];
    const double slack = 1e-9 * (skin + r) + 1e-12 * (x.norm() + wall.point.norm() + wall.radius);
    const WallHit hit = wall_hit(wall, x, r);
    return wall.kind == Wall::Kind::cylinder && !hit.touching && hit.overlap == 0.0
               ? true  // centre on the axis (no normal): keep it
               : hit.overlap > -(skin + slack);
  };
  sc.scratch_.assign(n + 1, 0);
  parallel_items(n, [&](std::size_t s) {
    std::size_t count = 0;
    for (std::size_t w = 0; w < nw; ++w) count += candidate(s, w) ? 1 : 0;
    sc.scratch_[s + 1] = count;
  });
  for (std::size_t s = 0; s < n; ++s) sc.scratch_[s + 1] += sc.scratch_[s];
  sc.wall_cand_.resize(sc.scratch_[n]);
  parallel_items(n, [&](std::size_t s) {
    std::size_t k = sc.scratch_[s];
    for (std::size_t w = 0; w < nw; ++w)
      if (candidate(s, w)) sc.wall_cand_[k++] = {static_cast<int>(s), static_cast<int>(w)};
  });
  const std::size_t nb = bodies_.size();
  sc.body_wall_begin_.resize(nb + 1);
  for (std::size_t b = 0; b <= nb; ++b) sc.body_wall_begin_[b] = sc.scratch_[body_first_sphere_[b]];
  sc.wall_slot_state_.resize(sc.wall_cand_.size());
  sc.wall_slot_active_.assign(sc.wall_cand_.size(), 0);
}

void World::import_walls() {
  StepCache& sc = cache_.get();
  parallel_items(wall_contacts_.size(), [&](std::size_t c) {
    const WallContact& wc = wall_contacts_[c];
    const auto it = std::lower_bound(sc.wall_cand_.begin(), sc.wall_cand_.end(),
                                     std::make_pair(wc.sphere, wc.wall));
    if (it == sc.wall_cand_.end() || *it != std::make_pair(wc.sphere, wc.wall)) return;
    const auto k = static_cast<std::size_t>(it - sc.wall_cand_.begin());
    sc.wall_slot_state_[k] = wc.state;
    sc.wall_slot_active_[k] = 1;
  });
}

void World::export_walls() {
  StepCache& sc = cache_.get();
  wall_contacts_.clear();
  for (std::size_t k = 0; k < sc.wall_cand_.size(); ++k) {
    if (!sc.wall_slot_active_[k]) continue;
    WallContact& c = wall_contacts_.emplace_back();
    c.sphere = sc.wall_cand_[k].first;
    c.wall = sc.wall_cand_[k].second;
    c.state = sc.wall_slot_state_[k];
  }
}

void World::compute_forces() {
  StepCache& sc = cache_.get();
  const double dt = options_.timestep;
  const ContactParams& p = options_.contact;
  if (!sc.damping_valid_) update_damping();

  // Pair contacts, one slot per candidate: a touching pair keeps its shear history when it
  // touched at the last step too, else it starts from a fresh state. Each touching pair writes
  // its force and contact point into its slot and marks both bodies touched; a pair that stops
  // touching zeroes its slot.
  const std::size_t ncand = candidates_.size();
  parallel_items(ncand, [&](std::size_t k) {
    // The partner j is far from i in memory for a mixed packing: fetch a few candidates ahead.
    constexpr std::size_t kAhead = 6;
    if (k + kAhead < ncand) {
      const int ahead = candidates_[k + kAhead].second;
      __builtin_prefetch(&sphere_world_[ahead]);
      __builtin_prefetch(&sc.kinematics_[sphere_body_[ahead]]);
    }
    const auto [i, j] = candidates_[k];
    auto release = [&] {
      if (!sc.slot_active_[k]) return;
      sc.slot_active_[k] = 0;
      sc.slot_out_[k] = SlotOut{Vec3::Zero(), Vec3::Zero()};
    };
    const Vec3 d = sphere_world_[j] - sphere_world_[i];
    const double touch = sphere_radius_[i] + sphere_radius_[j];
    const double d2 = d.squaredNorm();
    if (d2 > touch * touch * (1.0 + 1e-9)) return release();  // clearly apart: no square root
    const double dist = std::sqrt(d2);                        // = d.norm()
    const double delta = touch - dist;
    if (!(delta > 0.0)) return release();
    SlotForce& state = sc.slot_force_[k];
    if (!sc.slot_active_[k]) state = SlotForce{Vec3::Zero(), 0.0};
    sc.slot_active_[k] = 1;
    const Kinematics& a = sc.kinematics_[sphere_body_[i]];
    const Kinematics& b = sc.kinematics_[sphere_body_[j]];
    const Vec3 n = dist > 0.0 ? Vec3(d / dist) : Vec3(Vec3::UnitZ());
    const Vec3 point = sphere_world_[i] + (sphere_radius_[i] - 0.5 * delta) * n;
    const Vec3 va = point_velocity(a.velocity, a.angular_velocity, point, a.position);
    const Vec3 vb = point_velocity(b.velocity, b.angular_velocity, point, b.position);
    update_contact_force(state.shear, state.normal_force, n, delta, vb - va, sc.slot_damping_[k], p,
                         dt);
    if (sc.record_geometry_) sc.slot_geometry_[k] = SlotGeometry{n, point, delta};
    const Vec3 f = state.normal_force * n + state.shear;  // ContactState::force()
    // Body of j receives +f, body of i −f (sum_wrench forms the torques).
    sc.slot_out_[k] = SlotOut{f, point};
    // Several threads may mark the same body: relaxed atomic stores of the same value.
    __atomic_store_n(&sc.body_touched_[sphere_body_[i]], std::uint8_t{1}, __ATOMIC_RELAXED);
    __atomic_store_n(&sc.body_touched_[sphere_body_[j]], std::uint8_t{1}, __ATOMIC_RELAXED);
  });

  // Wall contacts, one slot per wall candidate, likewise.
  parallel_items(sc.wall_cand_.size(), [&](std::size_t k) {
    const auto [s, w] = sc.wall_cand_[k];
    const WallHit hit = wall_hit(walls_[w], sphere_world_[s], sphere_radius_[s]);
    if (!hit.touching) {
      sc.wall_slot_active_[k] = 0;
      return;
    }
    ContactState& state = sc.wall_slot_state_[k];
    if (!sc.wall_slot_active_[k]) state = ContactState();
    sc.wall_slot_active_[k] = 1;
    const Kinematics& b = sc.kinematics_[sphere_body_[s]];
    const Vec3 vb = b.velocity + b.angular_velocity.cross(hit.point - b.position);
    const Vec3 vw = walls_[w].kind == Wall::Kind::plane ? walls_[w].velocity : Vec3::Zero();
    update_contact(state, hit.normal, hit.overlap, hit.point, vb - vw, b.mass, p, dt);
  });

  // The sums per body are made by integrate(), in the same pass that advances the body.
}

// Net wrench on body k: gravity, then its pair contacts in (i, j) order, then its wall contacts
// in (sphere, wall) order — a fixed order, whatever the thread count (see sc.body_touched_).
static inline Wrench sum_wrench(const StepCache& sc, const Vec3& gravity, std::size_t k) {
  const Kinematics& b = sc.kinematics_[k];
  Vec3 force = b.mass * gravity;
  Vec3 torque = Vec3::Zero();
  if (sc.body_touched_[k]) {
    for (std::size_t e = sc.body_begin_[k]; e < sc.body_begin_[k + 1]; ++e) {
      const std::uint64_t item = sc.body_items_[e];
      const SlotOut& out = sc.slot_out_[item >> 1];
      // ±1 times a value is its exact negation or itself, as the unary minus (branch free).
      const double sign = item & 1 ? 1.0 : -1.0;
      force += sign * out.force;
      torque += sign * moment(out.point, b.position, out.force);
    }
  }
  for (std::size_t c = sc.body_wall_begin_[k]; c < sc.body_wall_begin_[k + 1]; ++c) {
    if (!sc.wall_slot_active_[c]) continue;
    const ContactState& s = sc.wall_slot_state_[c];
    const Vec3 f = s.force();
    force += f;
    torque += (s.point - b.position).cross(f);
  }
  return Wrench{force, torque};
}

void World::integrate() {
  StepCache& sc = cache_.get();
  const double dt = options_.timestep;
  const double alpha = options_.contact.local_damping;
  const bool have_reference = !dirty_ && sphere_at_filter_.size() == sphere_world_.size();
  const double limit = near_limit_;
  std::atomic<bool> moved{false};
  // What every body shares: the leapfrog translation, the damped torque and, for an isotropic
  // body (a sphere), ω = L/I whatever the orientation (the midpoint passes below would all
  // return the same ω; evaluated directly, equal up to rounding).
  auto translate = [&](Kinematics& b, const Wrench& wrench) {
    const Vec3 f = alpha == 0.0 ? wrench.force : local_damping(wrench.force, b.velocity, alpha);
    b.velocity += f * (dt / b.mass);
    b.position += b.velocity * dt;
  };
  auto damped_torque = [&](const Kinematics& b, const Wrench& wrench) {
    return alpha == 0.0 ? wrench.torque : local_damping(wrench.torque, b.angular_velocity, alpha);
  };
  auto spin_isotropic = [&](Kinematics& b, const Vec3& t, const Rotation& r) {
    const double inertia = r.moments.x();
    b.angular_velocity = (inertia * b.angular_velocity + t * dt) / inertia;
  };
  // Every body but a plain sphere (kept out of line so the loop below stays small).
  auto advance = [&](Kinematics & b, const Wrench& wrench, Rotation& r) __attribute__((noinline)) {
    translate(b, wrench);
    if (r.spin == Spin::locked) return;
    const Vec3 t = damped_torque(b, wrench);
    const Eigen::Quaterniond q0 = r.orientation;
    if (r.spin == Spin::isotropic) {
      spin_isotropic(b, t, r);
      r.orientation = (rotation_quaternion(dt * b.angular_velocity) * q0).normalized();
      return;
    }
    const Vec3 momentum = angular_momentum(r.moments, q0, b.angular_velocity) + t * dt;
    // Explicit midpoint for dq/dt = ½ ω ⊗ q with ω = ω(q, L) and L constant over the step.
    Vec3 omega = angular_velocity_for(r.moments, momentum, q0);
    for (int pass = 0; pass < 3; ++pass) {
      const Eigen::Quaterniond half = (rotation_quaternion(0.5 * dt * omega) * q0).normalized();
      omega = angular_velocity_for(r.moments, momentum, half);
    }
    r.orientation = (rotation_quaternion(dt * omega) * q0).normalized();
    b.angular_velocity = angular_velocity_for(r.moments, momentum, r.orientation);
  };
  // One pass per body: sum its wrench, advance it, then refresh its spheres' world positions
  // and the Verlet-skin check, so a step makes one pass over the bodies and their spheres.
  parallel_items(bodies_.size(), [&](std::size_t k) {
    const Wrench wrench = sum_wrench(sc, options_.gravity, k);
    sc.body_touched_[k] = 0;  // for the next step's contact pass
    sc.body_wrench_[k] = wrench;
    Kinematics& b = sc.kinematics_[k];
    Rotation& r = sc.rotation_[k];
    bool far = false;
    const int first = body_first_sphere_[k], last = body_first_sphere_[k + 1];
    if (r.spin == Spin::plain_sphere) {
      // A plain sphere centred on its body origin looks the same in every orientation, so its
      // orientation is not integrated (as LAMMPS nve/sphere): no sine, cosine or normalisation.
      translate(b, wrench);
      spin_isotropic(b, damped_torque(b, wrench), r);
      const Vec3 x = b.position + Vec3::Zero();  // the general formula's bits for a centred sphere
      sphere_world_[first] = x;
      far = have_reference && (x - sphere_at_filter_[first]).squaredNorm() > limit;
    } else {
      advance(b, wrench, r);
      for (int i = first; i < last; ++i) {
        const Vec3& local = sphere_local_[i];
        // q·0 is exactly +0 (Eigen's formula), so a centred sphere skips it.
        const Vec3 x = local.isZero(0.0) ? Vec3(b.position + Vec3::Zero())
                                         : Vec3(b.position + r.orientation * local);
        sphere_world_[i] = x;
        if (have_reference && (x - sphere_at_filter_[i]).squaredNorm() > limit) far = true;
      }
    }
    if (far) moved.store(true, std::memory_order_relaxed);
  });
  sc.positions_fresh_ = true;
  sc.moved_ = !have_reference || moved.load();
  for (Wall& w : walls_)
    if (w.kind == Wall::Kind::plane) w.point += w.velocity * dt;
}

void World::step(int count) {
  StepCache& sc = cache_.get();
  // Bodies may have been edited since the last call: refresh everything derived from them once.
  load_bodies();
  sc.positions_fresh_ = false;
  for (int s = 0; s < count; ++s) {
    bool walls_stale = !sc.walls_valid_;
    const bool moved = sc.positions_fresh_ ? sc.moved_ : update_positions_and_check();
    if (moved || !near_valid_) {
      // New candidates: the history travels through contacts_ (and wall_contacts_ after a build).
      if (sc.pairs_valid_) export_pairs();
      sc.pairs_valid_ = false;
      if (moved && refresh_neighbours()) {
        if (sc.walls_valid_) export_walls();
        sc.walls_valid_ = false;
        walls_stale = true;
      }
      filter_candidates();
    }
    if (!sc.pairs_valid_) {
      derive_pair_index();
      import_pairs();
      sc.pairs_valid_ = true;
    }
    if (walls_stale || walls_moved()) {
      if (sc.walls_valid_) export_walls();
      build_wall_candidates();
      import_walls();
      sc.walls_valid_ = true;
    }
    // Contacts report their geometry as of the last step; earlier steps need not write it.
    sc.record_geometry_ = s + 1 == count;
    compute_forces();
    integrate();
    time_ += options_.timestep;
    ++steps_;
  }
  store_bodies();
  if (sc.pairs_valid_) export_pairs();
  if (sc.walls_valid_) export_walls();
  if (!sc.positions_fresh_) update_sphere_positions();  // integrate() already set them otherwise
}

World::ListState World::list_state() const {
  ListState s;
  s.steps = steps_;
  s.time = time_;
  s.builds = builds_;
  s.filters = filters_;
  s.stale = dirty_;
  s.build_positions = sphere_at_build_;
  s.skin_pairs = neighbours_;
  s.filter_positions = sphere_at_filter_;
  s.near_limit = near_limit_;
  return s;
}

void World::restore(ListState lists, std::vector<PairContact> contacts,
                    std::vector<WallContact> wall_contacts) {
  const int n = sphere_count();
  const int nw = static_cast<int>(walls_.size());
  auto positions = [&](const std::vector<Vec3>& x, const char* what) {
    if (!x.empty() && x.size() != static_cast<std::size_t>(n))
      throw InvalidInput(std::string("DEM world: ") + what + " positions for " +
                         std::to_string(x.size()) + " spheres, the world has " + std::to_string(n));
  };
  positions(lists.build_positions, "neighbour-list");
  positions(lists.filter_positions, "near-list");
  auto pair_ok = [&](int i, int j) { return i >= 0 && j > i && j < n; };
  for (const auto& [i, j] : lists.skin_pairs)
    if (!pair_ok(i, j)) throw InvalidInput("DEM world: neighbour pair outside the world");
  for (const PairContact& c : contacts)
    if (!pair_ok(c.i, c.j)) throw InvalidInput("DEM world: contact between unknown spheres");
  for (const WallContact& c : wall_contacts)
    if (c.sphere < 0 || c.sphere >= n || c.wall < 0 || c.wall >= nw)
      throw InvalidInput("DEM world: wall contact of an unknown sphere or wall");
  if (!(lists.near_limit >= 0.0)) throw InvalidInput("DEM world: negative near-list limit");
  steps_ = lists.steps;
  time_ = lists.time;
  builds_ = lists.builds;
  filters_ = lists.filters;
  dirty_ = lists.stale;
  sphere_at_build_ = std::move(lists.build_positions);
  neighbours_ = std::move(lists.skin_pairs);
  sphere_at_filter_ = std::move(lists.filter_positions);
  near_limit_ = lists.near_limit;
  near_valid_ = false;  // filtered from the restored lists at the next step
  contacts_ = std::move(contacts);
  wall_contacts_ = std::move(wall_contacts);
  StepCache& sc = cache_.get();
  sc.pairs_valid_ = sc.walls_valid_ = false;
  update_sphere_positions();
}

void World::rescale_friction(double new_friction) {
  StepCache& sc = cache_.get();
  if (!(new_friction >= 0.0) || !std::isfinite(new_friction))
    throw InvalidInput("DEM world: friction must be non-negative, got " +
                       std::to_string(new_friction));
  options_.contact.friction = new_friction;
  for (PairContact& c : contacts_) dem::rescale_friction(c.state, new_friction);
  for (WallContact& c : wall_contacts_) dem::rescale_friction(c.state, new_friction);
  sc.pairs_valid_ = sc.walls_valid_ = false;  // the slots take the new states from the lists
}

double kinetic_energy(const World& world) {
  double e = 0.0;
  for (const Body& b : world.bodies()) e += b.kinetic_energy();
  return e;
}

double mean_unbalanced_force_ratio(const World& world) {
  double unbalanced = 0.0;
  for (const Body& b : world.bodies()) unbalanced += b.force.norm();
  double contact = 0.0;
  std::size_t n = 0;
  for (const PairContact& c : world.contacts()) contact += c.state.force().norm(), ++n;
  for (const WallContact& c : world.wall_contacts()) contact += c.state.force().norm(), ++n;
  if (world.bodies().empty() || unbalanced == 0.0) return 0.0;
  if (n == 0 || contact == 0.0) return std::numeric_limits<double>::infinity();
  return (unbalanced / static_cast<double>(world.bodies().size())) /
         (contact / static_cast<double>(n));
}

}  // namespace clumpkit::dem
