#include "dem/core/world.h"

#include "dem/core/parallel.h"
#include "dem/core/world_step_cache.h"
#include "geom/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

namespace clumpkit::dem {

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
  if (options_.sort_every < 0)
    throw InvalidInput("DEM world: sort_every must be non-negative, got " +
                       std::to_string(options_.sort_every));
  if (!(options_.near_skin_fraction > 0.0 && options_.near_skin_fraction <= 1.0))
    throw InvalidInput("DEM world: near_skin_fraction must be in (0, 1], got " +
                       std::to_string(options_.near_skin_fraction));
  validate(options_.contact);
  body_first_sphere_.push_back(0);
}

int World::add_body(Body body) {
  StepCache& sc = cache_.get();
  if (body.spheres.empty()) throw InvalidInput("DEM world: body has no spheres");
  if (!(body.mass > 0.0) || !(body.moments.minCoeff() > 0.0))
    throw InvalidInput("DEM world: body mass and moments must be positive");
  hold_contacts_in_lists();
  if (body.diameter <= 0.0) {
    // A plain sphere's own diameter, exactly (no cube root): scaled copies stay exact.
    if (body.spheres.size() == 1 && body.spheres[0].center.isZero(0.0))
      body.diameter = 2.0 * body.spheres[0].radius;
    else if (body.volume > 0.0)
      body.diameter = std::cbrt(6.0 * body.volume / 3.14159265358979323846);
  }
  if (options_.contact.scaling != StiffnessScaling::none &&
      (!(body.diameter > 0.0) || !std::isfinite(body.diameter)))
    throw InvalidInput(
        "DEM world: size-scaled stiffness needs each body's diameter (give it or a volume)");
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
  sc.index_valid_ = false;
  return index;
}

void World::reserve(std::size_t bodies, std::size_t spheres) {
  bodies_.reserve(bodies_.size() + bodies);
  body_first_sphere_.reserve(body_first_sphere_.size() + bodies);
  const std::size_t n = sphere_body_.size() + spheres;
  sphere_body_.reserve(n);
  sphere_local_.reserve(n);
  sphere_radius_.reserve(n);
  sphere_world_.reserve(n);
}

void World::reserve(const std::vector<Body>& bodies) {
  std::size_t spheres = 0;
  for (const Body& b : bodies) spheres += b.spheres.size();
  reserve(bodies.size(), spheres);
}

// The slots hold the history: the contact lists are written again when the call ends (or sooner,
// for a sort). Released meanwhile, they never coexist with the grid search's scratch: at 10⁶
// spheres each is a fair share of the peak.
void World::release_contacts() {
  std::vector<PairContact>().swap(contacts_);
  cache_.get().contacts_fresh_ = false;
}

