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
  pairs_valid_ = walls_valid_ = false;
  return index;
}

int World::add_wall(const Wall& wall) {
  walls_.push_back(wall);
  walls_valid_ = false;
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
  ++builds_;
  dirty_ = false;
  sphere_at_build_ = sphere_world_;
  find_skin_pairs(sphere_world_, sphere_radius_, sphere_body_, options_.skin, grid_, neighbours_);
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
  ++filters_;
  filter_pairs(neighbours_, sphere_at_filter_, sphere_radius_,
               options_.near_skin_fraction * options_.skin, filter_keep_, candidates_);
  near_valid_ = true;
}

// Index of the candidate list: per sphere its candidates as i (a range of candidates_) and as j
// (down_), per body every candidate it takes part in, in candidate order — the order in which
// the serial sum of the reference implementation added them — and empty slots.
void World::derive_pair_index() {
  const std::size_t n = sphere_body_.size();
  const std::size_t m = candidates_.size();
  cand_begin_.assign(n + 1, 0);
  down_begin_.assign(n + 1, 0);
  for (const auto& [i, j] : candidates_) ++cand_begin_[i + 1], ++down_begin_[j + 1];
  for (std::size_t s = 0; s < n; ++s) {
    cand_begin_[s + 1] += cand_begin_[s];
    down_begin_[s + 1] += down_begin_[s];
  }
  down_.resize(m);
  scratch_.assign(down_begin_.begin(), down_begin_.end() - 1);
  for (std::size_t k = 0; k < m; ++k) down_[scratch_[candidates_[k].second]++] = k;

  const std::size_t nb = bodies_.size();
  body_begin_.assign(nb + 1, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    std::size_t count = 0;
    for (int s = body_first_sphere_[b]; s < body_first_sphere_[b + 1]; ++s)
      count += (cand_begin_[s + 1] - cand_begin_[s]) + (down_begin_[s + 1] - down_begin_[s]);
    body_begin_[b + 1] = body_begin_[b] + count;
  }
  body_items_.resize(body_begin_[nb]);
  parallel_items(nb, [&](std::size_t b) {
    std::size_t out = body_begin_[b];
    for (int s = body_first_sphere_[b]; s < body_first_sphere_[b + 1]; ++s) {
      for (std::size_t d = down_begin_[s]; d < down_begin_[s + 1]; ++d)
        body_items_[out++] = 2 * static_cast<std::uint64_t>(down_[d]) + 1;  // holds j: +f
      for (std::size_t k = cand_begin_[s]; k < cand_begin_[s + 1]; ++k)
        body_items_[out++] = 2 * static_cast<std::uint64_t>(k);  // holds i: −f
    }
    // One sphere: (i', s) with i' < s precede (s, j), already in order. A clump: sort.
    if (body_first_sphere_[b + 1] - body_first_sphere_[b] > 1)
      std::sort(body_items_.begin() + static_cast<std::ptrdiff_t>(body_begin_[b]),
                body_items_.begin() + static_cast<std::ptrdiff_t>(body_begin_[b + 1]));
  });
  slot_out_.assign(m, SlotOut{Vec3::Zero(), Vec3::Zero()});
  slot_force_.resize(m);
  slot_geometry_.resize(m);
  slot_active_.assign(m, 0);
  slot_damping_.resize(m);
  damping_valid_ = false;
}

// The dashpot of every candidate pair from the bodies' current (packed) masses.
void World::update_damping() {
  const ContactParams& p = options_.contact;
  parallel_items(candidates_.size(), [&](std::size_t k) {
    const double ma = kinematics_[sphere_body_[candidates_[k].first]].mass;
    const double mb = kinematics_[sphere_body_[candidates_[k].second]].mass;
    slot_damping_[k] = normal_dashpot(ma * mb / (ma + mb), p);
  });
  damping_valid_ = true;
}

