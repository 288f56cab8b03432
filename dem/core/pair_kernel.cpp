// The pair-contact kernel in SIMD batches with run-time dispatch (Highway's foreach_target: this
// file is compiled once per instruction set and re-includes itself), and its scalar reference.
//
// Same bits on every path: the contact law (update_contact_force, dem/core/contact.h) is written
// once, below, over a "lanes" type that is either one double or a Highway vector, with every sum
// in the order Eigen uses for the scalar code (x·x + y·y first, then + z·z, checked for Vector3d),
// and branches turned into selects that keep each lane's value exactly. IEEE addition,
// multiplication, division and square root are correctly rounded in SIMD as in scalar, and the
// project compiles with -ffp-contract=off so that no multiply-add is fused on FMA targets.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "dem/core/pair_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "dem/core/pair_kernel.h"

#include <cmath>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace clumpkit::dem::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One contact per evaluation: the scalar reference (and the tail of a range).
struct ScalarLanes {
  using V = double;
  using M = bool;
  static V set(double x) { return x; }
  static V sqrt(V x) { return std::sqrt(x); }
  static V select(M m, V a, V b) { return m ? a : b; }
  static M gt(V a, V b) { return a > b; }
  static M lt(V a, V b) { return a < b; }
  static bool any(M m) { return m; }
};

// hn::Lanes(d) contacts per evaluation.
struct VectorLanes {
  using D = hn::ScalableTag<double>;
  using V = hn::Vec<D>;
  using M = hn::Mask<D>;
  static V set(double x) { return hn::Set(D(), x); }
  static V sqrt(V x) { return hn::Sqrt(x); }
  static V select(M m, V a, V b) { return hn::IfThenElse(m, a, b); }
  static M gt(V a, V b) { return a > b; }
  static M lt(V a, V b) { return a < b; }
  static bool any(M m) { return !hn::AllFalse(D(), m); }
};

// Centre distance and overlap of spheres i and j (the first part of World::compute_forces's
// reference loop): d = x_j − x_i, δ = r_i + r_j − |d|.
template <class L>
struct PairGeometry {
  typename L::V d[3], dist, delta;
};

template <class L>
HWY_INLINE PairGeometry<L> pair_geometry(const typename L::V xi[3], const typename L::V xj[3],
                                         typename L::V ri, typename L::V rj) {
  PairGeometry<L> g;
  for (int c = 0; c < 3; ++c) g.d[c] = xj[c] - xi[c];
  const typename L::V touch = ri + rj;
  const typename L::V d2 = (g.d[0] * g.d[0] + g.d[1] * g.d[1]) + g.d[2] * g.d[2];
  g.dist = L::sqrt(d2);
  g.delta = touch - g.dist;
  return g;
}

// What the law reads besides the geometry: the bodies' kinematics (position, velocity, angular
// velocity of the body of i, a, and of j, b), the shear and excused overlap carried from the
// last step (zero for a new contact), and the slot's dashpot c, kn and ks·dt (size-scaled where
// asked).
template <class L>
struct PairState {
  typename L::V xi[3], ri;
  typename L::V ax[3], av[3], aw[3], bx[3], bv[3], bw[3];
  typename L::V shear[3], excused;
  typename L::V c, kn, ks_dt, friction;
};

template <class L>
struct PairOutput {
  typename L::V n[3], point[3], shear[3], normal_force, f[3], excused;
};

// v + ω × (p − x), written per component as dem/core/world_contacts.cpp did.
template <class L>
HWY_INLINE void point_velocity(const typename L::V v[3], const typename L::V w[3],
                               const typename L::V p[3], const typename L::V x[3],
                               typename L::V out[3]) {
  const typename L::V rx = p[0] - x[0], ry = p[1] - x[1], rz = p[2] - x[2];
  out[0] = v[0] + (w[1] * rz - w[2] * ry);
  out[1] = v[1] + (w[2] * rx - w[0] * rz);
  out[2] = v[2] + (w[0] * ry - w[1] * rx);
}

// The contact of a touching pair: normal n = d/|d|, contact point x_i + (r_i − δ/2)·n, relative
// velocity of j's side minus i's side at that point, then update_contact_force's steps 1–4
// (dem/core/contact.h) and the force on j's side Fn·n + Fs.
// The contact frame of a pair: normal n = d/|d| (+z for two centres at one point) and contact
// point x_i + (r_i − δ/2)·n.
template <class L>
HWY_INLINE void contact_frame(const PairGeometry<L>& g, const typename L::V xi[3], typename L::V ri,
                              typename L::V n[3], typename L::V point[3]) {
  using V = typename L::V;
  const V zero = L::set(0.0);
  const typename L::M positive = L::gt(g.dist, zero);
  const V unit[3] = {zero, zero, L::set(1.0)};
  for (int c = 0; c < 3; ++c) n[c] = L::select(positive, g.d[c] / g.dist, unit[c]);
  const V lever = ri - L::set(0.5) * g.delta;
  for (int c = 0; c < 3; ++c) point[c] = xi[c] + lever * n[c];
}

