// The step caches of dem::World, shared by its three source files (world.cpp: lists and the
// step loop; world_contacts.cpp: the contact pass; world_integrate.cpp: sums and integration).
// Internal to dem: nothing outside the World includes it.
#pragma once

#include "dem/core/world.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace clumpkit::dem {

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

struct Rotation {  // what the integrator reads of a rotating body (not a plain sphere)
  Eigen::Quaterniond orientation;
  Vec3 moments;
};

// Per body: how it turns, where its Rotation is, and a plain sphere's one moment of inertia. A
// plain sphere (most bodies of a soil packing) needs no orientation or second and third moment,
// so its step reads these 16 bytes instead of a 64-byte Rotation.
struct Turning {
  Spin spin;
  std::uint32_t rotation;  // index in StepCache::rotation_; unused for a plain sphere
  double moment;           // a plain sphere's principal moment (kg·m²); unused for the rest
};

struct SlotForce {
  Vec3 shear;
  double normal_force;
};

struct PairHistory {  // what a slot takes from a contact list's entry
  std::pair<int, int> pair;
  SlotForce force;
  double excused;
};

}  // namespace detail

// What World::step derives from the persistent state and keeps between calls: the index of the
// near list, per-candidate contact slots, wall candidates and the packed body state. Never saved:
// every part is rebuilt from the persistent state when marked stale (a fresh cache is all stale).
namespace detail {
struct StepCache {
  NeighbourGrid grid_;                               // scratch of build_neighbours
  std::vector<std::size_t> cand_begin_;              // first candidate (i, ·) per sphere i
  std::vector<std::pair<int, int>> old_candidates_;  // the slots' keys while new ones are made
  // During step(count) the bodies' state lives in these packed arrays (loaded from bodies_ when
  // the call begins, stored back when it ends), so the per-step passes stream small records
  // instead of whole Body objects with their sphere vectors.
  std::vector<Kinematics> kinematics_;       // per body
  std::vector<Turning> turning_;             // per body
  std::vector<Rotation> rotation_;           // per body that is not a plain sphere, in order
  std::vector<std::int64_t> sphere_body64_;  // per sphere: its body, for the pair kernel's gathers
  // Per body: m·g, then the pair contacts of this step's contact pass, added by the kernel
  // itself (pair_kernel.h); integrate() adds the rest and starts it again from m·g. The pass
  // runs in chunks of whole bodies (consecutive candidates by i; chunk_begin_ gives their
  // candidate ranges), even chunks in parallel, then odd ones: a chunk adds to its own bodies and
  // those of the next chunk, so no two chunks of a phase add to one body, and each body's sum
  // runs in one order — chunk by chunk in phase order, candidates in order — that depends on
  // the candidates and the chunking alone, never on the thread count. A pair whose j lies beyond
  // the next chunk is deferred: its wrench on j's body waits in deferred_wrench_ and integrate()
  // adds it, per body in candidate order (body_deferred_*).
  std::vector<Wrench> pair_wrench_;
  std::vector<std::size_t> chunk_begin_;            // per chunk: first candidate; then the count
  std::vector<std::size_t> deferred_cand_;          // the deferred candidates, sorted
  std::vector<Wrench> deferred_wrench_;             // per deferred candidate, while it touches
  std::vector<std::size_t> body_deferred_begin_;    // per body: range in body_deferred_items_
  std::vector<std::uint32_t> body_deferred_items_;  // places in deferred_cand_, in order
  // Per candidate: the normal dashpot 2·β·sqrt(m_eff·kn) (update_contact's formula), computed
  // when the candidates or the masses change instead of at every contact and step.
  std::vector<double> slot_damping_;
  // Per candidate: the factor on kn and ks of the size rule (pair_stiffness_factor), computed
  // with the dashpot; per body its diameter (packed by load_bodies). Unused without scaling.
  std::vector<double> slot_stiffness_;
  std::vector<double> body_diameter_;
  bool damping_valid_ = false;
  // Per candidate, what the contact law carries from step to step (read and written every
  // step); the geometry (normal, point, overlap) is not kept: export_pairs computes it from the
  // positions of the contact pass (pair_contact_frame), on the call's last step before the
  // bodies move.
  std::vector<SlotForce> slot_force_;
  // Per candidate in a world with bonds (empty without): the overlap its law ignores
  // (ContactState::excused), read and written with slot_force_ while the slot is active.
  std::vector<double> slot_excused_;
  // The slot arrays before the last carry_pairs, kept as its scratch for the next.
  std::vector<SlotForce> carry_force_;
  std::vector<std::uint8_t> carry_active_;
  std::vector<double> carry_excused_;
  // The contact lists' history (40 bytes a contact, no geometry) while new slots are made for it:
  // the lists themselves are released before the grid search (World::pack_contacts).
  std::vector<PairHistory> pending_;
  bool last_step_ = true;        // the call's last step: Body::force and the contact lists written
  bool contacts_fresh_ = false;  // contacts_ holds the slots' present state (nothing to export)
  std::vector<std::uint8_t> slot_active_;       // per candidate: touching at the last step
  std::vector<std::pair<int, int>> wall_cand_;  // sorted (sphere, wall)
  std::vector<ContactState> wall_slot_state_;   // per wall candidate
  std::vector<std::uint8_t> wall_slot_active_;  // per wall candidate
  std::vector<std::size_t> body_wall_begin_;    // per body: range in wall_cand_
  // Bonds: per bond its wrench of this step; per body its bonds in index order (range in
  // body_bond_items_, each 2·bond + 1 when the body is the bond's b), built by load_bodies.
  std::vector<BondWrench> bond_wrench_;
  std::vector<std::uint8_t> bond_broke_;  // per bond: stopped holding at this step's bond pass
  // Per body with bonds: its rotation matrix at this step's contact pass (made by load_bodies and
  // after each body's advance), so the bond pass reads two matrices per bond instead of making
  // them from the quaternions: a body has about ten bonds. Empty in a world without bonds.
  std::vector<Mat3> bond_matrix_;
  // Polyhedral bodies: which bodies have corners (by load_bodies), and per body the wrench of
  // its corner contacts of this step, summed in (vertex, wall) order.
  std::vector<std::uint8_t> body_has_vertices_;
  bool any_vertices_ = false;
  std::vector<Wrench> vertex_wrench_;
  std::vector<std::size_t> body_bond_begin_;
  std::vector<std::uint64_t> body_bond_items_;
  // body_bond_begin_, body_bond_items_ and sphere_body64_ hold for the bodies and bonds as they
  // are (World::add_body, add_bond and sort_bodies clear it).
  bool index_valid_ = false;
  std::vector<Wall> walls_at_build_;  // walls when wall_cand_ was built
  // Sphere positions when wall_cand_ was built, in a cell frame (spheres may then move more
  // than skin/2 between grid builds); empty without one: the build positions serve.
  std::vector<Vec3> sphere_at_walls_;
  std::vector<std::size_t> scratch_;       // counts / offsets
  std::vector<std::uint8_t> filter_keep_;  // scratch of filter_candidates
  bool positions_fresh_ = false;           // sphere_world_ and moved_ set by integrate this call
  bool moved_ = true;         // a sphere moved more than sqrt(near_limit_) since the filter
  bool pairs_valid_ = false;  // slots mirror contacts_ for the current candidates_
  bool walls_valid_ = false;  // wall slots mirror wall_contacts_ for the current wall_cand_
};
}  // namespace detail

}  // namespace clumpkit::dem