// bodies_ -> packed state, at the start of step(count): the caller may have edited anything.
void World::load_bodies() {
  const std::size_t nb = bodies_.size();
  kinematics_.resize(nb);
  body_wrench_.resize(nb);
  rotation_.resize(nb);
  body_touched_.assign(nb, 0);
  parallel_items(nb, [&](std::size_t k) {
    const Body& b = bodies_[k];
    kinematics_[k] = Kinematics{b.position, b.velocity, b.angular_velocity, b.mass};
    body_wrench_[k] = Wrench{b.force, b.torque};
    Spin spin = Spin::general;
    if (b.rotation_locked)
      spin = Spin::locked;
    else if (b.moments.x() == b.moments.y() && b.moments.y() == b.moments.z())
      spin = b.spheres.size() == 1 && b.spheres[0].center.isZero(0.0) ? Spin::plain_sphere
                                                                      : Spin::isotropic;
    rotation_[k] = Rotation{b.orientation, b.moments, spin};
  });
  damping_valid_ = false;  // masses may have changed
}

// Packed state -> bodies_, at the end of step(count).
void World::store_bodies() {
  parallel_items(bodies_.size(), [&](std::size_t k) {
    Body& b = bodies_[k];
    b.position = kinematics_[k].position;
    b.velocity = kinematics_[k].velocity;
    b.angular_velocity = kinematics_[k].angular_velocity;
    b.orientation = rotation_[k].orientation;
    b.force = body_wrench_[k].force;
    b.torque = body_wrench_[k].torque;
  });
}

void World::import_pairs() {
  const int n = sphere_count();
  parallel_items(contacts_.size(), [&](std::size_t c) {
    const PairContact& pc = contacts_[c];
    if (pc.i < 0 || pc.i >= n) return;
    const auto first = candidates_.begin() + static_cast<std::ptrdiff_t>(cand_begin_[pc.i]);
    const auto last = candidates_.begin() + static_cast<std::ptrdiff_t>(cand_begin_[pc.i + 1]);
    const auto it = std::lower_bound(first, last, std::make_pair(pc.i, pc.j));
    if (it == last || it->second != pc.j) return;  // no longer a candidate: history dropped
    const auto k = static_cast<std::size_t>(it - candidates_.begin());
    slot_force_[k] = SlotForce{pc.state.shear, pc.state.normal_force};
    slot_geometry_[k] = SlotGeometry{pc.state.normal, pc.state.point, pc.state.overlap};
    slot_active_[k] = 1;
    // The wrenches are written by the next contact pass (every active slot is refreshed there).
  });
}

void World::export_pairs() {
  contacts_.clear();
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (!slot_active_[k]) continue;
    PairContact& c = contacts_.emplace_back();
    c.i = candidates_[k].first;
    c.j = candidates_[k].second;
    const SlotGeometry& g = slot_geometry_[k];
    c.state.normal = g.normal;
    c.state.point = g.point;
    c.state.overlap = g.overlap;
    c.state.normal_force = slot_force_[k].normal_force;
    c.state.shear = slot_force_[k].shear;
  }
}

// Wall candidates: (sphere, wall) pairs with a gap below the skin at the spheres' build positions.
// A sphere moves at most skin/2 before the next build and a wall at most skin/2 before
// walls_moved() asks for new candidates, so every touching pair is a candidate.
bool World::walls_moved() const {
  if (walls_.size() != walls_at_build_.size()) return true;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& a = walls_[w];
    const Wall& b = walls_at_build_[w];
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
  const std::size_t n = sphere_body_.size();
  const std::size_t nw = walls_.size();
  walls_at_build_ = walls_;
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
  scratch_.assign(n + 1, 0);
  parallel_items(n, [&](std::size_t s) {
    std::size_t count = 0;
    for (std::size_t w = 0; w < nw; ++w) count += candidate(s, w) ? 1 : 0;
    scratch_[s + 1] = count;
  });
  for (std::size_t s = 0; s < n; ++s) scratch_[s + 1] += scratch_[s];
  wall_cand_.resize(scratch_[n]);
  parallel_items(n, [&](std::size_t s) {
    std::size_t k = scratch_[s];
    for (std::size_t w = 0; w < nw; ++w)
      if (candidate(s, w)) wall_cand_[k++] = {static_cast<int>(s), static_cast<int>(w)};
  });
  const std::size_t nb = bodies_.size();
  body_wall_begin_.resize(nb + 1);
  for (std::size_t b = 0; b <= nb; ++b) body_wall_begin_[b] = scratch_[body_first_sphere_[b]];
  wall_slot_state_.resize(wall_cand_.size());
  wall_slot_active_.assign(wall_cand_.size(), 0);
}

