// The fidelity report's volume measure against analytic volumes.
#include "geom/fill/fidelity.h"

#include "geom/shapes/primitives.h"
#include "geom/sphere.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

// The report takes the clump's volume from its power diagram (exact) and the part outside the
// mesh from rows. Disjoint balls of 0.7 row spacings above a unit cube (wholly outside), on a
// lattice of two spacings whose points lie midway between the rows a regular lattice would have
// there (as a fill's spheres sit on its voxel lattice, in phase with rows at the voxel): such
// rows pass 0.707 spacings from every centre, read nothing outside and so the balls as covering
// the cube. The report's jittered rows read their whole volume, N·4/3·π·r³, outside, within the
// error of one sample per cell over the 576 cells the balls reach (−10 % here; regular rows:
// −100 %).
TEST(Fidelity, BallsInPhaseWithARowLatticeReadTheirVolume) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  const double s = 0.02, r = 0.7 * s;
  Clump clump;
  for (int a = 0; a < 2; ++a)  // along the rows: the same rows, so two are enough
    for (int b = 0; b < 24; ++b)
      for (int c = 26; c < 32; ++c)  // z from 0.56 up: above the cube's top face at 0.5
        clump.spheres.push_back(Sphere{
            Vec3(-0.2 + 0.4 * a, -0.5 + (1.0012345 + 2 * b) * s, -0.5 + (0.9987654 + 2 * c) * s),
            r});
  const double balls = clump.spheres.size() * 4.0 / 3.0 * kPi * r * r * r;
  const Fidelity f = assess_fidelity(cube, clump, s);
  EXPECT_NEAR(f.overshoot_fraction, balls, 0.15 * balls);
  EXPECT_NEAR(f.covered_fraction, 0.0, 0.15 * balls);
}

// The volumes alone are the full report's volumes, to the bit, and leave the rest at 0.
TEST(Fidelity, VolumesAloneAreTheFullReportsVolumes) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  Clump clump;
  clump.spheres = {Sphere{Vec3(0, 0, 0), 0.5}, Sphere{Vec3(0.3, 0.3, 0.3), 0.25}};
  const Fidelity full = assess_fidelity(cube, clump, 0.03),
                 volumes = assess_volumes(cube, clump, 0.03);
  EXPECT_EQ(volumes.mesh_volume, full.mesh_volume);
  EXPECT_EQ(volumes.clump_volume, full.clump_volume);
  EXPECT_EQ(volumes.covered_fraction, full.covered_fraction);
  EXPECT_EQ(volumes.overshoot_fraction, full.overshoot_fraction);
  EXPECT_GT(full.overshoot_fraction, 0.0);  // the second sphere reaches past the corner's faces
  EXPECT_GT(full.surface_mean_distance, 0.0);
  EXPECT_EQ(volumes.surface_mean_distance, 0.0);
}
