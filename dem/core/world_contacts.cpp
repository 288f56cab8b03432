// The contact pass of dem::World: the near-list index and its contact slots, wall candidates,
// and the pair and wall contact forces of a step.
#include "dem/core/pair_kernel.h"
#include "dem/core/parallel.h"
#include "dem/core/world.h"
#include "dem/core/world_step_cache.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <tuple>

namespace clumpkit::dem {

using namespace detail;

namespace {

// Contacts in (i, j) order, as the contact lists and parted_ keep them.
bool pair_order(const PairContact& a, const PairContact& b) {
  return std::make_pair(a.i, a.j) < std::make_pair(b.i, b.j);
}

// Spheres per chunk of the contact pass (StepCache::pair_wrench_): enough that most pairs reach
// no further than the next chunk — the 95th percentile of j − i over the candidates, from a
// sample — within [n/64, n/16] (at least 128), so a phase has 8 to 32 chunks to share among
// threads. A function of the candidates alone, never of the thread count.
std::size_t chunk_spheres(std::size_t n, const std::vector<std::pair<int, int>>& candidates) {
  const std::size_t lo = std::max<std::size_t>(128, n / 64);
  const std::size_t hi = std::max<std::size_t>(128, n / 16);
  if (candidates.empty()) return hi;
  const std::size_t stride = std::max<std::size_t>(1, candidates.size() / 4096);
  std::vector<int> span;
  span.reserve(candidates.size() / stride + 1);
  for (std::size_t k = 0; k < candidates.size(); k += stride)
    span.push_back(candidates[k].second - candidates[k].first);
  const auto at = span.begin() + static_cast<std::ptrdiff_t>(span.size() * 95 / 100);
  std::nth_element(span.begin(), at, span.end());
  return std::clamp(static_cast<std::size_t>(*at), lo, hi);
}

}  // namespace

// Index of the candidate list: per sphere its candidates as i (a range of candidates_), the
// chunks of the contact pass and its deferred pairs (StepCache::pair_wrench_), and empty slots.
void World::derive_pair_index() {
  StepCache& sc = cache_.get();
  const std::size_t n = sphere_body_.size();
  const std::size_t m = candidates_.size();
  const std::size_t nb = bodies_.size();
  sc.cand_begin_.assign(n + 1, 0);
  for (const auto& [i, j] : candidates_) ++sc.cand_begin_[i + 1];
  for (std::size_t s = 0; s < n; ++s) sc.cand_begin_[s + 1] += sc.cand_begin_[s];

  // Chunks of whole bodies, each closed once it holds `target` spheres.
  const std::size_t target = chunk_spheres(n, candidates_);
  std::vector<std::size_t> first_sphere{0};
  for (std::size_t b = 1; b < nb; ++b)
    if (static_cast<std::size_t>(body_first_sphere_[b]) - first_sphere.back() >= target)
      first_sphere.push_back(static_cast<std::size_t>(body_first_sphere_[b]));
  const std::size_t nc = first_sphere.size();
  first_sphere.push_back(n);
  sc.chunk_begin_.resize(nc + 1);
  for (std::size_t c = 0; c <= nc; ++c) sc.chunk_begin_[c] = sc.cand_begin_[first_sphere[c]];

  // Deferred pairs: j beyond the next chunk.
  sc.deferred_cand_.clear();
  for (std::size_t c = 0; c < nc; ++c) {
    const auto limit = static_cast<int>(first_sphere[std::min(c + 2, nc)]);
    for (std::size_t k = sc.chunk_begin_[c]; k < sc.chunk_begin_[c + 1]; ++k)
      if (candidates_[k].second >= limit) sc.deferred_cand_.push_back(k);
  }
  const std::size_t nd = sc.deferred_cand_.size();
  sc.deferred_wrench_.resize(nd);
  sc.body_deferred_begin_.assign(nb + 1, 0);
  for (const std::size_t k : sc.deferred_cand_)
    ++sc.body_deferred_begin_[sphere_body_[candidates_[k].second] + 1];
  for (std::size_t b = 0; b < nb; ++b) sc.body_deferred_begin_[b + 1] += sc.body_deferred_begin_[b];
  sc.body_deferred_items_.resize(nd);
  sc.scratch_.assign(sc.body_deferred_begin_.begin(), sc.body_deferred_begin_.end() - 1);
  for (std::size_t d = 0; d < nd; ++d)
    sc.body_deferred_items_[sc.scratch_[sphere_body_[candidates_[sc.deferred_cand_[d]].second]]++] =
        static_cast<std::uint32_t>(d);

  sc.slot_damping_.resize(m);
  sc.damping_valid_ = false;
}

// The dashpot and stiffness factor of every candidate pair from the bodies' current (packed)
// masses and diameters.
void World::update_damping() {
  StepCache& sc = cache_.get();
  const ContactParams& p = options_.contact;
  const bool scaled = p.scaling != StiffnessScaling::none;
  sc.slot_stiffness_.resize(scaled ? candidates_.size() : 0);
  parallel_items(candidates_.size(), [&](std::size_t k) {
    const int a = sphere_body_[candidates_[k].first], b = sphere_body_[candidates_[k].second];
    const double ma = sc.kinematics_[a].mass, mb = sc.kinematics_[b].mass;
    if (scaled) {
      const double f = pair_stiffness_factor(p, sc.body_diameter_[a], sc.body_diameter_[b]);
      sc.slot_stiffness_[k] = f;
      sc.slot_damping_[k] = normal_dashpot(ma * mb / (ma + mb), scaled_stiffness(p, f));
    } else {
      sc.slot_damping_[k] = normal_dashpot(ma * mb / (ma + mb), p);
    }
  });
  sc.damping_valid_ = true;
}

// The contact lists (authoritative while the slots are not) reduced to what the slots take and
// released: at 10⁶ spheres the lists held beside the grid search's scratch made the run's peak.
void World::pack_contacts() {
  StepCache& sc = cache_.get();
  if (contacts_.empty()) return;
  sc.pending_.resize(contacts_.size());
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const PairContact& pc = contacts_[c];
    sc.pending_[c] = PairHistory{
        {pc.i, pc.j}, SlotForce{pc.state.shear, pc.state.normal_force}, pc.state.excused};
  }
  release_contacts();
}

