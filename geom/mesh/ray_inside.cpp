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
  for (const auto& d : m.dirs) {
    int crossings = 0;
    float tnear = 0.0f;
    for (int guard = 0; guard < 10000; ++guard) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRayHit rh{};
      rh.ray.org_x = float(o.x());
      rh.ray.org_y = float(o.y());
      rh.ray.org_z = float(o.z());
      rh.ray.dir_x = float(d.x());
      rh.ray.dir_y = float(d.y());
      rh.ray.dir_z = float(d.z());
      rh.ray.tnear = tnear;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = 0xFFFFFFFFu;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(m.embree->scene, &ctx, &rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
      ++crossings;
      // Step past this hit: a relative epsilon, since the hit distance is a float.
      tnear = std::nextafter(rh.ray.tfar, std::numeric_limits<float>::infinity()) * (1.0f + 1e-6f) +
              1e-7f;
    }
    odd += crossings & 1;
  }
  return odd / 7.0;
}

}  // namespace clumpkit
