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

/// One hit along a ray: the distance along `dir` and the triangle, or triangle -1 for none.
struct RayHit {
  float t = 0.0f;
  int triangle = -1;
};

/// The first hit of the ray `origin + t dir` with t ≥ `tnear` (shifted float coordinates).
RayHit first_hit(const EmbreeScene& s, const float origin[3], const float dir[3], float tnear);

/// The tnear that steps past a hit at `t`: a relative epsilon, since the hit distance is a
/// float, so the other triangles of an edge or vertex the ray went through do not count again.
float step_past(float t);

}  // namespace clumpkit