// The slots from the packed history (step() packs the lists before the grid search).
void World::import_pairs() {
  StepCache& sc = cache_.get();
  sc.contacts_fresh_ = false;  // candidates no longer in reach drop their history
  sc.slot_force_.resize(candidates_.size());
  sc.slot_active_.assign(candidates_.size(), 0);
  sc.slot_excused_.assign(bonds_.empty() ? 0 : candidates_.size(), 0.0);
  const int n = sphere_count();
  parallel_items(sc.pending_.size(), [&](std::size_t c) {
    const auto [i, j] = sc.pending_[c].pair;
    if (i < 0 || i >= n) return;
    const auto first = candidates_.begin() + static_cast<std::ptrdiff_t>(sc.cand_begin_[i]);
    const auto last = candidates_.begin() + static_cast<std::ptrdiff_t>(sc.cand_begin_[i + 1]);
    const auto it = std::lower_bound(first, last, std::make_pair(i, j));
    if (it == last || it->second != j) return;  // no longer a candidate: history dropped
    const auto k = static_cast<std::size_t>(it - candidates_.begin());
    sc.slot_force_[k] = sc.pending_[c].force;
    sc.slot_active_[k] = 1;
    if (!sc.slot_excused_.empty()) sc.slot_excused_[k] = sc.pending_[c].excused;
    // The wrenches are written by the next contact pass (every active slot is refreshed there).
  });
  std::vector<PairHistory>().swap(sc.pending_);
  parted_.clear();  // the lists held them (export_pairs), so the pending history did
}

