// The lean DEM world: bodies, walls, neighbour grid with Verlet skin, contacts with history,
// gravity and a deterministic leapfrog integrator with quaternion rotation.
#pragma once

#include "dem/body.h"
#include "dem/contact.h"
#include "dem/neighbour_search.h"
#include "dem/wall.h"

#include <cstdint>
#include <vector>

namespace clumpkit::dem {

/// World settings (SI).
struct WorldOptions {
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  ///< m/s²
  double timestep = 1e-5;                ///< s
  /// Verlet skin (m): candidate pairs are those closer than r_i + r_j + skin; the list is
  /// rebuilt once any sphere has moved more than skin/2 since the last build.
  double skin = 1e-3;
  /// Two-level Verlet list: the contact pass scans only the skin-list pairs closer than
  /// r_i + r_j + near_skin_fraction·skin, filtered again from the skin list (no grid search)
  /// once a sphere has moved near_skin_fraction·skin/2. In (0, 1]; 1 = one list. Like the skin,
  /// a performance setting only: results do not depend on it.
  double near_skin_fraction = 0.125;
  ContactParams contact;
};

/// A contact between sphere `i` and sphere `j` (global sphere indices, i < j, different bodies);
/// the normal points from i to j, so j receives state.force().
struct PairContact {
  int i = 0;
  int j = 0;
  ContactState state;
};

/// A contact between sphere `sphere` and wall `wall`; the normal points from the wall to the
/// sphere, which receives state.force().
struct WallContact {
  int sphere = 0;
  int wall = 0;
  ContactState state;
};

/// Deterministic DEM world. Each step (leapfrog, velocities at half steps, as in PFC):
///  1. sphere world positions from the bodies; neighbour list rebuilt if needed;
///  2. contact forces at x_n with the velocities v_{n−1/2}, contacts in sorted (i, j) order,
///     then (sphere, wall) order; each body sums its own contacts in that order;
///  3. F_n = gravity + contacts (stored in Body::force), PFC local damping if set;
///  4. v_{n+1/2} = v_{n−1/2} + F/m·dt, x_{n+1} = x_n + v_{n+1/2}·dt;
///     L_{n+1/2} = L_{n−1/2} + T·dt (world angular momentum, so a free body keeps L exactly),
///     q_{n+1} = exp(ω·dt/2 ⊗) q_n with ω = R I⁻¹ Rᵀ L taken at the midpoint orientation
///     (explicit midpoint with two corrector passes; Euler's equations in the body frame are
///     implied by ω(q, L)), ω stored at q_{n+1}.
/// Parallel loops (TBB) only write per-item slots; every sum runs in a fixed order, so results
/// are bit-identical for any thread count.
class World {
 public:
  explicit World(WorldOptions options = {});

  /// Adds a body and returns its index. Throws InvalidInput for a body without spheres or with
  /// non-positive mass or moments.
  int add_body(Body body);
  /// Adds a wall and returns its index.
  int add_wall(const Wall& wall);

  /// Bodies may be edited between steps (positions, velocities, orientations).
  std::vector<Body>& bodies() { return bodies_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }
  WorldOptions& options() { return options_; }
  const WorldOptions& options() const { return options_; }

  /// Advances `count` steps of options().timestep.
  void step(int count = 1);

  /// Sets μ for later steps and clamps every stored shear force to μ_new·Fn (rescale_friction),
  /// keeping the history.
  void rescale_friction(double new_friction);

  const std::vector<PairContact>& contacts() const { return contacts_; }
  const std::vector<WallContact>& wall_contacts() const { return wall_contacts_; }
  /// Body owning global sphere `sphere` (spheres are numbered body by body, in insertion order).
  int sphere_body(int sphere) const { return sphere_body_[sphere]; }
  int sphere_count() const { return static_cast<int>(sphere_body_.size()); }
  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  /// Number of neighbour-list builds (grid searches) so far (for tests of the Verlet skin).
  std::int64_t neighbour_builds() const { return builds_; }
  /// Number of near-list filters so far, builds included (for tests of near_skin_fraction).
  std::int64_t near_filters() const { return filters_; }

 private:
  friend struct CheckpointAccess;  // dem/checkpoint.cpp saves and restores the private state