template <class L>
HWY_INLINE PairOutput<L> pair_law(const PairGeometry<L>& g, const PairState<L>& s) {
  using V = typename L::V;
  const V zero = L::set(0.0);
  PairOutput<L> o;
  contact_frame<L>(g, s.xi, s.ri, o.n, o.point);
  V va[3], vb[3], v[3];
  point_velocity<L>(s.av, s.aw, o.point, s.ax, va);
  point_velocity<L>(s.bv, s.bw, o.point, s.bx, vb);
  for (int c = 0; c < 3; ++c) v[c] = vb[c] - va[c];

  // 1. The stored shear rotated into the new tangent plane, its magnitude kept.
  V* sh = o.shear;
  for (int c = 0; c < 3; ++c) sh[c] = s.shear[c];
  const V old_squared = (sh[0] * sh[0] + sh[1] * sh[1]) + sh[2] * sh[2];
  const V along = (o.n[0] * sh[0] + o.n[1] * sh[1]) + o.n[2] * sh[2];
  V projected[3];
  for (int c = 0; c < 3; ++c) projected[c] = sh[c] - o.n[c] * along;
  const V m2 =
      (projected[0] * projected[0] + projected[1] * projected[1]) + projected[2] * projected[2];
  const V scale = L::sqrt(old_squared / m2);
  const typename L::M had_shear = L::gt(old_squared, zero);
  const typename L::M can_rotate = L::gt(m2, zero);
  for (int c = 0; c < 3; ++c)
    sh[c] = L::select(had_shear, L::select(can_rotate, projected[c] * scale, zero), sh[c]);

  // 2. Normal spring and dashpot, on the overlap less the excused part, which follows the
  // overlap down (ContactState::excused; zero for all but pairs freed by a broken bond, where
  // δ − 0 is δ to the bit).
  o.excused = L::select(L::lt(s.excused, g.delta), s.excused, g.delta);
  const V vn = (v[0] * o.n[0] + v[1] * o.n[1]) + v[2] * o.n[2];
  o.normal_force = s.kn * (g.delta - o.excused) - s.c * vn;

  // 3. Incremental shear spring.
  for (int c = 0; c < 3; ++c) sh[c] = sh[c] - s.ks_dt * (v[c] - vn * o.n[c]);

  // 4. Coulomb limit μ·max(Fn, 0): std::max returns Fn unless Fn < 0 (so −0 stays −0, which a
  // SIMD max instruction would not keep).
  const V limit = s.friction * L::select(L::lt(o.normal_force, zero), zero, o.normal_force);
  const V squared = (sh[0] * sh[0] + sh[1] * sh[1]) + sh[2] * sh[2];
  const typename L::M slips = L::gt(squared, limit * limit);
  if (L::any(slips)) {  // most contacts of a packing stick: no square root or division then
    const V factor = limit / L::sqrt(squared);
    for (int c = 0; c < 3; ++c) sh[c] = L::select(slips, sh[c] * factor, sh[c]);
  }

  for (int c = 0; c < 3; ++c) o.f[c] = o.normal_force * o.n[c] + sh[c];
  return o;
}

// The moment (p − x) × f about x of a force f at p, per component as the world's sums wrote it.
template <class L>
HWY_INLINE void moment(const typename L::V p[3], const typename L::V x[3], const typename L::V f[3],
                       typename L::V out[3]) {
  const typename L::V rx = p[0] - x[0], ry = p[1] - x[1], rz = p[2] - x[2];
  out[0] = ry * f[2] - rz * f[1];
  out[1] = rz * f[0] - rx * f[2];
  out[2] = rx * f[1] - ry * f[0];
}

HWY_INLINE void release(const PairKernelArgs& a, std::size_t k) {
  if (a.active[k]) a.active[k] = 0;
}

// Where the wrench of candidate k on the body of j goes: the place of k in the sorted deferred
// list (the cursor only moves forward, as the candidates of a range do), or −1 for the body.
HWY_INLINE std::ptrdiff_t deferred_slot(const PairKernelArgs& a, std::size_t& cursor,
                                        std::size_t k) {
  while (cursor < a.deferred_count && a.deferred_candidates[cursor] < k) ++cursor;
  return cursor < a.deferred_count && a.deferred_candidates[cursor] == k
             ? static_cast<std::ptrdiff_t>(cursor)
             : -1;
}

