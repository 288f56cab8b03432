// The lean DEM world: bodies, walls, neighbour grid with Verlet skin, contacts with history,
// gravity and a deterministic leapfrog integrator with quaternion rotation.
#pragma once

#include "dem/core/body.h"
#include "dem/core/bond.h"
#include "dem/core/bond_moments.h"
#include "dem/core/contact.h"
#include "dem/core/neighbour_search.h"
#include "dem/core/wall.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace clumpkit::dem {

namespace detail {
struct StepCache;
/// Owns a World's step caches (defined in dem/core/world.cpp, so the header shows none of them):
/// copied with the world; a moved-from world gets empty caches, which the next step rebuilds
/// from the persistent state (as after loading a checkpoint).
class StepCacheHolder {
 public:
  StepCacheHolder();
  ~StepCacheHolder();
  StepCacheHolder(const StepCacheHolder& other);
  StepCacheHolder& operator=(const StepCacheHolder& other);
  StepCacheHolder(StepCacheHolder&& other) noexcept;
  StepCacheHolder& operator=(StepCacheHolder&& other) noexcept;
  StepCache& get() const;

 private:
  mutable std::unique_ptr<StepCache> cache_;
};
}  // namespace detail

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
  /// Spatial sorting for memory locality (as LAMMPS's atom_modify sort, every 1,000 steps): at
  /// the start of each step whose index steps() is a multiple of sort_every, the world reorders
  /// its bodies by sort_bodies(). 0 = never. Bodies change their indices when it does, so a
  /// caller that keeps body indices across steps leaves it off (the World's default); the
  /// drivers of dem/ (deposition, compression, element tests) turn it on. The order is part
  /// of the state (bodies() holds it), so results stay the same for any thread count and a
  /// checkpoint resumes to the same bytes; they differ from an unsorted run in rounding (sums
  /// in another order).
  int sort_every = 0;
  ContactParams contact;
  /// The law of every bond (dem/core/bond.h); unused in a world without bonds.
  CohesiveParams cohesive;
  /// Whether a bond that no longer holds (every point failed) still acts: its points press in
  /// compression and slide with the law's friction, the crack's faces (true: the crushing rig,
  /// whose cells meet each other only through one inner sphere), or exert nothing (false: cells
  /// filled with spheres, which touch from the step the bond stops holding). Points fixed in
  /// both bodies stand for the faces only while the bodies stay where the crack opened: once a
  /// fragment has moved or turned away, a point's copies are no longer where the faces touch,
  /// and their spring, applied at the copies' midpoint, does work no potential accounts for (in
  /// a crushable specimen past its yield, it spun a freed cell up to 9·10⁴ rad/s).
  bool broken_bonds_act = true;
  /// Normal and shear stiffness (N/m) of one corner of a polyhedral body on a plane wall
  /// (Body::vertices); friction is the wall's, else the contact law's; the dashpot is the
  /// contact law's damping ratio. Unused without such bodies.
  double vertex_stiffness = 1e8;
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

/// A contact between corner `vertex` of body `body` (Body::vertices) and plane wall `wall`; the
/// normal is the wall's, and the body receives state.force() at state.point.
struct VertexContact {
  int body = 0;
  int vertex = 0;
  int wall = 0;
  ContactState state;
};

/// Deterministic DEM world. Each step (leapfrog, velocities at half steps, as in PFC):
///  1. sphere world positions from the bodies; neighbour list rebuilt if needed;
///  2. contact forces at x_n with the velocities v_{n−1/2}: pair contacts in sorted (i, j) order,
///     run in chunks of consecutive bodies (even chunks, then odd ones), each pair adding its
///     force and moment to its two bodies as it goes; then wall contacts in (sphere, wall) order;
///  3. F_n = gravity + pair contacts in that chunk order + pairs deferred to the end (j beyond
///     the next chunk) + walls + corners + bonds (stored in Body::force), PFC local damping if set;
///  4. v_{n+1/2} = v_{n−1/2} + F/m·dt, x_{n+1} = x_n + v_{n+1/2}·dt;
///     L_{n+1/2} = L_{n−1/2} + T·dt (world angular momentum, so a free body keeps L exactly),
///     q_{n+1} = exp(ω·dt/2 ⊗) q_n with ω = R I⁻¹ Rᵀ L taken at the midpoint orientation
///     (explicit midpoint with two corrector passes; Euler's equations in the body frame are
///     implied by ω(q, L)), ω stored at q_{n+1}.
/// Parallel loops (TBB) only write per-item slots, or per-body sums that no other task of the
/// same phase touches; every sum runs in an order fixed by the state alone (the candidates and
/// the chunking), so results are bit-identical for any thread count.
class World {
 public:
  explicit World(WorldOptions options = {});

