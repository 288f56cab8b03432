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

/// One hit along a ray: the distance along `dir`, the primitive (triangle, or sphere of a point
/// scene; -1 for none) and Embree's geometric normal there (not normalized).
struct RayHit {
  float t = 0.0f;
  int triangle = -1;
  float normal[3] = {0.0f, 0.0f, 0.0f};
};

/// The first hit in `scene` of the ray `origin + t dir` with t ≥ `tnear` (the scene's float
/// coordinates).
RayHit first_hit(RTCScene scene, const float origin[3], const float dir[3], float tnear);

/// The tnear that steps past a hit at `t`: a relative epsilon, since the hit distance is a
/// float, so the other triangles of an edge or vertex the ray went through do not count again.
float step_past(float t);

}  // namespace clumpkit