// What a touching pair leaves behind, the same for both paths: its law state and flag, and its
// wrench on the two bodies (that of j perhaps deferred).
struct Touch {
  Vec3 shear, f, torque_a, torque_b;
  double normal_force, excused;
};

HWY_INLINE void store_contact(const PairKernelArgs& a, std::size_t& cursor, std::size_t k,
                              const Touch& t) {
  a.active[k] = 1;
  a.force[k] = SlotForce{t.shear, t.normal_force};
  if (a.excused) a.excused[k] = t.excused;
  const auto [i, j] = a.candidates[k];
  Wrench& wa = a.wrench[a.sphere_body[i]];
  wa.force -= t.f;
  wa.torque -= t.torque_a;
  const std::ptrdiff_t d = deferred_slot(a, cursor, k);
  if (d >= 0) {
    a.deferred[d] = Wrench{t.f, t.torque_b};
  } else {
    Wrench& wb = a.wrench[a.sphere_body[j]];
    wb.force += t.f;
    wb.torque += t.torque_b;
  }
}

// The reference: one candidate at a time, with the early exits of a scalar loop.
HWY_INLINE void scalar_candidate(const PairKernelArgs& a, std::size_t& cursor, std::size_t k) {
  using L = ScalarLanes;
  const auto [i, j] = a.candidates[k];
  const Vec3& xi = a.sphere_world[i];
  const Vec3& xj = a.sphere_world[j];
  const double pi[3] = {xi.x(), xi.y(), xi.z()}, pj[3] = {xj.x(), xj.y(), xj.z()};
  const PairGeometry<L> g = pair_geometry<L>(pi, pj, a.sphere_radius[i], a.sphere_radius[j]);
  if (!(g.delta > 0.0)) return release(a, k);
  PairState<L> s;
  for (int c = 0; c < 3; ++c) s.xi[c] = pi[c];
  s.ri = a.sphere_radius[i];
  const Kinematics& ka = a.kinematics[a.sphere_body[i]];
  const Kinematics& kb = a.kinematics[a.sphere_body[j]];
  for (int c = 0; c < 3; ++c) {
    s.ax[c] = ka.position[c], s.av[c] = ka.velocity[c], s.aw[c] = ka.angular_velocity[c];
    s.bx[c] = kb.position[c], s.bv[c] = kb.velocity[c], s.bw[c] = kb.angular_velocity[c];
    s.shear[c] = a.active[k] ? a.force[k].shear[c] : 0.0;
  }
  s.excused = a.excused && a.active[k] ? a.excused[k] : 0.0;
  const double f = a.stiffness ? a.stiffness[k] : 1.0;
  s.c = a.damping[k];
  s.kn = a.stiffness ? a.kn * f : a.kn;
  s.ks_dt = (a.stiffness ? a.ks * f : a.ks) * a.dt;
  s.friction = a.friction;
  const PairOutput<L> o = pair_law<L>(g, s);
  double ta[3], tb[3];
  moment<L>(o.point, s.ax, o.f, ta);
  moment<L>(o.point, s.bx, o.f, tb);
  auto vec = [](const double v[3]) { return Vec3(v[0], v[1], v[2]); };
  store_contact(a, cursor, k,
                Touch{vec(o.shear), vec(o.f), vec(ta), vec(tb), o.normal_force, o.excused});
}