int World::add_wall(const Wall& wall) {
  if (wall.kind == Wall::Kind::probe) validate_probe_profile(wall);
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

// The skin list (dem/core/neighbour_search.h): pairs of different bodies closer than
// r_i + r_j + skin at the current positions, which become the build positions.
void World::build_neighbours() {
  StepCache& sc = cache_.get();
  ++builds_;
  dirty_ = false;
  sphere_at_build_ = sphere_world_;
  frame_at_build_ = frame_;
  radius_at_build_ = 0.0;
  for (double r : sphere_radius_) radius_at_build_ = std::max(radius_at_build_, r);
  // carry_pairs' scratch is not held through the search (the peak of a large packing).
  std::vector<SlotForce>().swap(sc.carry_force_);
  std::vector<std::uint8_t>().swap(sc.carry_active_);
  std::vector<double>().swap(sc.carry_excused_);
  find_skin_pairs(sphere_world_, sphere_radius_, sphere_body_, options_.skin, sc.grid_,
                  neighbours_);
  sc.grid_ = NeighbourGrid{};  // scratch of a search every few hundred steps: not kept between
  // The skin list keeps the pairs of bonded bodies (filter_candidates leaves them out): when a
  // bond breaks, its bodies' spheres may touch from the next filter, with no grid search.
}

int World::add_bond(Bond bond) {
  StepCache& sc = cache_.get();
  const int n = static_cast<int>(bodies_.size());
  if (bond.a < 0 || bond.a >= n || bond.b < 0 || bond.b >= n || bond.a == bond.b)
    throw InvalidInput("DEM world: a bond must join two different bodies of the world, got " +
                       std::to_string(bond.a) + " and " + std::to_string(bond.b) + " of " +
                       std::to_string(n));
  if (bond.points.empty()) throw InvalidInput("DEM world: a bond needs at least one point");
  if (!(bond.factor > 0.0) || !std::isfinite(bond.factor))
    throw InvalidInput("DEM world: a bond's strength factor must be positive and finite, got " +
                       std::to_string(bond.factor));
  if (!(std::abs(bond.normal_in_a.norm() - 1.0) < 1e-9))
    throw InvalidInput("DEM world: a bond's normal must be a unit vector");
  for (const BondPoint& p : bond.points)
    if (!(p.area >= 0.0) || !std::isfinite(p.area) || !p.in_a.allFinite() || !p.in_b.allFinite())
      throw InvalidInput("DEM world: a bond point needs a finite position and area ≥ 0");
  validate(options_.cohesive, bond.factor);
  hold_contacts_in_lists();
  if (bond.holds()) {  // one more pair in the sorted set (update_bonded for all would be O(n²))
    const std::pair<int, int> pair(std::min(bond.a, bond.b), std::max(bond.a, bond.b));
    const auto at = std::lower_bound(bonded_.begin(), bonded_.end(), pair);
    if (at == bonded_.end() || *at != pair) bonded_.insert(at, pair);
  }
  bond_moments_.push_back(bond_moments(bond));
  bonds_.push_back(std::move(bond));
  dirty_ = true;
  sc.pairs_valid_ = false;
  sc.index_valid_ = false;
  return static_cast<int>(bonds_.size()) - 1;
}

void World::restore_vertex_contacts(std::vector<VertexContact> contacts) {
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const VertexContact& c = contacts[k];
    if (c.body < 0 || c.body >= static_cast<int>(bodies_.size()) || c.vertex < 0 ||
        c.vertex >= static_cast<int>(bodies_[c.body].vertices.size()) || c.wall < 0 ||
        c.wall >= static_cast<int>(walls_.size()))
      throw InvalidInput("DEM world: corner contact " + std::to_string(k) +
                         " names a body, corner or wall the world does not have");
    if (k > 0 && std::make_tuple(contacts[k - 1].body, contacts[k - 1].vertex,
                                 contacts[k - 1].wall) >= std::make_tuple(c.body, c.vertex, c.wall))
      throw InvalidInput("DEM world: corner contacts out of order at " + std::to_string(k));
  }
  vertex_contacts_ = std::move(contacts);
}

void World::update_bonded() {
  bonded_.clear();
  for (const Bond& bond : bonds_)
    if (bond.holds()) bonded_.emplace_back(std::min(bond.a, bond.b), std::max(bond.a, bond.b));
  std::sort(bonded_.begin(), bonded_.end());
  bonded_.erase(std::unique(bonded_.begin(), bonded_.end()), bonded_.end());
}