void World::import_walls() {
  parallel_items(wall_contacts_.size(), [&](std::size_t c) {
    const WallContact& wc = wall_contacts_[c];
    const auto it =
        std::lower_bound(wall_cand_.begin(), wall_cand_.end(), std::make_pair(wc.sphere, wc.wall));
    if (it == wall_cand_.end() || *it != std::make_pair(wc.sphere, wc.wall)) return;
    const auto k = static_cast<std::size_t>(it - wall_cand_.begin());
    wall_slot_state_[k] = wc.state;
    wall_slot_active_[k] = 1;
  });
}

void World::export_walls() {
  wall_contacts_.clear();
  for (std::size_t k = 0; k < wall_cand_.size(); ++k) {
    if (!wall_slot_active_[k]) continue;
    WallContact& c = wall_contacts_.emplace_back();
    c.sphere = wall_cand_[k].first;
    c.wall = wall_cand_[k].second;
    c.state = wall_slot_state_[k];
  }
}

void World::compute_forces() {
  const double dt = options_.timestep;
  const ContactParams& p = options_.contact;
  if (!damping_valid_) update_damping();

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
      __builtin_prefetch(&kinematics_[sphere_body_[ahead]]);
    }
    const auto [i, j] = candidates_[k];
    auto release = [&] {
      if (!slot_active_[k]) return;
      slot_active_[k] = 0;
      slot_out_[k] = SlotOut{Vec3::Zero(), Vec3::Zero()};
    };
    const Vec3 d = sphere_world_[j] - sphere_world_[i];
    const double touch = sphere_radius_[i] + sphere_radius_[j];
    const double d2 = d.squaredNorm();
    if (d2 > touch * touch * (1.0 + 1e-9)) return release();  // clearly apart: no square root
    const double dist = std::sqrt(d2);                        // = d.norm()
    const double delta = touch - dist;
    if (!(delta > 0.0)) return release();
    SlotForce& state = slot_force_[k];
    if (!slot_active_[k]) state = SlotForce{Vec3::Zero(), 0.0};
    slot_active_[k] = 1;
    const Kinematics& a = kinematics_[sphere_body_[i]];
    const Kinematics& b = kinematics_[sphere_body_[j]];
    const Vec3 n = dist > 0.0 ? Vec3(d / dist) : Vec3(Vec3::UnitZ());
    const Vec3 point = sphere_world_[i] + (sphere_radius_[i] - 0.5 * delta) * n;
    const Vec3 va = point_velocity(a.velocity, a.angular_velocity, point, a.position);
    const Vec3 vb = point_velocity(b.velocity, b.angular_velocity, point, b.position);
    update_contact_force(state.shear, state.normal_force, n, delta, vb - va, slot_damping_[k], p,
                         dt);
    if (record_geometry_) slot_geometry_[k] = SlotGeometry{n, point, delta};
    const Vec3 f = state.normal_force * n + state.shear;  // ContactState::force()
    // Body of j receives +f, body of i −f (sum_wrench forms the torques).
    slot_out_[k] = SlotOut{f, point};
    // Several threads may mark the same body: relaxed atomic stores of the same value.
    __atomic_store_n(&body_touched_[sphere_body_[i]], std::uint8_t{1}, __ATOMIC_RELAXED);
    __atomic_store_n(&body_touched_[sphere_body_[j]], std::uint8_t{1}, __ATOMIC_RELAXED);
  });

  // Wall contacts, one slot per wall candidate, likewise.
  parallel_items(wall_cand_.size(), [&](std::size_t k) {
    const auto [s, w] = wall_cand_[k];
    const WallHit hit = wall_hit(walls_[w], sphere_world_[s], sphere_radius_[s]);
    if (!hit.touching) {
      wall_slot_active_[k] = 0;
      return;
    }
    ContactState& state = wall_slot_state_[k];
    if (!wall_slot_active_[k]) state = ContactState();
    wall_slot_active_[k] = 1;
    const Kinematics& b = kinematics_[sphere_body_[s]];
    const Vec3 vb = b.velocity + b.angular_velocity.cross(hit.point - b.position);
    const Vec3 vw = walls_[w].kind == Wall::Kind::plane ? walls_[w].velocity : Vec3::Zero();
    update_contact(state, hit.normal, hit.overlap, hit.point, vb - vw, b.mass, p, dt);
  });

  // The sums per body are made by integrate(), in the same pass that advances the body.
}

