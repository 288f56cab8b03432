// Test fixture: the spec of a small crushable specimen — about a dozen 14–18 mm particles of
// 8 mm cells (five to eleven each, four spheres per cell) in a 40 mm cylinder, closed from 1.3
// times its size at 1e-4 strain per step — shared by the crushable compression and oedometer
// tests.
#pragma once

#include "dem/specimen/compression.h"

namespace clumpkit::dem::test {

inline CompressionSpec small_crushable_spec(double porosity) {
  CompressionSpec s;
  s.shape = CompressionSpec::Shape::cylinder;
  s.size = Vec3(0.04, 0.04, 0.04);
  s.porosity = porosity;
  s.classes = {{0.014, 0.018, 100.0, true}};
  s.contact.kn = 1e6;
  s.contact.ks = 1e6;
  s.contact.friction = 0.5;
  s.loose_factor = 1.3;
  s.strain_per_step = 1e-4;
  s.relax_max_steps = 2000;
  s.seed = 5;
  CrushableMaterial m;
  m.cells.cell_size = 0.008;
  m.cells.lloyd = 1;
  m.fill.spheres = 4;
  m.fill.field.voxels = 12;
  m.fill.voxels_from_count = false;
  s.crushable = m;
  return s;
}

}  // namespace clumpkit::dem::test