// The slots of the previous candidates (old_candidates_, both lists sorted) carried over to the
// new ones: a pair in both keeps its state, a pair only in the new list starts untouched, one only
// in the old list drops its history (it is out of reach). A merge, no contact list built.
void World::carry_pairs() {
  StepCache& sc = cache_.get();
  const std::vector<std::pair<int, int>>& old = sc.old_candidates_;
  const std::size_t m = candidates_.size();
  // Into the arrays the last carry left behind, not new ones at every filter (a crushable
  // specimen past its yield filters at most steps).
  const bool excuses = !bonds_.empty();
  std::vector<SlotForce>& force = sc.carry_force_;
  std::vector<std::uint8_t>& active = sc.carry_active_;
  std::vector<double>& excused = sc.carry_excused_;
  force.assign(m, SlotForce{Vec3::Zero(), 0.0});
  active.assign(m, 0);
  excused.assign(excuses ? m : 0, 0.0);
  sc.slot_excused_.resize(excuses ? old.size() : 0, 0.0);
  std::size_t o = 0, p = 0;
  for (std::size_t k = 0; k < m; ++k) {
    while (o < old.size() && old[o] < candidates_[k]) ++o;
    if (o < old.size() && old[o] == candidates_[k] && sc.slot_active_[o]) {
      force[k] = sc.slot_force_[o];
      active[k] = 1;
      if (excuses) excused[k] = sc.slot_excused_[o];
      continue;
    }
    // A pair freed by a bond that broke at the last step starts touching with its overlap
    // excused (part_bodies).
    if (!excuses) continue;  // parted_ is empty without bonds
    while (p < parted_.size() && std::make_pair(parted_[p].i, parted_[p].j) < candidates_[k]) ++p;
    if (p < parted_.size() && std::make_pair(parted_[p].i, parted_[p].j) == candidates_[k]) {
      force[k] = SlotForce{Vec3::Zero(), 0.0};
      active[k] = 1;
      excused[k] = parted_[p].state.excused;
    }
  }
  sc.slot_force_.swap(force);
  sc.slot_active_.swap(active);
  sc.slot_excused_.swap(excused);
  parted_.clear();
  sc.contacts_fresh_ = false;
}

// The touching slots as contact lists, with the geometry of sphere_world_: between calls the
// positions of the last contact pass (integrate() leaves them on a call's last step), so the
// lists report that pass's geometry, the same bits as the kernel's.
void World::export_pairs() const {
  StepCache& sc = cache_.get();
  if (sc.contacts_fresh_) return;
  contacts_.clear();
  // Exactly as many as touch (a growing vector would hold up to twice that at its peak).
  std::size_t touching = parted_.size();
  for (const std::uint8_t a : sc.slot_active_) touching += a;
  contacts_.reserve(touching);
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (!sc.slot_active_[k]) continue;
    PairContact& c = contacts_.emplace_back();
    c.i = candidates_[k].first;
    c.j = candidates_[k].second;
    pair_contact_frame(sphere_world_[c.i], sphere_world_[c.j], sphere_radius_[c.i],
                       sphere_radius_[c.j], c.state.normal, c.state.point, c.state.overlap);
    c.state.normal_force = sc.slot_force_[k].normal_force;
    c.state.shear = sc.slot_force_[k].shear;
    if (!sc.slot_excused_.empty()) c.state.excused = sc.slot_excused_[k];
  }
  // Pairs still waiting for their slots (parted_, never candidates yet) in their places.
  if (!parted_.empty()) {
    const auto middle = contacts_.insert(contacts_.end(), parted_.begin(), parted_.end());
    std::inplace_merge(contacts_.begin(), middle, contacts_.end(), pair_order);
  }
  sc.contacts_fresh_ = true;
}