// Net wrench on body k: gravity, then its pair contacts in (i, j) order, then its wall contacts
// in (sphere, wall) order — a fixed order, whatever the thread count (see body_touched_).
inline World::Wrench World::sum_wrench(std::size_t k) const {
  const Kinematics& b = kinematics_[k];
  Vec3 force = b.mass * options_.gravity;
  Vec3 torque = Vec3::Zero();
  if (body_touched_[k]) {
    for (std::size_t e = body_begin_[k]; e < body_begin_[k + 1]; ++e) {
      const std::uint64_t item = body_items_[e];
      const SlotOut& out = slot_out_[item >> 1];
      // ±1 times a value is its exact negation or itself, as the unary minus (branch free).
      const double sign = item & 1 ? 1.0 : -1.0;
      force += sign * out.force;
      torque += sign * moment(out.point, b.position, out.force);
    }
  }
  for (std::size_t c = body_wall_begin_[k]; c < body_wall_begin_[k + 1]; ++c) {
    if (!wall_slot_active_[c]) continue;
    const ContactState& s = wall_slot_state_[c];
    const Vec3 f = s.force();
    force += f;
    torque += (s.point - b.position).cross(f);
  }
  return Wrench{force, torque};
}

void World::integrate() {
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
    const Wrench wrench = sum_wrench(k);
    body_touched_[k] = 0;  // for the next step's contact pass
    body_wrench_[k] = wrench;
    Kinematics& b = kinematics_[k];
    Rotation& r = rotation_[k];
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
  positions_fresh_ = true;
  moved_ = !have_reference || moved.load();
  for (Wall& w : walls_)
    if (w.kind == Wall::Kind::plane) w.point += w.velocity * dt;
}

void World::step(int count) {
  // Bodies may have been edited since the last call: refresh everything derived from them once.
  load_bodies();
  positions_fresh_ = false;
  for (int s = 0; s < count; ++s) {
    bool walls_stale = !walls_valid_;
    const bool moved = positions_fresh_ ? moved_ : update_positions_and_check();
    if (moved || !near_valid_) {
      // New candidates: the history travels through contacts_ (and wall_contacts_ after a build).
      if (pairs_valid_) export_pairs();
      pairs_valid_ = false;
      if (moved && refresh_neighbours()) {
        if (walls_valid_) export_walls();
        walls_valid_ = false;
        walls_stale = true;
      }
      filter_candidates();
    }
    if (!pairs_valid_) {
      derive_pair_index();
      import_pairs();
      pairs_valid_ = true;
    }
    if (walls_stale || walls_moved()) {
      if (walls_valid_) export_walls();
      build_wall_candidates();
      import_walls();
      walls_valid_ = true;
    }
    // Contacts report their geometry as of the last step; earlier steps need not write it.
    record_geometry_ = s + 1 == count;
    compute_forces();
    integrate();
    time_ += options_.timestep;
    ++steps_;
  }
  store_bodies();
  if (pairs_valid_) export_pairs();
  if (walls_valid_) export_walls();
  if (!positions_fresh_) update_sphere_positions();  // integrate() already set them otherwise
}

void World::rescale_friction(double new_friction) {
  if (!(new_friction >= 0.0) || !std::isfinite(new_friction))
    throw InvalidInput("DEM world: friction must be non-negative, got " +
                       std::to_string(new_friction));
  options_.contact.friction = new_friction;
  for (PairContact& c : contacts_) dem::rescale_friction(c.state, new_friction);
  for (WallContact& c : wall_contacts_) dem::rescale_friction(c.state, new_friction);
  pairs_valid_ = walls_valid_ = false;  // the slots take the new states from the lists
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

double critical_timestep(const World& world) {
  const ContactParams& p = world.options().contact;
  double dt = std::numeric_limits<double>::infinity();
  for (const Body& b : world.bodies()) {
    dt = std::min(dt, critical_timestep(b.mass, p.kn));
    if (!b.rotation_locked) {
      const double r = b.bounding_radius();
      dt = std::min(dt, critical_timestep(b.moments.minCoeff(), std::max(p.kn, p.ks) * r * r));
    }
  }
  return dt;
}

}  // namespace clumpkit::dem