  /// Adds a body and returns its index. Throws InvalidInput for a body without spheres or with
  /// non-positive mass or moments.
  int add_body(Body body);
  /// Makes room for `bodies` more bodies of `spheres` more spheres in all, so a world built body by
  /// body holds no more than it needs (a growing array holds up to twice its bodies while it
  /// grows). Optional: results do not depend on it.
  void reserve(std::size_t bodies, std::size_t spheres);
  /// reserve() for these bodies and all their spheres.
  void reserve(const std::vector<Body>& bodies);
  /// Adds a wall and returns its index.
  int add_wall(const Wall& wall);
  /// Adds a bond between bodies bond.a and bond.b and returns its index. Each step adds its
  /// wrench to the two bodies (after their contacts, bonds in index order); while it holds, the
  /// spheres of the two bodies never touch (the pair is kept out of the near list, which is
  /// filtered again from the skin list once it breaks). A bonded body's orientation is always
  /// integrated (its bond points turn with it). Throws InvalidInput for bodies the world does not
  /// have, a = b, or a bond without points.
  int add_bond(Bond bond);
  const std::vector<Bond>& bonds() const { return bonds_; }

  /// Bodies may be edited between steps (positions, velocities, orientations).
  std::vector<Body>& bodies() { return bodies_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }
  WorldOptions& options() { return options_; }
  const WorldOptions& options() const { return options_; }

  /// Advances `count` steps of options().timestep.
  void step(int count = 1);

  /// Declares that the bodies sit in a cell deformed homogeneously: `size` its present extents
  /// along x, y and z (m, positive) about `centre`. A sphere's motion is then measured for the
  /// Verlet lists from the image of its position at the last grid search under the cell's
  /// stretch since then, so a steadily strained specimen searches again when its spheres move
  /// relative to the cell, not with it. The lists stay complete for any cell (the bound is one
  /// of any affine map), so no result depends on it; only the count of grid searches does.
  /// Throws InvalidInput for a size not finite and positive.
  void set_cell_frame(const Vec3& centre, const Vec3& size);

  /// Reorders the bodies by the bin of their centroid — cubic bins of the largest sphere
  /// diameter counted from the lowest centroid, x fastest, then y, then z (LAMMPS's order), ties
  /// in the current order — renumbering spheres, contacts and wall contacts with them (the
  /// contact histories travel along). Lengths are those of the specimen, so a copy scaled by a
  /// power of two sorts the same. Returns false, changing nothing, when the order stays.
  bool sort_bodies();

  /// Sets μ for later steps and clamps every stored shear force to μ_new·Fn (rescale_friction),
  /// keeping the history.
  void rescale_friction(double new_friction);

  /// Touching sphere pairs with the state of the last step's contact pass, sorted (i, j).
  /// Written from the engine's per-pair slots when first asked for after a step (so not
  /// from two threads at once on one world); a reference lasts until the next step or edit.
  const std::vector<PairContact>& contacts() const;
  const std::vector<WallContact>& wall_contacts() const { return wall_contacts_; }
  /// Corners of polyhedral bodies on plane walls, sorted (body, vertex, wall).
  const std::vector<VertexContact>& vertex_contacts() const { return vertex_contacts_; }
  /// Restores vertex contacts saved from vertex_contacts() (after restore()). Throws
  /// InvalidInput for bodies, corners or walls the world does not have, or a list out of order.
  void restore_vertex_contacts(std::vector<VertexContact> contacts);
  /// Body owning global sphere `sphere` (spheres are numbered body by body, in insertion order).
  int sphere_body(int sphere) const { return sphere_body_[sphere]; }
  int sphere_count() const { return static_cast<int>(sphere_body_.size()); }
  /// Centre (world, m) and radius (m) of sphere `sphere`, from its body's present pose.
  Vec3 sphere_center(int sphere) const {
    const Body& b = bodies_[sphere_body_[sphere]];
    return b.position + b.orientation * sphere_local_[sphere];
  }
  double sphere_radius(int sphere) const { return sphere_radius_[sphere]; }
  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  /// Number of neighbour-list builds (grid searches) so far (for tests of the Verlet skin).
  std::int64_t neighbour_builds() const { return builds_; }
  /// Number of near-list filters so far, builds included (for tests of near_skin_fraction).
  std::int64_t near_filters() const { return filters_; }

  /// What the next steps depend on besides options, bodies, walls and contact lists: the clock
  /// and the two-level Verlet list. Checkpoints save it, so a resumed run takes the same steps.
  struct ListState {
    std::int64_t steps = 0;
    double time = 0.0;
    std::int64_t builds = 0, filters = 0;
    bool stale = true;  ///< no skin list yet: the next step builds one
    // The cell frame at the last build is not saved: a restored world measures plain motion
    // until its next build, which may then come earlier than in a run never stopped.
    std::vector<Vec3> build_positions;            ///< sphere positions at the last grid search
    std::vector<std::pair<int, int>> skin_pairs;  ///< the skin list, sorted (i, j)
    std::vector<Vec3> filter_positions;           ///< sphere positions at the last near filter
    double near_limit = 0.0;                      ///< squared move allowed before the next filter
  };
  ListState list_state() const;
  /// Restores a state saved with list_state() and the contact lists, into a world holding the
  /// same options, bodies and walls; the near list is filtered again at the next step. Throws
  /// InvalidInput for position lists of the wrong size or pairs and contacts naming spheres or
  /// walls the world does not have.
  void restore(ListState lists, std::vector<PairContact> contacts,
               std::vector<WallContact> wall_contacts);