// The first deferred candidate at or after `begin`.
HWY_INLINE std::size_t first_deferred(const PairKernelArgs& a, std::size_t begin) {
  std::size_t lo = 0, hi = a.deferred_count;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (a.deferred_candidates[mid] < begin)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

void PairRangeScalar(const PairKernelArgs& a, std::size_t begin, std::size_t end) {
  std::size_t cursor = first_deferred(a, begin);
  for (std::size_t k = begin; k < end; ++k) scalar_candidate(a, cursor, k);
}

// Batches of hn::Lanes(d) candidates: the spheres' centres and radii are gathered first, and a
// batch in which nothing touches (most of a falling cloud) stops there, releasing the slots that
// touched at the last step; otherwise the bodies' kinematics and the slots' state are gathered,
// every lane is evaluated, and each touching lane's result is written as the reference writes
// it, in candidate order (the body sums depend on it). Tried and dropped: a queue that runs the
// law on touching candidates only (a settled packing touches in 73 % of its candidates, and the
// second gather of each cost more than the lanes it saved: −15 %).
void PairRange(const PairKernelArgs& a, std::size_t begin, std::size_t end) {
  if (begin >= end) return;
  using L = VectorLanes;
  using V = L::V;
  const L::D d;
  const hn::RebindToSigned<L::D> di;
  constexpr std::size_t kMax = HWY_MAX_BYTES / sizeof(double);
  const std::size_t lanes = hn::Lanes(d);
  HWY_ALIGN double lane_out[15][kMax];
  std::size_t cursor = first_deferred(a, begin);
  const double* world = a.sphere_world[0].data();
  const double* kin = &a.kinematics[0].position[0];
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Kinematics) == 10 * sizeof(double) &&
                    sizeof(SlotForce) == 4 * sizeof(double) &&
                    sizeof(std::pair<int, int>) == sizeof(std::int64_t),
                "pair kernel: packed records must be plain arrays of doubles");
  constexpr int kPos = 0, kVel = 3, kSpin = 6;  // offsets in a Kinematics record
  constexpr std::size_t kAhead = 32;            // candidates prefetched ahead (j is far in memory)
  // Lane l of a batch reads slot k + l: its shear at 4·l + c from the batch's first record.
  const auto slot4 = hn::ShiftLeft<2>(hn::Iota(di, 0));
  const auto low32 = hn::Set(di, 0xFFFFFFFF);
  std::size_t k = begin;
  for (; k + lanes <= end; k += lanes) {
    for (std::size_t l = 0; l < lanes && k + l + kAhead < end; ++l) {
      const int ahead = a.candidates[k + l + kAhead].second;
      __builtin_prefetch(&a.sphere_world[ahead]);
      __builtin_prefetch(&a.kinematics[a.sphere_body[ahead]]);
    }
    // (i, j) as one 64-bit lane: i in the low half, j in the high half (x86 is little-endian).
    const auto pairs = hn::LoadU(di, reinterpret_cast<const std::int64_t*>(a.candidates + k));
    const auto si = hn::And(pairs, low32), sj = hn::ShiftRight<32>(pairs);
    const auto si3 = hn::Add(hn::Add(si, si), si), sj3 = hn::Add(hn::Add(sj, sj), sj);
    V xi[3], xj[3];
    for (int c = 0; c < 3; ++c) {
      xi[c] = hn::GatherIndex(d, world + c, si3);
      xj[c] = hn::GatherIndex(d, world + c, sj3);
    }
    const V ri = hn::GatherIndex(d, a.sphere_radius, si);
    const V rj = hn::GatherIndex(d, a.sphere_radius, sj);
    const PairGeometry<L> g = pair_geometry<L>(xi, xj, ri, rj);
    const L::M touching = L::gt(g.delta, hn::Zero(d));
    std::uint8_t active_bits = 0;
    for (std::size_t l = 0; l < lanes; ++l)
      active_bits |= static_cast<std::uint8_t>((a.active[k + l] != 0) << l);
    if (hn::AllFalse(d, touching)) {
      if (active_bits)
        for (std::size_t l = 0; l < lanes; ++l) release(a, k + l);
      continue;
    }
    // Kinematics records are 10 doubles: index 10·body = 8·body + 2·body.
    const auto body_a = hn::GatherIndex(di, a.sphere_body64, si);
    const auto body_b = hn::GatherIndex(di, a.sphere_body64, sj);
    const auto ba = hn::Add(hn::ShiftLeft<3>(body_a), hn::ShiftLeft<1>(body_a));
    const auto bb = hn::Add(hn::ShiftLeft<3>(body_b), hn::ShiftLeft<1>(body_b));
    const double* force = &a.force[k].shear[0];
    PairState<L> s;
    for (int c = 0; c < 3; ++c) {
      s.xi[c] = xi[c];
      s.ax[c] = hn::GatherIndex(d, kin + kPos + c, ba);
      s.av[c] = hn::GatherIndex(d, kin + kVel + c, ba);
      s.aw[c] = hn::GatherIndex(d, kin + kSpin + c, ba);
      s.bx[c] = hn::GatherIndex(d, kin + kPos + c, bb);
      s.bv[c] = hn::GatherIndex(d, kin + kVel + c, bb);
      s.bw[c] = hn::GatherIndex(d, kin + kSpin + c, bb);
    }
    s.ri = ri;
    const L::M carried = hn::LoadMaskBits(d, &active_bits);
    for (int c = 0; c < 3; ++c)
      s.shear[c] = hn::IfThenElseZero(carried, hn::GatherIndex(d, force + c, slot4));
    s.excused = a.excused ? hn::IfThenElseZero(carried, hn::LoadU(d, a.excused + k)) : hn::Zero(d);
    s.c = hn::LoadU(d, a.damping + k);
    if (a.stiffness) {
      const V f = hn::LoadU(d, a.stiffness + k);
      s.kn = L::set(a.kn) * f;
      s.ks_dt = (L::set(a.ks) * f) * L::set(a.dt);
    } else {
      s.kn = L::set(a.kn);
      s.ks_dt = L::set(a.ks * a.dt);
    }
    s.friction = L::set(a.friction);
    const PairOutput<L> o = pair_law<L>(g, s);
    V ta[3], tb[3];
    moment<L>(o.point, s.ax, o.f, ta);
    moment<L>(o.point, s.bx, o.f, tb);
    for (int c = 0; c < 3; ++c) {
      hn::Store(o.shear[c], d, lane_out[c]);
      hn::Store(o.f[c], d, lane_out[3 + c]);
      hn::Store(ta[c], d, lane_out[6 + c]);
      hn::Store(tb[c], d, lane_out[9 + c]);
    }
    hn::Store(o.normal_force, d, lane_out[12]);
    hn::Store(g.delta, d, lane_out[13]);
    hn::Store(o.excused, d, lane_out[14]);
    for (std::size_t l = 0; l < lanes; ++l) {
      const std::size_t kk = k + l;
      if (!(lane_out[13][l] > 0.0)) {
        release(a, kk);
        continue;
      }
      auto vec = [&](int first) {
        return Vec3(lane_out[first][l], lane_out[first + 1][l], lane_out[first + 2][l]);
      };
      store_contact(a, cursor, kk,
                    Touch{vec(0), vec(3), vec(6), vec(9), lane_out[12][l], lane_out[14][l]});
    }
  }
  for (; k < end; ++k) scalar_candidate(a, cursor, k);
}

