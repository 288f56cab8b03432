// An Embree scene of one triangle mesh, in float coordinates relative to a shift (internal to
// geom/mesh: MeshIndex and RayInside share it).
#pragma once

#include "geom/mesh/mesh.h"

#include <embree3/rtcore.h>

namespace clumpkit {

/// Owns an Embree device and a committed scene holding `mesh` (vertices minus `shift`, in
/// float), built single-threaded; `robust` asks Embree for watertight ray traversal.
struct EmbreeScene {
  EmbreeScene(const Mesh& mesh, const Vec3& shift, bool robust);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

}  // namespace clumpkit