 private:
  void update_sphere_positions();
  bool refresh_neighbours();
  void build_neighbours();
  void filter_candidates();
  void add_freed_candidates();
  void compute_forces();
  void integrate();
  // Fast path (world.cpp): per-candidate contact slots mirror contacts_ / wall_contacts_ during
  // step(); they are rebuilt from those lists whenever marked stale.
  bool update_positions_and_check();
  void derive_pair_index();
  void export_pairs() const;
  void hold_contacts_in_lists();
  void pack_contacts();
  void import_pairs();
  void carry_pairs();
  void release_contacts();
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
  // neighbours_ closer than r_i + r_j + near_skin_fraction·skin at sphere_at_filter_, less the
  // pairs of bodies whose bond holds (the skin list keeps them, so a bond that breaks needs a
  // filter, not a grid search). The contact slots follow candidates_. Both lists hold every
  // touching pair while no sphere has moved more than sqrt(near_limit_) from sphere_at_filter_
  // (refresh_neighbours sets it).
  // With a cell frame (set_cell_frame) the motion since the build is measured from the build
  // positions carried by the cell's stretch since then (frame_at_build_; size zero: none).
  std::vector<Vec3> sphere_at_build_;
  struct CellFrame {
    Vec3 centre = Vec3::Zero(), size = Vec3::Zero();
  };
  CellFrame frame_, frame_at_build_;
  double radius_at_build_ = 0.0;  // the largest sphere radius when neighbours_ was built
  std::vector<std::pair<int, int>> neighbours_;  // sorted (i, j)
  std::vector<Vec3> sphere_at_filter_;
  double near_limit_ = 0.0;                      // squared displacement
  std::vector<std::pair<int, int>> candidates_;  // sorted (i, j)
  bool near_valid_ = false;                      // candidates_ filtered for sphere_at_filter_
  std::int64_t filters_ = 0;
  bool dirty_ = true;
  std::vector<Bond> bonds_;
  std::vector<BondMoments> bond_moments_;    // one per bond: its closed form while undamaged
  std::vector<std::pair<int, int>> bonded_;  // sorted (a, b), a < b, of the bonds that hold
  void update_bonded();
  // The pairs of bonded_ whose last bond broke at this step (bond_broke_ of the step cache),
  // taken out of bonded_: sorted (a, b), a < b.
  std::vector<std::pair<int, int>> release_bonded();
  // Body pairs freed since the last filter while candidates_ stayed filtered for
  // sphere_at_filter_ (sorted; empty when a whole filter is due for another reason): the near
  // list then only lacks their spheres' pairs, which add_freed_candidates merges in instead of
  // filtering the whole skin list again.
  std::vector<std::pair<int, int>> freed_;
  // Contacts of the spheres of bodies whose bond broke at the last step that overlapped then
  // (sorted (i, j), no force yet, excused = the overlap): not candidates until the next filter,
  // they wait here for their slots (carry_pairs, import_pairs), and contacts() lists them.
  std::vector<PairContact> parted_;
  void part_bodies(const std::vector<std::pair<int, int>>& freed);
  mutable std::vector<PairContact> contacts_;   // sorted (i, j); see contacts()
  std::vector<WallContact> wall_contacts_;      // sorted (sphere, wall)
  std::vector<VertexContact> vertex_contacts_;  // sorted (body, vertex, wall)
  void vertex_wall_contacts();
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  std::int64_t builds_ = 0;

  // Derived state of the fast path (never saved): the step caches of dem/core/world.cpp.
  std::vector<int> body_first_sphere_;  // per body, then the sphere count
  detail::StepCacheHolder cache_;
  void load_bodies();
  void store_bodies();
  // A body's orientation during step(count): its packed record, or the Body's own for a plain
  // sphere, whose orientation is not integrated.
  const Eigen::Quaterniond& orientation_in_step(std::size_t body) const;
  void update_damping();
};

/// Total kinetic energy Σ ½·m·|v|² + ½·ω·L (J) (velocities at the half step).
double kinetic_energy(const World& world);

/// Mean unbalanced-force ratio (PFC "mechanical ratio"): mean over bodies of |F_net| divided by
/// the mean magnitude of the contact forces (pair and wall), from the last step. 0 when nothing
/// acts; +∞ when bodies feel a net force but no contact exists (free fall).
double mean_unbalanced_force_ratio(const World& world);

}  // namespace clumpkit::dem
