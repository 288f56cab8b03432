// The distance field: sign from row parity against an independent ray vote, exact distances in
// the band, the feature-transformed interior never below and seldom far above the truth, and a
// finer tessellation of the same shape giving the same field.
#include "geom/fill/distance_field.h"
#include "geom/mesh/mesh_index.h"
#include "geom/mesh/ray_inside.h"
#include "geom/random.h"
#include "geom/shapes/block.h"
#include "geom/shapes/primitives.h"

#include <tbb/global_control.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

TEST(DistanceField, SignBandAndInteriorAgainstExactQueries) {
  Rng rng(1);
  const Mesh block = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  const Mesh ellipsoid = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 5);
  for (const Mesh* m : {&block, &ellipsoid}) {
    const MeshIndex index(*m);
    const RayInside rays(*m);
    FieldOptions o;
    o.voxels = 24;
    const DistanceField f = make_distance_field(index, o);
    double mean_excess = 0.0;
    long inside = 0;
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) {
          const Vec3 p = f.position(i, j, k);
          const float v = f.at(i, j, k);
          const double exact = index.distance(p);
          if (exact > 1e-6 * f.h) {
            ASSERT_EQ(v > 0.0f, rays.inside(p)) << i << " " << j << " " << k;
          }
          if (v <= 0.0f) continue;
          ++inside;
          // Never below the truth (a distance to a real triangle), within a voxel above it, and
          // exact (float rounding) at the surface voxels (a face neighbour outside).
          EXPECT_GE(v, exact * (1 - 1e-6) - 1e-6 * f.h);
          EXPECT_LE(v, exact + 1.0 * f.h);
          const bool surface = f.at(i - 1, j, k) <= 0 || f.at(i + 1, j, k) <= 0 ||
                               f.at(i, j - 1, k) <= 0 || f.at(i, j + 1, k) <= 0 ||
                               f.at(i, j, k - 1) <= 0 || f.at(i, j, k + 1) <= 0;
          if (surface) {
            EXPECT_NEAR(v, exact, 1e-5 * f.h + 1e-6 * exact);
          }
          mean_excess += v - exact;
          // The feature distance through a point is bounded the same way.
          const Vec3 q = p + 0.37 * f.h * Vec3(1, -1, 1).normalized();
          const double fq = feature_distance(f, *m, q), eq = index.distance(q);
          EXPECT_GE(fq, eq * (1 - 1e-9) - 1e-9 * f.h);
        }
    ASSERT_GT(inside, 1000);
    EXPECT_LT(mean_excess / inside, 0.05 * f.h);
  }
}

TEST(DistanceField, SameShapeFinerTessellationSameField) {
  // An icosphere at level 3 and 6 (1,280 and 81,920 triangles) are the same sphere up to the
  // facets' sagitta (level 3: 0.5 %, level 6: 0.01 % of the radius): the fields agree to that.
  FieldOptions o;
  o.voxel_size = 0.1;
  const Mesh coarse = make_icosphere(3), fine = make_icosphere(6);
  const DistanceField a = make_distance_field(coarse, o), b = make_distance_field(fine, o);
  ASSERT_EQ(a.dims, b.dims);
  double worst = 0.0;
  for (std::size_t q = 0; q < a.d.size(); ++q)
    if (a.d[q] > 0.0f && b.d[q] > 0.0f) worst = std::max(worst, double(std::abs(a.d[q] - b.d[q])));
  // The level-3 sagitta (0.005) and the feature transform's excess of up to 0.3 voxel where the
  // facets are smaller than a voxel (measured 0.026 here; a field taken from the facets' count
  // would differ by their spacing, 0.15).
  EXPECT_LT(worst, 0.005 + 0.3 * o.voxel_size);
}

TEST(DistanceField, SameResultsOnOneAndTwoThreads) {
  const Mesh e = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 4);
  FieldOptions o;
  const DistanceField a = make_distance_field(e, o);
  DistanceField b;
  {
    tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    b = make_distance_field(e, o);
  }
  DistanceField c;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    c = make_distance_field(e, o);
  }
  EXPECT_EQ(b.d, c.d);
  EXPECT_EQ(b.feature, c.feature);
  EXPECT_EQ(a.d, c.d);
}

// The fill's finer lattice: distances from a coarser field's features. Its sign is the full
// field's at that voxel; its values are exact distances to real triangles, never below the truth
// and within a voxel of the full field's, and the count voxel alone never refines the distances.
TEST(DistanceField, FinerLatticeFromACoarseFieldsFeatures) {
  Rng rng(3);
  const Mesh block = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  const MeshIndex index(block);
  FieldOptions coarse_options;
  coarse_options.voxels = 24;
  FieldOptions fine_options = coarse_options;
  fine_options.count_voxel = 1e-9;  // as fine as kCountVoxelGrowth allows
  const DistanceField coarse = make_distance_field(index, fine_options);
  EXPECT_EQ(coarse.h, distance_voxel_size(block, coarse_options));
  const DistanceField finer = make_finer_field(index, coarse, fine_options);
  EXPECT_NEAR(finer.h, coarse.h / std::cbrt(kCountVoxelGrowth), 1e-12 * coarse.h);
  FieldOptions full_options = coarse_options;
  full_options.voxel_size = finer.h;
  const DistanceField full = make_distance_field(index, full_options);
  ASSERT_EQ(full.dims, finer.dims);
  double worst = 0.0;
  for (std::size_t q = 0; q < full.d.size(); ++q) {
    ASSERT_EQ(full.d[q] > 0.0f, finer.d[q] > 0.0f) << q;
    if (!(finer.d[q] > 0.0f)) continue;
    const int i = int(q % full.dims[0]), j = int(q / full.dims[0] % full.dims[1]),
              k = int(q / (std::size_t(full.dims[0]) * full.dims[1]));
    const double exact = index.distance(full.position(i, j, k));
    EXPECT_GE(finer.d[q], exact * (1 - 1e-6) - 1e-9) << q;
    worst = std::max(worst, std::abs(double(finer.d[q]) - double(full.d[q])));
  }
  EXPECT_LT(worst, finer.h);
}
