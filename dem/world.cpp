#include "dem/world.h"

#include "dem/timestep.h"
#include "geom/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
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

template <class F>
void parallel_items(std::size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 32),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k) f(k);
                    });
}

}  // namespace

World::World(WorldOptions options) : options_(options) {
  if (!(options_.timestep > 0.0) || !std::isfinite(options_.timestep))
    throw InvalidInput("DEM world: timestep must be positive, got " +
                       std::to_string(options_.timestep));
  if (!(options_.skin >= 0.0) || !std::isfinite(options_.skin))
    throw InvalidInput("DEM world: skin must be non-negative, got " +
                       std::to_string(options_.skin));
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
  body.orientation.normalize();
  bodies_.push_back(std::move(body));
  sphere_world_.resize(sphere_body_.size());
  dirty_ = true;
  return index;
}

int World::add_wall(const Wall& wall) {
  walls_.push_back(wall);
  return static_cast<int>(walls_.size()) - 1;
}

void World::update_sphere_positions() {
  parallel_items(sphere_body_.size(), [&](std::size_t k) {
    const Body& b = bodies_[sphere_body_[k]];
    sphere_world_[k] = b.position + b.orientation * sphere_local_[k];
  });
}

bool World::need_rebuild() const {
  if (dirty_ || sphere_at_build_.size() != sphere_world_.size()) return true;
  const double limit = 0.25 * options_.skin * options_.skin;  // (skin/2)²
  for (std::size_t k = 0; k < sphere_world_.size(); ++k)
    if ((sphere_world_[k] - sphere_at_build_[k]).squaredNorm() > limit) return true;
  return false;
}

void World::build_neighbours() {
  ++builds_;
  dirty_ = false;
  sphere_at_build_ = sphere_world_;
  candidates_.clear();
  const std::size_t n = sphere_world_.size();
  if (n < 2) return;

  // Cell size ≥ largest diameter + skin, so every candidate lies in the 27 surrounding cells.
  double h = options_.skin;
  Vec3 lo = sphere_world_[0], hi = sphere_world_[0];
  for (std::size_t k = 0; k < n; ++k) {
    lo = lo.cwiseMin(sphere_world_[k]);
    hi = hi.cwiseMax(sphere_world_[k]);
  }
  h += 2.0 * *std::max_element(sphere_radius_.begin(), sphere_radius_.end());
  std::int64_t dims[3];
  for (;;) {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a) {
      dims[a] = static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / h)) + 1;
      cells *= static_cast<double>(dims[a]);
    }
    if (cells < 1e15) break;
    h *= 2.0;  // keep linear cell keys inside 64 bits for very sparse worlds
  }
  auto cell_of = [&](const Vec3& x, int a) {
    return std::min<std::int64_t>(static_cast<std::int64_t>(std::floor((x[a] - lo[a]) / h)),
                                  dims[a] - 1);
  };
  auto key_of = [&](std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    return (cx * dims[1] + cy) * dims[2] + cz;
  };

  // Spheres sorted by (cell key, index): a deterministic, locality-friendly order.
  std::vector<std::pair<std::int64_t, int>> keyed(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& x = sphere_world_[k];
    keyed[k] = {key_of(cell_of(x, 0), cell_of(x, 1), cell_of(x, 2)), static_cast<int>(k)};
  }
  std::sort(keyed.begin(), keyed.end());

  std::vector<std::vector<int>> partners(n);
  parallel_items(n, [&](std::size_t i) {
    const Vec3& x = sphere_world_[i];
    const std::int64_t c[3] = {cell_of(x, 0), cell_of(x, 1), cell_of(x, 2)};
    std::vector<int>& out = partners[i];
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const std::int64_t cx = c[0] + dx, cy = c[1] + dy, cz = c[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= dims[0] || cy >= dims[1] || cz >= dims[2])
            continue;
          const std::int64_t key = key_of(cx, cy, cz);
          auto first = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(key, -1));
          for (auto it = first; it != keyed.end() && it->first == key; ++it) {
            const int j = it->second;
            if (j <= static_cast<int>(i) || sphere_body_[j] == sphere_body_[i]) continue;
            const double reach = sphere_radius_[i] + sphere_radius_[j] + options_.skin;
            if ((sphere_world_[j] - x).squaredNorm() < reach * reach) out.push_back(j);
          }
        }
    std::sort(out.begin(), out.end());
  });
  for (std::size_t i = 0; i < n; ++i)
    for (int j : partners[i]) candidates_.emplace_back(static_cast<int>(i), j);
}

