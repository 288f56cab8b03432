// The pair-contact kernel of dem::World: contacts of the near list evaluated 2, 4 or 8 at a time
// with SIMD (Highway, chosen at run time for the CPU), beside a scalar reference that performs
// the same operations in the same order, so both give the same bits.
#pragma once

#include "dem/core/world_step_cache.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>

namespace clumpkit::dem {

/// Turns SIMD in the pair-contact kernel on or off for the whole process (default: on, unless
/// the environment variable CLUMPKIT_SIMD is "0" or "off" at start-up). Off runs the scalar
/// reference; results are identical bit for bit either way, so this is a switch for checks and
/// measurements, not for accuracy.
void set_simd(bool on);

/// Whether the pair-contact kernel uses SIMD.
bool simd_enabled();

/// The instruction set the pair-contact kernel runs on: Highway's name of the target chosen for
/// this CPU ("AVX3" = AVX-512, "AVX2", "SSE4", …) with SIMD on, "scalar reference" with it off.
const char* simd_target();

/// For tests and benchmarks: calls f(name) once per instruction set that this build compiled and
/// this CPU runs, with the kernel (SIMD on) dispatching to that set meanwhile; afterwards the
/// CPU's best set and the former on/off setting are restored. Not thread-safe against steps
/// running at the same time.
void for_each_simd_target(const std::function<void(const char*)>& f);

namespace detail {

/// What the pair kernel reads and writes: the World's arrays during a contact pass
/// (World::compute_forces). Per candidate k = (i, j): the spheres' world centres and radii, the
/// bodies' packed kinematics, the slot's dashpot (and stiffness factor with size scaling), and
/// its contact law state and flag. Per body: the wrench the pass adds its contacts to.
struct PairKernelArgs {
  const std::pair<int, int>* candidates;
  const Vec3* sphere_world;
  const double* sphere_radius;
  const int* sphere_body;
  const std::int64_t* sphere_body64;  // the same indices as 64-bit lanes, for SIMD gathers
  const Kinematics* kinematics;
  const double* damping;    // per candidate: 2·β·sqrt(m_eff·kn)
  const double* stiffness;  // per candidate: factor on kn and ks; null without size scaling
  double kn, ks, friction, dt;
  SlotForce* force;
  /// Per candidate: the overlap its law ignores (ContactState::excused), read while the slot is
  /// active and written while the pair touches; null: none (a world without bonds).
  double* excused;
  std::uint8_t* active;
  /// Per body: each touching pair adds −F and −(p − x_a) × F to the body of i and, unless the
  /// pair is deferred, +F and (p − x_b) × F to the body of j, in candidate order.
  Wrench* wrench;
  /// Deferred candidates (sorted): their wrench on the body of j goes to deferred[d] (d the
  /// candidate's place in deferred_candidates) instead, for a later sum; written only while the
  /// pair touches.
  const std::size_t* deferred_candidates;
  std::size_t deferred_count;
  Wrench* deferred;
};

/// Advances the candidates [begin, end) in order: a touching pair updates its contact law
/// (update_contact, dem/core/contact.h) and adds its wrench to the bodies as PairKernelArgs
/// says; a pair that stopped touching clears its flag. The wrench
/// sums make a range a serial unit: ranges may run on several threads at once only when no two
/// of them add to the same body (World::compute_forces's chunks).
void pair_contacts(const PairKernelArgs& args, std::size_t begin, std::size_t end);

/// The frame of a touching pair of spheres (centres x_i, x_j, radii r_i, r_j, m) as the kernel
/// computes it, bit for bit: the unit normal d/|d| from i to j (+z for two centres at one point),
/// the contact point x_i + (r_i − δ/2)·n and the overlap δ = r_i + r_j − |d|. The contact lists
/// report it instead of the kernel storing it for every candidate.
void pair_contact_frame(const Vec3& xi, const Vec3& xj, double ri, double rj, Vec3& normal,
                        Vec3& point, double& overlap);

}  // namespace detail

}  // namespace clumpkit::dem
