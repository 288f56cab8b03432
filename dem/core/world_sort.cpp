// World::sort_bodies: spatial order of the bodies for memory locality (dem/core/world.h).
#include "dem/core/world.h"
#include "dem/core/world_step_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>

namespace clumpkit::dem {

using namespace detail;

namespace {

// Bin index along one axis, clamped to 21 bits so three fit in one 64-bit key (a body flown far
// away lands in the last bin rather than overflowing the key).
std::uint64_t bin_of(double offset, double bin) {
  constexpr double kMax = double((1u << 21) - 1);
  const double b = std::floor(offset / bin);
  return static_cast<std::uint64_t>(b >= 0.0 ? std::min(b, kMax) : 0.0);  // NaN -> 0
}

}  // namespace

bool World::sort_bodies() {
  const std::size_t nb = bodies_.size();
  if (nb < 2) return false;
  hold_contacts_in_lists();  // renumbered below with the spheres
  parted_.clear();           // the lists hold them now
  // Bins of the largest sphere diameter from the lowest centroid: only lengths of the specimen,
  // so a copy scaled by λ = 2^k computes the same bins and sorts the same.
  Vec3 lo = Vec3::Constant(INFINITY);
  double r_max = 0.0;
  for (const Body& b : bodies_) lo = lo.cwiseMin(b.position);
  for (double r : sphere_radius_) r_max = std::max(r_max, r);
  if (!(r_max > 0.0) || !lo.allFinite()) return false;
  const double bin = 2.0 * r_max;
  std::vector<std::uint64_t> key(nb);
  for (std::size_t k = 0; k < nb; ++k) {
    const Vec3 d = bodies_[k].position - lo;
    key[k] = (bin_of(d.z(), bin) << 42) | (bin_of(d.y(), bin) << 21) | bin_of(d.x(), bin);
  }
  std::vector<int> order(nb);  // new index -> old index
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  bool same = true;
  for (std::size_t k = 0; k < nb && same; ++k) same = order[k] == static_cast<int>(k);
  if (same) return false;

  // Bodies and the per-sphere arrays in the new order; old sphere -> new sphere.
  const std::size_t ns = sphere_body_.size();
  std::vector<int> sphere_map(ns);
  std::vector<Body> bodies;
  bodies.reserve(nb);
  std::vector<int> first{0};
  std::vector<int> sphere_body;
  std::vector<Vec3> sphere_local, sphere_world;
  std::vector<double> sphere_radius;
  sphere_body.reserve(ns), sphere_local.reserve(ns), sphere_world.reserve(ns);
  sphere_radius.reserve(ns);
  for (std::size_t k = 0; k < nb; ++k) {
    const int old = order[k];
    for (int s = body_first_sphere_[old]; s < body_first_sphere_[old + 1]; ++s) {
      sphere_map[s] = static_cast<int>(sphere_body.size());
      sphere_body.push_back(static_cast<int>(k));
      sphere_local.push_back(sphere_local_[s]);
      sphere_radius.push_back(sphere_radius_[s]);
      sphere_world.push_back(sphere_world_[s]);
    }
    first.push_back(static_cast<int>(sphere_body.size()));
    bodies.push_back(std::move(bodies_[old]));
  }
  bodies_ = std::move(bodies);
  body_first_sphere_ = std::move(first);
  sphere_body_ = std::move(sphere_body);
  sphere_local_ = std::move(sphere_local);
  sphere_radius_ = std::move(sphere_radius);
  sphere_world_ = std::move(sphere_world);

  // Contacts renumbered, i < j kept: a swapped pair sees the other side, so its normal and
  // shear force change sign (force() is what the new j receives, the old i's force).
  for (PairContact& c : contacts_) {
    c.i = sphere_map[c.i], c.j = sphere_map[c.j];
    if (c.i > c.j) {
      std::swap(c.i, c.j);
      c.state.normal = -c.state.normal;
      c.state.shear = -c.state.shear;
    }
  }
  std::sort(contacts_.begin(), contacts_.end(), [](const PairContact& a, const PairContact& b) {
    return std::make_pair(a.i, a.j) < std::make_pair(b.i, b.j);
  });
  for (WallContact& c : wall_contacts_) c.sphere = sphere_map[c.sphere];
  // Bonds keep their order and sides (a, b): only the body indices change; corner contacts
  // are renumbered and sorted again.
  if (!bonds_.empty() || !vertex_contacts_.empty()) {
    std::vector<int> body_map(nb);  // old body -> new body
    for (std::size_t k = 0; k < nb; ++k) body_map[order[k]] = static_cast<int>(k);
    for (Bond& bond : bonds_) bond.a = body_map[bond.a], bond.b = body_map[bond.b];
    update_bonded();
    for (VertexContact& c : vertex_contacts_) c.body = body_map[c.body];
    std::sort(vertex_contacts_.begin(), vertex_contacts_.end(),
              [](const VertexContact& a, const VertexContact& b) {
                return std::make_tuple(a.body, a.vertex, a.wall) <
                       std::make_tuple(b.body, b.vertex, b.wall);
              });
  }
  std::sort(wall_contacts_.begin(), wall_contacts_.end(),
            [](const WallContact& a, const WallContact& b) {
              return std::make_pair(a.sphere, a.wall) < std::make_pair(b.sphere, b.wall);
            });

  // The Verlet lists name old spheres: the next step searches the grid again.
  dirty_ = true;
  near_valid_ = false;
  freed_.clear();
  neighbours_.clear();
  candidates_.clear();
  sphere_at_build_.clear();
  sphere_at_filter_.clear();
  StepCache& sc = cache_.get();
  sc.pairs_valid_ = sc.walls_valid_ = false;
  sc.damping_valid_ = false;
  sc.index_valid_ = false;
  return true;
}

}  // namespace clumpkit::dem
