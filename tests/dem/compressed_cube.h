// Test fixture: a 5 d cube of about 130 spheres of 10 mm compressed to n = 0.42 (kn ∝ d), and its
// bodies in a cuboid test cell as the test jobs set it up — the specimen of the element-test and
// CPT tests.
#pragma once

#include "dem/core/timestep.h"
#include "dem/lab/element_loading.h"
#include "dem/specimen/compression.h"

namespace clumpkit::dem::test {

/// Built once per test process (a static).
inline const CompressionResult& compressed_cube() {
  static const CompressionResult c = [] {
    CompressionSpec s;
    s.size = Vec3::Constant(0.05);
    s.porosity = 0.42;
    s.classes = {{0.0099, 0.0101, 100.0, false}};
    s.contact.kn = 8e7;
    s.contact.ks = 8e5;
    s.contact.friction = 0.5;
    s.contact.local_damping = 0.7;  // as specimens have it: equilibrium in few steps
    s.contact.scaling = StiffnessScaling::linear;
    s.contact.d_ref = 0.01;
    s.loose_factor = 1.25;
    s.strain_per_step = 2e-5;
    s.relax_max_steps = 2000;
    s.seed = 7;
    return compress_specimen(s);
  }();
  return c;
}

/// The cube's bodies in a fresh world with the element-test options inside a cuboid test cell
/// (0.2 of the critical step).
inline CellSpecimen cube_in_cell() {
  const CompressionResult& c = compressed_cube();
  CellSpecimen s{World(element_test_world_options(c.world.bodies(), c.world.options().contact)),
                 {}};
  for (const Body& b : c.world.bodies()) s.world.add_body(b);
  s.cell = add_cuboid_test_cell(s.world, c.lo, c.hi);
  s.world.options().timestep = 0.2 * critical_timestep(s.world);
  return s;
}

}  // namespace clumpkit::dem::test
