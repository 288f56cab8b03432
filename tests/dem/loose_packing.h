// Test fixture: a loose cubic lattice of spheres in a cuboid test cell, copyable at scale λ.
#pragma once

#include "dem/core/body.h"
#include "dem/core/contact.h"
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "dem/lab/cell.h"
#include "geom/random.h"

#include <cmath>

namespace clumpkit::dem::test {

/// n³-ish spheres (nx × ny × nz) of radii uniform in [0.8, 1]·r0 on a jittered lattice of
/// spacing 2.2·r0, the box one spacing wider than the lattice; gravity off, μ = 0.5, local
/// damping 0.3. Everything of length is multiplied by `lambda` (radii, positions, skin), kn by
/// `lambda` unless linear scaling does it through the diameters, dt by `lambda`; so a run at λ
/// is the run at 1 seen at a λ-times larger scale (CTGU 2017 eqs. 1–3).
struct LoosePacking {
  World world;
  TestCell cell;
  double dt = 0;
};

inline LoosePacking loose_packing(int nx, int ny, int nz, double lambda, bool linear,
                                  std::uint64_t seed = 7) {
  const double r0 = 1e-3, density = 2650.0, spacing = 2.2 * r0;
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.skin = 0.2 * r0 * lambda;
  o.contact.friction = 0.5;
  o.contact.local_damping = 0.3;
  o.contact.ks = 0.5e5;
  if (linear) {
    o.contact.scaling = StiffnessScaling::linear;
    o.contact.kn = 1e5;  // kn_ref at d_ref
    o.contact.d_ref = 2e-3;
  } else {
    o.contact.kn = 1e5 * lambda;
    o.contact.ks *= lambda;
  }
  LoosePacking p{World(o), {}, 0.0};
  Rng rng(seed);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double r = rng.uniform(0.8, 1.0) * r0;
        const Vec3 jitter = rng.uniform(Vec3::Constant(-0.05), Vec3::Constant(0.05));
        const Vec3 x = (Vec3(i + 1, j + 1, k + 1) + jitter) * spacing;
        p.world.add_body(make_sphere_body(x * lambda, r * lambda, density));
      }
  p.cell =
      add_cuboid_test_cell(p.world, Vec3::Zero(), Vec3(nx + 1, ny + 1, nz + 1) * spacing * lambda);
  // The step of the unscaled packing (0.2·sqrt(m_min/k_max), k_max the stiffest wall contact
  // of either law), times λ: a power of two keeps it exact.
  const double m_min = density * 4.0 / 3.0 * 3.14159265358979323846 * std::pow(0.8 * r0, 3);
  p.dt = 0.2 * std::sqrt(m_min / 2e5) * lambda;
  p.world.options().timestep = p.dt;
  return p;
}

}  // namespace clumpkit::dem::test