void World::compute_forces() {
  const double dt = options_.timestep;
  const ContactParams& p = options_.contact;

  // Pair contacts: geometry per candidate (parallel, own slots), then the new sorted contact
  // list merged with the old one (both sorted by (i, j)) to carry the shear history.
  std::vector<double> overlap(candidates_.size());
  parallel_items(candidates_.size(), [&](std::size_t k) {
    const auto [i, j] = candidates_[k];
    overlap[k] =
        sphere_radius_[i] + sphere_radius_[j] - (sphere_world_[j] - sphere_world_[i]).norm();
  });
  std::vector<PairContact> next;
  std::size_t old = 0;
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    if (!(overlap[k] > 0.0)) continue;
    PairContact c;
    c.i = candidates_[k].first;
    c.j = candidates_[k].second;
    while (old < contacts_.size() &&
           std::make_pair(contacts_[old].i, contacts_[old].j) < candidates_[k])
      ++old;
    if (old < contacts_.size() && contacts_[old].i == c.i && contacts_[old].j == c.j)
      c.state = contacts_[old].state;  // existing contact: keep its shear history
    next.push_back(c);
  }
  contacts_ = std::move(next);

  parallel_items(contacts_.size(), [&](std::size_t k) {
    PairContact& c = contacts_[k];
    const Body& a = bodies_[sphere_body_[c.i]];
    const Body& b = bodies_[sphere_body_[c.j]];
    const Vec3 d = sphere_world_[c.j] - sphere_world_[c.i];
    const double dist = d.norm();
    const Vec3 n = dist > 0.0 ? Vec3(d / dist) : Vec3(Vec3::UnitZ());
    const double delta = sphere_radius_[c.i] + sphere_radius_[c.j] - dist;
    const Vec3 point = sphere_world_[c.i] + (sphere_radius_[c.i] - 0.5 * delta) * n;
    const Vec3 va = a.velocity + a.angular_velocity.cross(point - a.position);
    const Vec3 vb = b.velocity + b.angular_velocity.cross(point - b.position);
    const double m_eff = a.mass * b.mass / (a.mass + b.mass);
    update_contact(c.state, n, delta, point, vb - va, m_eff, p, dt);
  });

  // Wall contacts, enumerated in (sphere, wall) order and merged with the old list likewise.
  std::vector<WallContact> next_wall;
  std::size_t old_wall = 0;
  for (int s = 0; s < sphere_count(); ++s)
    for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
      const WallHit hit = wall_hit(walls_[w], sphere_world_[s], sphere_radius_[s]);
      if (!hit.touching) continue;
      WallContact c;
      c.sphere = s;
      c.wall = w;
      while (old_wall < wall_contacts_.size() &&
             std::make_pair(wall_contacts_[old_wall].sphere, wall_contacts_[old_wall].wall) <
                 std::make_pair(s, w))
        ++old_wall;
      if (old_wall < wall_contacts_.size() && wall_contacts_[old_wall].sphere == s &&
          wall_contacts_[old_wall].wall == w)
        c.state = wall_contacts_[old_wall].state;
      const Body& b = bodies_[sphere_body_[s]];
      const Vec3 vb = b.velocity + b.angular_velocity.cross(hit.point - b.position);
      const Vec3 vw = walls_[w].kind == Wall::Kind::plane ? walls_[w].velocity : Vec3::Zero();
      update_contact(c.state, hit.normal, hit.overlap, hit.point, vb - vw, b.mass, p, dt);
      next_wall.push_back(c);
    }
  wall_contacts_ = std::move(next_wall);

  // Sums in fixed order: gravity, pair contacts in (i, j) order, wall contacts.
  for (Body& b : bodies_) {
    b.force = b.mass * options_.gravity;
    b.torque = Vec3::Zero();
  }
  for (const PairContact& c : contacts_) {
    const Vec3 f = c.state.force();
    Body& a = bodies_[sphere_body_[c.i]];
    Body& b = bodies_[sphere_body_[c.j]];
    b.force += f;
    b.torque += (c.state.point - b.position).cross(f);
    a.force -= f;
    a.torque -= (c.state.point - a.position).cross(f);
  }
  for (const WallContact& c : wall_contacts_) {
    const Vec3 f = c.state.force();
    Body& b = bodies_[sphere_body_[c.sphere]];
    b.force += f;
    b.torque += (c.state.point - b.position).cross(f);
  }
}

void World::integrate() {
  const double dt = options_.timestep;
  const double alpha = options_.contact.local_damping;
  parallel_items(bodies_.size(), [&](std::size_t k) {
    Body& b = bodies_[k];
    const Vec3 f = local_damping(b.force, b.velocity, alpha);
    b.velocity += f * (dt / b.mass);
    b.position += b.velocity * dt;
    if (b.rotation_locked) return;
    const Vec3 t = local_damping(b.torque, b.angular_velocity, alpha);
    const Vec3 momentum = b.angular_momentum() + t * dt;
    const Eigen::Quaterniond q0 = b.orientation;
    // Explicit midpoint for dq/dt = ½ ω ⊗ q with ω = ω(q, L) and L constant over the step.
    Vec3 omega = b.angular_velocity_for(momentum, q0);
    for (int pass = 0; pass < 3; ++pass) {
      const Eigen::Quaterniond half = (rotation_quaternion(0.5 * dt * omega) * q0).normalized();
      omega = b.angular_velocity_for(momentum, half);
    }
    b.orientation = (rotation_quaternion(dt * omega) * q0).normalized();
    b.angular_velocity = b.angular_velocity_for(momentum, b.orientation);
  });
  for (Wall& w : walls_)
    if (w.kind == Wall::Kind::plane) w.point += w.velocity * dt;
}

void World::step(int count) {
  for (int s = 0; s < count; ++s) {
    update_sphere_positions();
    if (need_rebuild()) build_neighbours();
    compute_forces();
    integrate();
    time_ += options_.timestep;
    ++steps_;
  }
  update_sphere_positions();
}

void World::rescale_friction(double new_friction) {
  if (!(new_friction >= 0.0) || !std::isfinite(new_friction))
    throw InvalidInput("DEM world: friction must be non-negative, got " +
                       std::to_string(new_friction));
  options_.contact.friction = new_friction;
  for (PairContact& c : contacts_) dem::rescale_friction(c.state, new_friction);
  for (WallContact& c : wall_contacts_) dem::rescale_friction(c.state, new_friction);
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
