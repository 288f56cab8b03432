#include "geom/mesh/embree_scene.h"

#include "geom/errors.h"

namespace clumpkit {

EmbreeScene::EmbreeScene(const Mesh& mesh, const Vec3& shift, bool robust) {
  device = rtcNewDevice("threads=1");
  if (!device) throw NumericError("Embree: cannot create a device");
  scene = rtcNewScene(device);
  if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
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
  rtcCommitScene(scene);
}

EmbreeScene::~EmbreeScene() {
  if (scene) rtcReleaseScene(scene);
  if (device) rtcReleaseDevice(device);
}

}  // namespace clumpkit