  void update_sphere_positions();
  bool refresh_neighbours();
  void build_neighbours();
  void filter_candidates();
  void compute_forces();
  void integrate();
  // Fast path (world.cpp): per-candidate contact slots mirror contacts_ / wall_contacts_ during
  // step(); they are rebuilt from those lists whenever marked stale.
  bool update_positions_and_check();
  void derive_pair_index();
  void export_pairs();
  void import_pairs();
  bool walls_moved() const;
  void build_wall_candidates();
  void export_walls();
  void import_walls();

  WorldOptions options_;
  std::vector<Body> bodies_;
  std::vector<Wall> walls_;
  // Global sphere arrays.
  std::vector<int> sphere_body_;
  std::vector<Vec3> sphere_local_;  // body frame
  std::vector<double> sphere_radius_;
  std::vector<Vec3> sphere_world_;
  // Two-level Verlet list. The skin list neighbours_ holds the pairs closer than
  // r_i + r_j + skin at sphere_at_build_ (grid search); the near list candidates_ those of
  // neighbours_ closer than r_i + r_j + near_skin_fraction·skin at sphere_at_filter_. The contact
  // slots follow candidates_. Both lists hold every touching pair while no sphere has moved more
  // than sqrt(near_limit_) from sphere_at_filter_ (refresh_neighbours sets it).
  std::vector<Vec3> sphere_at_build_;
  std::vector<std::pair<int, int>> neighbours_;  // sorted (i, j)
  std::vector<Vec3> sphere_at_filter_;
  double near_limit_ = 0.0;                      // squared displacement
  std::vector<std::pair<int, int>> candidates_;  // sorted (i, j)
  bool near_valid_ = false;                      // candidates_ filtered for sphere_at_filter_
  std::int64_t filters_ = 0;
  bool dirty_ = true;
  std::vector<PairContact> contacts_;       // sorted (i, j)
  std::vector<WallContact> wall_contacts_;  // sorted (sphere, wall)
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  std::int64_t builds_ = 0;

  // Derived state of the fast path (never saved; see world.cpp).
  std::vector<int> body_first_sphere_;     // per body, then the sphere count
  NeighbourGrid grid_;                     // scratch of build_neighbours
  std::vector<std::size_t> cand_begin_;    // first candidate (i, ·) per sphere i
  std::vector<std::size_t> down_begin_;    // per sphere j: range in down_
  std::vector<std::size_t> down_;          // candidates (·, j) grouped by j, in order
  std::vector<std::size_t> body_begin_;    // per body: range in body_items_
  std::vector<std::uint64_t> body_items_;  // 2·candidate + (1 when the body holds j)
  // During step(count) the bodies' state lives in these packed arrays (loaded from bodies_ when
  // the call begins, stored back when it ends), so the per-step passes stream small records
  // instead of whole Body objects with their sphere vectors.
  struct Kinematics {  // the translational and spin state of a body: what the contact kernels read
    Vec3 position, velocity, angular_velocity;
    double mass;
  };
  std::vector<Kinematics> kinematics_;  // per body
  struct Wrench {                       // a force and a torque
    Vec3 force, torque;
  };
  std::vector<Wrench> body_wrench_;  // per body: gravity + contacts of the last step
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
  std::vector<Rotation> rotation_;  // per body
  Wrench sum_wrench(std::size_t body) const;
  void load_bodies();
  void store_bodies();
  void update_damping();
  // Per candidate: the force on the body of j and its point of application, written by the
  // contact kernel in candidate order (zero while not touching); each body gathers its items
  // (body_items_) and forms ±force and the torque about its own centroid.
  struct SlotOut {
    Vec3 force, point;
  };
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
  struct SlotForce {
    Vec3 shear;
    double normal_force;
  };
  struct SlotGeometry {
    Vec3 normal, point;
    double overlap;
  };
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

/// Total kinetic energy Σ ½·m·|v|² + ½·ω·L (J) (velocities at the half step).
double kinetic_energy(const World& world);

/// Mean unbalanced-force ratio (PFC "mechanical ratio"): mean over bodies of |F_net| divided by
/// the mean magnitude of the contact forces (pair and wall), from the last step. 0 when nothing
/// acts; +∞ when bodies feel a net force but no contact exists (free fall).
double mean_unbalanced_force_ratio(const World& world);

/// Critical time step of the world (s): the minimum over bodies of sqrt(m / kn) and, for
/// rotating bodies, sqrt(I_min / (max(kn, ks)·R²)) with R the bounding radius (the rotational
/// analogue of dem::critical_timestep). Multiply by a safety factor (e.g. 0.1–0.2) for use.
double critical_timestep(const World& world);

}  // namespace clumpkit::dem
