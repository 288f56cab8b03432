// Integration of dem::World: the packed body state, each body's wrench summed in a fixed order,
// and the step of every body (dem/core/integrator.h) with its spheres' positions and the skin
// check.
#include "dem/core/integrator.h"
#include "dem/core/parallel.h"
#include "dem/core/world.h"
#include "dem/core/world_step_cache.h"

#include <atomic>
#include <cmath>

namespace clumpkit::dem {

using namespace detail;

// bodies_ -> packed state, at the start of step(count): the caller may have edited anything.
void World::load_bodies() {
  StepCache& sc = cache_.get();
  const std::size_t nb = bodies_.size();
  sc.kinematics_.resize(nb);
  sc.turning_.resize(nb);
  sc.pair_wrench_.resize(nb);
  sc.body_diameter_.resize(nb);
  sc.body_has_vertices_.assign(nb, 0);
  sc.any_vertices_ = false;
  for (std::size_t k = 0; k < nb; ++k) {
    sc.body_has_vertices_[k] = !bodies_[k].vertices.empty();
    sc.any_vertices_ = sc.any_vertices_ || sc.body_has_vertices_[k];
  }
  // Corner wrenches only where corners exist (a world of spheres keeps none).
  sc.vertex_wrench_.assign(sc.any_vertices_ ? nb : 0, Wrench{Vec3::Zero(), Vec3::Zero()});
  // Each body's bonds in index order (counting sort), and which bodies have any: made again only
  // when bodies or bonds were added or renumbered (element tests step one step a call).
  if (!sc.index_valid_) {
    sc.body_bond_begin_.assign(nb + 1, 0);
    for (const Bond& bond : bonds_)
      ++sc.body_bond_begin_[bond.a + 1], ++sc.body_bond_begin_[bond.b + 1];
    for (std::size_t k = 0; k < nb; ++k) sc.body_bond_begin_[k + 1] += sc.body_bond_begin_[k];
    sc.body_bond_items_.resize(sc.body_bond_begin_[nb]);
    std::vector<std::size_t> at(sc.body_bond_begin_.begin(), sc.body_bond_begin_.end() - 1);
    for (std::size_t i = 0; i < bonds_.size(); ++i) {
      sc.body_bond_items_[at[bonds_[i].a]++] = 2 * i;
      sc.body_bond_items_[at[bonds_[i].b]++] = 2 * i + 1;
    }
    sc.sphere_body64_.assign(sphere_body_.begin(), sphere_body_.end());
    sc.index_valid_ = true;
  }
  parallel_items(nb, [&](std::size_t k) {
    const Body& b = bodies_[k];
    sc.body_diameter_[k] = b.diameter;
    sc.kinematics_[k] = Kinematics{b.position, b.velocity, b.angular_velocity, b.mass};
    sc.pair_wrench_[k] = Wrench{b.mass * options_.gravity, Vec3::Zero()};
    Spin spin = Spin::general;
    if (b.rotation_locked)
      spin = Spin::locked;
    else if (b.moments.x() == b.moments.y() && b.moments.y() == b.moments.z())
      spin = b.spheres.size() == 1 && b.spheres[0].center.isZero(0.0) &&
                     sc.body_bond_begin_[k] == sc.body_bond_begin_[k + 1]
                 ? Spin::plain_sphere
                 : Spin::isotropic;
    sc.turning_[k] = Turning{spin, 0, b.moments.x()};
  });
  std::uint32_t rotating = 0;
  for (Turning& t : sc.turning_)
    if (t.spin != Spin::plain_sphere) t.rotation = rotating++;
  sc.rotation_.resize(rotating);
  sc.bond_matrix_.resize(bonds_.empty() ? 0 : nb);
  parallel_items(nb, [&](std::size_t k) {
    const Turning& t = sc.turning_[k];
    // A plain sphere has no bonds (Spin::plain_sphere), so its matrix is never read.
    if (t.spin == Spin::plain_sphere) return;
    sc.rotation_[t.rotation] = Rotation{bodies_[k].orientation, bodies_[k].moments};
    if (!sc.bond_matrix_.empty()) sc.bond_matrix_[k] = bodies_[k].orientation.toRotationMatrix();
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
    const Turning& t = sc.turning_[k];  // a plain sphere keeps the orientation it was given
    if (t.spin != Spin::plain_sphere) b.orientation = sc.rotation_[t.rotation].orientation;
  });
}

const Eigen::Quaterniond& World::orientation_in_step(std::size_t body) const {
  const StepCache& sc = cache_.get();
  const Turning& t = sc.turning_[body];
  return t.spin == Spin::plain_sphere ? bodies_[body].orientation
                                      : sc.rotation_[t.rotation].orientation;
}

// Net wrench on body k: gravity and its pair contacts as the contact pass added them
// (StepCache::pair_wrench_), then its deferred pair contacts in candidate order, its wall
// contacts in (sphere, wall) order, its corners on walls, its bonds in index order — a fixed
// order, whatever the thread count.
static inline Wrench sum_wrench(const StepCache& sc, std::size_t k) {
  const Kinematics& b = sc.kinematics_[k];
  Vec3 force = sc.pair_wrench_[k].force;
  Vec3 torque = sc.pair_wrench_[k].torque;
  for (std::size_t e = sc.body_deferred_begin_[k]; e < sc.body_deferred_begin_[k + 1]; ++e) {
    const std::uint32_t d = sc.body_deferred_items_[e];
    if (!sc.slot_active_[sc.deferred_cand_[d]]) continue;
    force += sc.deferred_wrench_[d].force;
    torque += sc.deferred_wrench_[d].torque;
  }
  for (std::size_t c = sc.body_wall_begin_[k]; c < sc.body_wall_begin_[k + 1]; ++c) {
    if (!sc.wall_slot_active_[c]) continue;
    const ContactState& s = sc.wall_slot_state_[c];
    const Vec3 f = s.force();
    force += f;
    torque += (s.point - b.position).cross(f);
  }
  if (sc.body_has_vertices_[k]) {
    force += sc.vertex_wrench_[k].force;
    torque += sc.vertex_wrench_[k].torque;
  }
  for (std::size_t e = sc.body_bond_begin_[k]; e < sc.body_bond_begin_[k + 1]; ++e) {
    const std::uint64_t item = sc.body_bond_items_[e];
    const BondWrench& w = sc.bond_wrench_[item >> 1];
    force += item & 1 ? w.force_b : w.force_a;
    torque += item & 1 ? w.torque_b : w.torque_a;
  }
  return Wrench{force, torque};
}

void World::integrate() {
  StepCache& sc = cache_.get();
  const double dt = options_.timestep;
  const double alpha = options_.contact.local_damping;
  const Vec3 gravity = options_.gravity;
  // On the last step of step(count): Body::force and torque are written, and sphere_world_ keeps
  // the positions of this step's contact pass for the contact lists (World::contacts); the next
  // call computes the spheres' positions from the bodies anyway.
  const bool last_step = sc.last_step_;
  const bool have_reference = !dirty_ && sphere_at_filter_.size() == sphere_world_.size();
  const double limit = near_limit_;
  std::atomic<bool> moved{false};
  // What every body shares: the leapfrog translation and the damped torque (dem/core/integrator.h
  // holds the integration itself).
  auto translate = [&](Kinematics& b, const Wrench& wrench) {
    const Vec3 f = alpha == 0.0 ? wrench.force : local_damping(wrench.force, b.velocity, alpha);
    leapfrog_translate(b.position, b.velocity, f, b.mass, dt);
  };
  auto damped_torque = [&](const Kinematics& b, const Wrench& wrench) {
    return alpha == 0.0 ? wrench.torque : local_damping(wrench.torque, b.angular_velocity, alpha);
  };
  // Every body but a plain sphere (kept out of line so the loop below stays small).
  auto advance = [&](Kinematics & b, const Wrench& wrench, Spin spin, Rotation& r)
      __attribute__((noinline)) {
    translate(b, wrench);
    if (spin == Spin::locked) return;
    rotate_rigid_body(r.orientation, b.angular_velocity, r.moments, damped_torque(b, wrench), dt,
                      spin == Spin::isotropic);
  };
  // One pass per body: sum its wrench, advance it, then refresh its spheres' world positions
  // and the Verlet-skin check, so a step makes one pass over the bodies and their spheres.
  parallel_items(bodies_.size(), [&](std::size_t k) {
    const Wrench wrench = sum_wrench(sc, k);
    if (last_step) {
      bodies_[k].force = wrench.force;
      bodies_[k].torque = wrench.torque;
    }
    Kinematics& b = sc.kinematics_[k];
    sc.pair_wrench_[k] = Wrench{b.mass * gravity, Vec3::Zero()};  // the next contact pass's start
    const Turning t = sc.turning_[k];
    bool far = false;
    const int first = body_first_sphere_[k], last = body_first_sphere_[k + 1];
    if (t.spin == Spin::plain_sphere) {
      // A plain sphere centred on its body origin looks the same in every orientation, so its
      // orientation is not integrated (as LAMMPS nve/sphere): no sine, cosine or normalisation.
      translate(b, wrench);
      spin_isotropic(b.angular_velocity, damped_torque(b, wrench), t.moment, dt);
      if (!last_step) {
        const Vec3 x = b.position + Vec3::Zero();  // the general formula's bits: centred sphere
        sphere_world_[first] = x;
        far = have_reference && (x - sphere_at_filter_[first]).squaredNorm() > limit;
      }
    } else {
      Rotation& r = sc.rotation_[t.rotation];
      advance(b, wrench, t.spin, r);
      if (!sc.bond_matrix_.empty()) sc.bond_matrix_[k] = r.orientation.toRotationMatrix();
      for (int i = first; i < last && !last_step; ++i) {
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
  sc.positions_fresh_ = !last_step;
  sc.moved_ = !have_reference || moved.load();
  for (Wall& w : walls_) {
    if (w.kind != Wall::Kind::cylinder)
      w.point += w.velocity * dt;
    else if (w.radial_velocity != 0.0)
      w.radius += w.radial_velocity * dt;
  }
}

}  // namespace clumpkit::dem