// What update_bonded would leave after the bonds of bond_broke_ stopped holding, at the cost of
// those bonds: a pair leaves bonded_ unless another bond of its bodies still holds.
std::vector<std::pair<int, int>> World::release_bonded() {
  const StepCache& sc = cache_.get();
  std::vector<std::pair<int, int>> freed;
  for (std::size_t k = 0; k < bonds_.size(); ++k) {
    if (!sc.bond_broke_[k]) continue;
    const Bond& bond = bonds_[k];
    bool held = false;
    for (std::size_t e = sc.body_bond_begin_[bond.a]; e < sc.body_bond_begin_[bond.a + 1]; ++e) {
      const std::size_t i = sc.body_bond_items_[e] >> 1;
      const Bond& other = bonds_[i];
      held =
          held || (i != k && (other.a == bond.b || other.b == bond.b) && bond_moments_[i].holding);
    }
    if (!held) freed.emplace_back(std::min(bond.a, bond.b), std::max(bond.a, bond.b));
  }
  std::sort(freed.begin(), freed.end());
  freed.erase(std::unique(freed.begin(), freed.end()), freed.end());
  for (const std::pair<int, int>& pair : freed) {
    const auto at = std::lower_bound(bonded_.begin(), bonded_.end(), pair);
    if (at != bonded_.end() && *at == pair) bonded_.erase(at);
  }
  return freed;
}

// Called once a sphere has moved more than sqrt(near_limit_) since the last filter (or there is
// none). Let D be the largest displacement since the last build: the skin list still holds every
// pair that can touch while each sphere stays within skin/2 − D of where it is now, so when that
// leaves room for a fair step the near list is filtered again from it (a linear pass), else the
// grid search runs. Filtering at near skin s and allowing moves of min(s/2, skin/2 − D) keeps
// both lists complete, with as many builds as the one-list scheme when spheres move steadily.
// In a cell frame D is measured from the build positions carried by the cell's stretch F since
// the build: a pair left out was at least R + skin apart (R = r_i + r_j ≤ 2·r_max), so it is now
// at least σ·(R + skin) − 2·D apart, σ = min(1, smallest stretch), which leaves a gap of
// σ·skin − (1 − σ)·2·r_max − 2·D. Returns true when the wall candidates must be made again
// (after a grid build, or spheres about to leave the half skin around their own positions).
bool World::refresh_neighbours() {
  StepCache& sc = cache_.get();
  const std::size_t n = sphere_world_.size();
  const double skin = options_.skin;
  const double near = options_.near_skin_fraction * skin;
  // x ↦ c + F∘(x − c_b), the cell at the build onto the cell now; the identity without frames.
  const bool affine = frame_.size.x() > 0.0 && frame_at_build_.size.x() > 0.0;
  const Vec3 stretch =
      affine ? Vec3(frame_.size.cwiseQuotient(frame_at_build_.size)) : Vec3(Vec3::Ones());
  const Vec3 c_b = frame_at_build_.centre, c = frame_.centre;
  const bool walls_own = sc.walls_valid_ && sc.sphere_at_walls_.size() == n;
  double left = -1.0;  // how far every sphere may still move before neighbours_ expires
  double wall_moved2 = 0.0;
  if (!dirty_ && sphere_at_build_.size() == n) {
    using Moves = std::pair<double, double>;  // squared: from the build, from the wall build
    const Moves moved2 = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 1024), Moves(0.0, 0.0),
        [&](const tbb::blocked_range<std::size_t>& r, Moves m) {
          for (std::size_t k = r.begin(); k != r.end(); ++k) {
            const Vec3& x = sphere_world_[k];
            const Vec3 from = affine ? Vec3(c + stretch.cwiseProduct(sphere_at_build_[k] - c_b))
                                     : sphere_at_build_[k];
            m.first = std::max(m.first, (x - from).squaredNorm());
            if (walls_own)
              m.second = std::max(m.second, (x - sc.sphere_at_walls_[k]).squaredNorm());
          }
          return m;
        },
        [](const Moves& a, const Moves& b) {
          return Moves(std::max(a.first, b.first), std::max(a.second, b.second));
        });
    wall_moved2 = moved2.second;
    double gap = skin;  // half of it is left to share between the two spheres of a pair
    double moved = std::sqrt(moved2.first);
    if (affine) {
      const double sigma = std::min(1.0, stretch.minCoeff());
      gap = sigma * skin - (1.0 - sigma) * 2.0 * radius_at_build_;
      moved += 1e-15 * (c.norm() + c_b.norm() + frame_at_build_.size.norm());  // rounding
    }
    // A relative margin keeps the rounding of this bound on the safe side.
    left = (0.5 * gap - moved) * (1.0 - 1e-9);
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
  // Wall candidates made at their own positions hold while no sphere is skin/2 from them.
  const bool walls_expire =
      walls_own && !((std::sqrt(wall_moved2) + allowed) <= 0.5 * skin * (1.0 - 1e-9));
  return build || walls_expire;
}