std::int64_t PairTarget() {
  return HWY_TARGET;
}

void PairFrame(const Vec3& xi, const Vec3& xj, double ri, double rj, Vec3& normal, Vec3& point,
               double& overlap) {
  using L = ScalarLanes;
  const double pi[3] = {xi.x(), xi.y(), xi.z()}, pj[3] = {xj.x(), xj.y(), xj.z()};
  const PairGeometry<L> g = pair_geometry<L>(pi, pj, ri, rj);
  double n[3], p[3];
  contact_frame<L>(g, pi, ri, n, p);
  normal = Vec3(n[0], n[1], n[2]);
  point = Vec3(p[0], p[1], p[2]);
  overlap = g.delta;
}

}  // namespace HWY_NAMESPACE
}  // namespace clumpkit::dem::detail
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <atomic>
#include <cstdlib>

namespace clumpkit::dem {

namespace {

bool simd_from_environment() {
  const char* v = std::getenv("CLUMPKIT_SIMD");
  return !(v && (std::strcmp(v, "0") == 0 || std::strcmp(v, "off") == 0));
}

std::atomic<bool>& simd_flag() {
  static std::atomic<bool> on{simd_from_environment()};
  return on;
}

}  // namespace

namespace detail {

HWY_EXPORT(PairRange);
HWY_EXPORT(PairRangeScalar);
HWY_EXPORT(PairTarget);
HWY_EXPORT(PairFrame);

std::int64_t pair_target() {
  return HWY_DYNAMIC_DISPATCH(PairTarget)();
}

void pair_contact_frame(const Vec3& xi, const Vec3& xj, double ri, double rj, Vec3& normal,
                        Vec3& point, double& overlap) {
  HWY_STATIC_DISPATCH(PairFrame)(xi, xj, ri, rj, normal, point, overlap);
}

void pair_contacts(const PairKernelArgs& args, std::size_t begin, std::size_t end) {
  if (simd_flag().load(std::memory_order_relaxed))
    HWY_DYNAMIC_DISPATCH(PairRange)(args, begin, end);
  else
    HWY_STATIC_DISPATCH(PairRangeScalar)(args, begin, end);
}

}  // namespace detail

void set_simd(bool on) {
  simd_flag().store(on);
}

bool simd_enabled() {
  return simd_flag().load();
}

void for_each_simd_target(const std::function<void(const char*)>& f) {
  const bool was = simd_enabled();
  set_simd(true);
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::GetChosenTarget().Update(target);
    f(hwy::TargetName(target));
  }
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
  set_simd(was);
}

const char* simd_target() {
  if (!simd_enabled()) return "scalar reference";
  return hwy::TargetName(detail::pair_target());
}

}  // namespace clumpkit::dem
#endif  // HWY_ONCE
