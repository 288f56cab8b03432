// Shaded orthographic pictures of a clump inside its mesh, by Embree ray casting.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/sphere.h"
#include "io/formats/png.h"

#include <memory>

namespace clumpkit {

/// Holds the Embree scenes of one mesh and one clump and renders square views of them: the
/// spheres opaque, each its own colour, lit from the upper left and darkened with depth; the
/// mesh a translucent veil over them with its silhouette drawn dark and its creases lighter;
/// where a sphere pokes out of the surface it is tinted red. Every view frames the same ball (mesh
/// and spheres), so views of one particle share a scale. Renders are deterministic (each pixel on
/// its own ray) whatever the thread count.
class ClumpRenderer {
 public:
  ClumpRenderer(const Mesh& mesh, const Clump& clump);
  ~ClumpRenderer();
  ClumpRenderer(const ClumpRenderer&) = delete;
  ClumpRenderer& operator=(const ClumpRenderer&) = delete;

  /// A pixels × pixels view looking along `direction` with `up` (not parallel to it) pointing
  /// up the image, on a white background.
  RgbImage render(const Vec3& direction, const Vec3& up, int pixels) const;
  /// The width (and height) every view spans, in mesh units.
  double frame_width() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clumpkit