// Wall candidates: (sphere, wall) pairs with a gap below the skin at the spheres' build positions
// (in a cell frame: their present ones, kept). A sphere moves at most skin/2 from those before
// the next build (in a cell frame: before refresh_neighbours asks for new candidates) and a wall
// at most skin/2 before walls_moved() does, so every touching pair is a candidate.
bool World::walls_moved() const {
  StepCache& sc = cache_.get();
  if (walls_.size() != sc.walls_at_build_.size()) return true;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& a = walls_[w];
    const Wall& b = sc.walls_at_build_[w];
    if (a.kind != b.kind || a.normal != b.normal) return true;
    if (a.kind == Wall::Kind::probe) {
      if (a.profile != b.profile || !((a.point - b.point).norm() <= 0.5 * options_.skin))
        return true;
    } else if (a.kind == Wall::Kind::cylinder) {
      if (a.point.x() != b.point.x() || a.point.y() != b.point.y()) return true;
      // A servo-driven radius, like a plane, may move half the skin before new candidates.
      if (!(std::abs(a.radius - b.radius) <= 0.5 * options_.skin)) return true;
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
  if (frame_.size.x() > 0.0)
    sc.sphere_at_walls_ = sphere_world_;
  else
    sc.sphere_at_walls_.clear();
  const std::vector<Vec3>& at =
      sc.sphere_at_walls_.empty() ? sphere_at_build_ : sc.sphere_at_walls_;
  const double skin = options_.skin;
  auto candidate = [&](std::size_t s, std::size_t w) {
    const Wall& wall = walls_[w];
    // A polyhedral body meets plane walls with its corners (vertex_wall_contacts).
    if (wall.kind == Wall::Kind::plane && !bodies_[sphere_body_[s]].vertices.empty()) return false;
    const Vec3& x = at[s];
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

// Corners of polyhedral bodies below plane walls: a linear spring-dashpot contact with Coulomb
// friction per corner, its history carried from the last step through vertex_contacts_ (sorted
// (body, vertex, wall), merged in order). Serial: few bodies have corners.
void World::vertex_wall_contacts() {
  StepCache& sc = cache_.get();
  if (!sc.any_vertices_) return;  // the common world: no pass over the bodies
  const double dt = options_.timestep;
  ContactParams corner = options_.contact;  // the corner spring, with the law's damping
  corner.scaling = StiffnessScaling::none;
  corner.kn = corner.ks = options_.vertex_stiffness;
  std::vector<VertexContact> next;
  std::size_t old = 0;
  auto key = [](const VertexContact& c) { return std::make_tuple(c.body, c.vertex, c.wall); };
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (!sc.body_has_vertices_[k]) continue;
    Wrench total{Vec3::Zero(), Vec3::Zero()};
    const Kinematics& b = sc.kinematics_[k];
    const Eigen::Quaterniond& q = orientation_in_step(k);
    const std::vector<Vec3>& corners = bodies_[k].vertices;
    for (std::size_t v = 0; v < corners.size(); ++v) {
      const Vec3 x = b.position + q * corners[v];
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const Wall& wall = walls_[w];
        if (wall.kind != Wall::Kind::plane) continue;
        const double d = wall.normal.dot(x - wall.point);
        if (!(d < 0.0)) continue;
        VertexContact c{static_cast<int>(k), static_cast<int>(v), static_cast<int>(w), {}};
        while (old < vertex_contacts_.size() && key(vertex_contacts_[old]) < key(c)) ++old;
        if (old < vertex_contacts_.size() && key(vertex_contacts_[old]) == key(c))
          c.state = vertex_contacts_[old].state;
        ContactParams p = corner;
        if (wall.friction >= 0.0) p.friction = wall.friction;
        const Vec3 vb = b.velocity + b.angular_velocity.cross(x - b.position);
        update_contact(c.state, wall.normal, -d, x, vb - wall.velocity, b.mass, p, dt);
        const Vec3 f = c.state.force();
        total.force += f;
        total.torque += (x - b.position).cross(f);
        next.push_back(c);
      }
    }
    sc.vertex_wrench_[k] = total;
  }
  vertex_contacts_ = std::move(next);
}

// The bodies whose last bond broke at this step (freed: sorted, out of bonded_): each pair of
// their spheres that overlaps at this step's positions waits in parted_ for its slot, with that
// overlap excused (ContactState::excused). Serial: a few pairs per broken bond, at the steps
// where one breaks.
void World::part_bodies(const std::vector<std::pair<int, int>>& freed) {
  std::vector<PairContact> parted;
  for (const auto& [a, b] : freed) {
    for (int s = body_first_sphere_[a]; s < body_first_sphere_[a + 1]; ++s)
      for (int t = body_first_sphere_[b]; t < body_first_sphere_[b + 1]; ++t) {
        PairContact c;
        c.i = std::min(s, t), c.j = std::max(s, t);
        pair_contact_frame(sphere_world_[c.i], sphere_world_[c.j], sphere_radius_[c.i],
                           sphere_radius_[c.j], c.state.normal, c.state.point, c.state.overlap);
        if (!(c.state.overlap > 0.0)) continue;
        c.state.excused = c.state.overlap;
        parted.push_back(c);
      }
  }
  if (parted.empty()) return;
  std::sort(parted.begin(), parted.end(), pair_order);
  const auto middle = parted_.insert(parted_.end(), parted.begin(), parted.end());
  std::inplace_merge(parted_.begin(), middle, parted_.end(), pair_order);
}

void World::compute_forces() {
  StepCache& sc = cache_.get();
  sc.contacts_fresh_ = false;
  const double dt = options_.timestep;
  const ContactParams& p = options_.contact;
  const bool scaled = p.scaling != StiffnessScaling::none;
  if (!sc.damping_valid_) update_damping();

  // Pair contacts, one slot per candidate (dem/core/pair_kernel.h): a touching pair keeps its
  // shear history when it touched at the last step too, else it starts from a fresh state.
  const PairKernelArgs args{candidates_.data(),
                            sphere_world_.data(),
                            sphere_radius_.data(),
                            sphere_body_.data(),
                            sc.sphere_body64_.data(),
                            sc.kinematics_.data(),
                            sc.slot_damping_.data(),
                            scaled ? sc.slot_stiffness_.data() : nullptr,
                            p.kn,
                            p.ks,
                            p.friction,
                            dt,
                            sc.slot_force_.data(),
                            sc.slot_excused_.empty() ? nullptr : sc.slot_excused_.data(),
                            sc.slot_active_.data(),
                            sc.pair_wrench_.data(),
                            sc.deferred_cand_.data(),
                            sc.deferred_cand_.size(),
                            sc.deferred_wrench_.data()};
  // Even chunks, then odd ones (StepCache::pair_wrench_): each chunk one serial range.
  const std::size_t nc = sc.chunk_begin_.empty() ? 0 : sc.chunk_begin_.size() - 1;
  for (std::size_t phase = 0; phase < 2 && phase < nc; ++phase)
    parallel_ranges((nc - phase + 1) / 2, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t q = begin; q < end; ++q) {
        const std::size_t c = 2 * q + phase;
        pair_contacts(args, sc.chunk_begin_[c], sc.chunk_begin_[c + 1]);
      }
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
    const Wall& wall = walls_[w];
    // Planes and probes translate; a growing cylinder's surface moves along −normal (outward)
    // at radial_velocity.
    const Vec3 vw = wall.kind != Wall::Kind::cylinder ? wall.velocity
                    : wall.radial_velocity != 0.0     ? Vec3(-wall.radial_velocity * hit.normal)
                                                      : Vec3(Vec3::Zero());
    const int body = sphere_body_[s];
    ContactParams q =
        scaled ? scaled_stiffness(p, wall_stiffness_factor(p, sc.body_diameter_[body])) : p;
    if (wall.friction >= 0.0) q.friction = wall.friction;
    update_contact(state, hit.normal, hit.overlap, hit.point, vb - vw, b.mass, q, dt);
  });

  vertex_wall_contacts();

  // Bonds, one wrench slot per bond. One that stops holding lets its bodies' spheres touch from
  // the next step: their pairs join the near list from the skin list, which holds them.
  if (!bonds_.empty()) {
    sc.bond_wrench_.resize(bonds_.size());
    sc.bond_broke_.assign(bonds_.size(), 0);
    std::atomic<bool> broke{false};
    parallel_items(bonds_.size(), [&](std::size_t k) {
      Bond& bond = bonds_[k];
      BondMoments& moments = bond_moments_[k];
      if (!moments.holding && !options_.broken_bonds_act) {
        sc.bond_wrench_[k] = BondWrench{};  // its bodies' spheres touch instead
        return;
      }
      const Mat3 &ra = sc.bond_matrix_[bond.a], &rb = sc.bond_matrix_[bond.b];
      const Vec3 &pa = sc.kinematics_[bond.a].position, &pb = sc.kinematics_[bond.b].position;
      // Most bonds, most steps: undamaged and far below the onset, the closed form.
      if (elastic_bond_wrench(moments, bond, options_.cohesive, pa, ra, pb, rb, sc.bond_wrench_[k]))
        return;
      BondPointsAfter after;
      sc.bond_wrench_[k] = bond_wrench(bond, options_.cohesive, pa, ra, pb, rb, after);
      if (moments.holding && !after.holds) {
        sc.bond_broke_[k] = 1;
        broke.store(true, std::memory_order_relaxed);
      }
      moments.holding = after.holds;
      moments.pristine = moments.pristine && after.undamaged;
    });
    if (broke.load()) {
      const std::vector<std::pair<int, int>> freed = release_bonded();
      part_bodies(freed);
      // A near list filtered for sphere_at_filter_ lacks only the freed pairs' spheres now (a
      // bond whose bodies another bond still holds changes nothing).
      if (near_valid_ && !freed.empty()) {
        std::vector<std::pair<int, int>> all(freed_.size() + freed.size());
        std::merge(freed_.begin(), freed_.end(), freed.begin(), freed.end(), all.begin());
        freed_.swap(all);
        near_valid_ = false;
      }
    }
  }

  // The sums per body are made by integrate(), in the same pass that advances the body.
}

}  // namespace clumpkit::dem