// The near list: pairs of neighbours_ closer than r_i + r_j + near skin at sphere_at_filter_.
void World::filter_candidates() {
  StepCache& sc = cache_.get();
  ++filters_;
  filter_pairs(neighbours_, sphere_at_filter_, sphere_radius_,
               options_.near_skin_fraction * options_.skin, sc.filter_keep_, candidates_);
  // The spheres of two bodies whose bond holds never touch: marked in parallel (this runs at
  // every filter), then the list closed up in order.
  if (!bonded_.empty()) {
    std::vector<std::uint8_t>& bonded = sc.filter_keep_;  // filter_pairs is done with it
    bonded.resize(candidates_.size());
    parallel_items(candidates_.size(), [&](std::size_t k) {
      const int a = sphere_body_[candidates_[k].first], b = sphere_body_[candidates_[k].second];
      bonded[k] = std::binary_search(bonded_.begin(), bonded_.end(),
                                     std::make_pair(std::min(a, b), std::max(a, b)));
    });
    std::size_t at = 0;
    for (std::size_t k = 0; k < candidates_.size(); ++k)
      if (!bonded[k]) candidates_[at++] = candidates_[k];
    candidates_.resize(at);
  }
  near_valid_ = true;
  freed_.clear();
}

// The near list of the last step (old_candidates_, filtered for sphere_at_filter_ while the pairs
// of freed_ were bonded) with the pairs of the freed bodies' spheres that filter_candidates would
// keep, merged in order into candidates_:
// the list a whole filter makes, at the cost of the freed bodies' spheres. A crushable specimen
// breaks a bond at most steps past its yield, and a whole filter of its skin list (the bonded
// cells' pairs included) at each of them made those steps the dearest.
void World::add_freed_candidates() {
  StepCache& sc = cache_.get();
  ++filters_;
  const double near = options_.near_skin_fraction * options_.skin;
  std::vector<std::pair<int, int>> added;
  for (const auto& [a, b] : freed_) {  // a < b, so each of a's spheres comes first in its pairs
    const int first_b = body_first_sphere_[b], end_b = body_first_sphere_[b + 1];
    for (int s = body_first_sphere_[a]; s < body_first_sphere_[a + 1]; ++s) {
      auto it =
          std::lower_bound(neighbours_.begin(), neighbours_.end(), std::make_pair(s, first_b));
      for (; it != neighbours_.end() && it->first == s && it->second < end_b; ++it) {
        if (near_pair(sphere_at_filter_, sphere_radius_, near, it->first, it->second))
          added.push_back(*it);
      }
    }
  }
  std::sort(added.begin(), added.end());
  const std::vector<std::pair<int, int>>& before = sc.old_candidates_;
  candidates_.resize(before.size() + added.size());
  std::merge(before.begin(), before.end(), added.begin(), added.end(), candidates_.begin());
  near_valid_ = true;
  freed_.clear();
}

