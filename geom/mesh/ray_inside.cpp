#include "geom/mesh/ray_inside.h"

#include "geom/errors.h"
#include "geom/mesh/embree_scene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

namespace clumpkit {

struct RayInside::Impl {
  std::unique_ptr<EmbreeScene> embree;
  Vec3 shift = Vec3::Zero();  // Embree works in float: coordinates relative to the box centre
  Vec3 dirs[7];
};

RayInside::RayInside(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const auto bb = bounding_box(mesh);
  m.shift = 0.5 * (bb[0] + bb[1]);
  // Directions with irrational components, so rays avoid mesh edges and vertices in practice.
  const double g = 0.6180339887498949;
  for (int k = 0; k < 7; ++k) {
    const double z = std::fmod(0.1234567 + k * g, 1.0) * 2.0 - 1.0;
    const double phi = 2.0 * M_PI * std::fmod(0.7654321 + k * g * g, 1.0);
    m.dirs[k] = Vec3(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
  }
  m.embree = std::make_unique<EmbreeScene>(mesh, m.shift, false);
}

RayInside::~RayInside() = default;

double RayInside::vote(const Vec3& p) const {
  const Impl& m = *impl_;
  const Vec3 o = p - m.shift;
  int odd = 0;
  const float origin[3] = {float(o.x()), float(o.y()), float(o.z())};
  for (const auto& d : m.dirs) {
    const float dir[3] = {float(d.x()), float(d.y()), float(d.z())};
    int crossings = 0;
    float tnear = 0.0f;
    for (int guard = 0; guard < 10000; ++guard) {
      const RayHit hit = first_hit(m.embree->scene, origin, dir, tnear);
      if (hit.triangle < 0) break;
      ++crossings;
      tnear = step_past(hit.t);
    }
    odd += crossings & 1;
  }
  return odd / 7.0;
}

}  // namespace clumpkit
