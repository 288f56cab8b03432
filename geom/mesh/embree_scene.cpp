#include "geom/mesh/embree_scene.h"

#include "geom/errors.h"

#include <tbb/task_arena.h>

#include <cmath>
#include <limits>

namespace clumpkit {

EmbreeScene::EmbreeScene(const Mesh& mesh, const Vec3& shift, bool robust) {
  // No "threads=N" in the device's configuration: with TBB tasking Embree enforces it by a
  // process-wide tbb::global_control while the device lives, which held every parallel loop of
  // the program (the distance field, the renderer) to one thread. The build runs in an arena of
  // one thread instead, so the tree, and the hit reported where two triangles tie, are the same
  // whatever the thread count.
  device = rtcNewDevice(nullptr);
  if (!device) throw NumericError("Embree: cannot create a device");
  scene = rtcNewScene(device);
  // Compact leaves (indices, not copies of the corners): a tenth less build time and a fifth
  // less peak memory on a 1.3·10⁶-triangle scan, the same hits.
  const int flags = RTC_SCENE_FLAG_COMPACT | (robust ? RTC_SCENE_FLAG_ROBUST : 0);
  rtcSetSceneFlags(scene, static_cast<RTCSceneFlags>(flags));
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(mesh.vertices[i][k] - shift[k]);
  auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) t[3 * i + k] = static_cast<unsigned>(mesh.triangles[i][k]);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  tbb::task_arena(1).execute([&] { rtcCommitScene(scene); });
}

EmbreeScene::~EmbreeScene() {
  if (scene) rtcReleaseScene(scene);
  if (device) rtcReleaseDevice(device);
}

RayHit first_hit(RTCScene scene, const float origin[3], const float dir[3], float tnear) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = origin[0];
  rh.ray.org_y = origin[1];
  rh.ray.org_z = origin[2];
  rh.ray.dir_x = dir[0];
  rh.ray.dir_y = dir[1];
  rh.ray.dir_z = dir[2];
  rh.ray.tnear = tnear;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return RayHit{};
  return RayHit{
      rh.ray.tfar, static_cast<int>(rh.hit.primID), {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z}};
}

float step_past(float t) {
  return std::nextafter(t, std::numeric_limits<float>::infinity()) * (1.0f + 1e-6f) + 1e-7f;
}

}  // namespace clumpkit