void World::step(int count) {
  StepCache& sc = cache_.get();
  // Bodies may have been edited since the last call: refresh everything derived from them once.
  load_bodies();
  sc.positions_fresh_ = false;
  if (sc.pairs_valid_) release_contacts();  // lists asked for since the last call: the slots rule
  for (int s = 0; s < count; ++s) {
    if (options_.sort_every > 0 && steps_ % options_.sort_every == 0) {
      // The sort reads and renumbers the persistent state: bring it up to date first.
      store_bodies();  // sort_bodies() hands the slots' history to the lists itself
      if (sc.walls_valid_) export_walls();
      if (sort_bodies()) {
        load_bodies();
        sc.positions_fresh_ = false;
      } else if (sc.pairs_valid_) {
        release_contacts();
      }
    }
    if (!sc.pairs_valid_) pack_contacts();  // before the grid search and the new candidates
    bool walls_stale = !sc.walls_valid_;
    const bool moved = sc.positions_fresh_ ? sc.moved_ : update_positions_and_check();
    if (moved || !near_valid_) {
      // New candidates: the slots' history is carried over to them by a merge of the two sorted
      // lists (the wall contacts' through wall_contacts_ after a build).
      const bool carry = sc.pairs_valid_;
      if (carry) sc.old_candidates_.swap(candidates_);
      sc.pairs_valid_ = false;
      if (moved && refresh_neighbours()) {
        if (sc.walls_valid_) export_walls();
        sc.walls_valid_ = false;
        walls_stale = true;
      }
      if (!moved && carry && !freed_.empty())  // only bonds broke since the last filter
        add_freed_candidates();
      else
        filter_candidates();
      if (carry) {
        derive_pair_index();
        carry_pairs();
        sc.pairs_valid_ = true;
      }
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
    sc.last_step_ = s + 1 == count;
    compute_forces();
    // On the call's last step integrate() leaves sphere_world_ at the positions this pass saw,
    // so contacts() can write the lists with this pass's geometry when asked for.
    integrate();
    time_ += options_.timestep;
    ++steps_;
  }
  store_bodies();
  if (sc.walls_valid_) export_walls();
}

// Written from the slots on the first call after a step: a run that never asks for them never
// holds them beside the slots (96 bytes per touching pair, a sixth of a packing's peak).
const std::vector<PairContact>& World::contacts() const {
  if (cache_.get().pairs_valid_) export_pairs();
  return contacts_;
}

// Before the slots are dropped (the world edited between calls), their history goes to the lists.
void World::hold_contacts_in_lists() {
  if (cache_.get().pairs_valid_) export_pairs();
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

void World::set_cell_frame(const Vec3& centre, const Vec3& size) {
  if (!centre.allFinite() || !size.allFinite() || !(size.minCoeff() > 0.0))
    throw InvalidInput("DEM world: a cell frame needs a finite centre and positive extents");
  frame_ = CellFrame{centre, size};
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
  for (const PairContact& c : contacts) {
    if (!pair_ok(c.i, c.j)) throw InvalidInput("DEM world: contact between unknown spheres");
    if (!(c.state.excused >= 0.0) || !std::isfinite(c.state.excused))
      throw InvalidInput("DEM world: contact " + std::to_string(c.i) + "-" + std::to_string(c.j) +
                         " has an excused overlap that is not finite and >= 0");
  }
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
  frame_at_build_ = CellFrame{};  // unknown: plain motion until the next build
  neighbours_ = std::move(lists.skin_pairs);
  sphere_at_filter_ = std::move(lists.filter_positions);
  near_limit_ = lists.near_limit;
  near_valid_ = false;  // filtered from the restored lists at the next step
  freed_.clear();
  contacts_ = std::move(contacts);
  parted_.clear();  // the lists given here are the whole history
  wall_contacts_ = std::move(wall_contacts);
  StepCache& sc = cache_.get();
  sc.pairs_valid_ = sc.walls_valid_ = false;
  std::vector<PairHistory>().swap(sc.pending_);  // the lists given here are the whole history
  update_sphere_positions();
}

void World::rescale_friction(double new_friction) {
  StepCache& sc = cache_.get();
  require(kFriction, new_friction, "DEM world: friction");
  options_.contact.friction = new_friction;
  hold_contacts_in_lists();
  for (PairContact& c : contacts_) dem::rescale_friction(c.state, new_friction);
  for (WallContact& c : wall_contacts_) {
    const double own = walls_[c.wall].friction;  // a wall with its own μ keeps it
    dem::rescale_friction(c.state, own >= 0.0 ? own : new_friction);
  }
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
