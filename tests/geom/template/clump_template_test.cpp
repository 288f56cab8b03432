// Tests of clump templates: principal frame, exact mass properties, pose back to the source.
#include "geom/template/clump_template.h"
#include "geom/volume/union_of_balls.h"

#include <gtest/gtest.h>

using namespace clumpkit;

TEST(ClumpTemplate, PrincipalFrameAndPoseRoundTrip) {
  // Oracle C3 (r=1 at 0, r=0.5 at (0,0,0.9)), rotated and moved.
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(5, -2, 1);
  Clump c{{Sphere{t, 1.0}, Sphere{R * Vec3(0, 0, 0.9) + t, 0.5}}};
  const ClumpTemplate tp = make_clump_template(c, 5.0);
  EXPECT_NEAR(tp.mass.volume, 4.423362456254, 1e-11);
  // Moments ascending: 1.700477548166 (about the symmetry axis), then 1.962313887582 twice.
  EXPECT_NEAR(tp.principal_moments[0], 1.700477548166, 1e-10);
  EXPECT_NEAR(tp.principal_moments[1], 1.962313887582, 1e-10);
  EXPECT_NEAR(tp.principal_moments[2], 1.962313887582, 1e-10);
  EXPECT_NEAR(tp.density_factor, 5.0 / 4.423362456254, 1e-12);
  // Template spheres have centroid 0 and diagonal inertia.
  const UnionProperties u = union_properties(Clump{tp.spheres});
  EXPECT_LT(u.mass.centroid.norm(), 1e-12);
  EXPECT_NEAR(u.mass.inertia(0, 1), 0.0, 1e-10);
  EXPECT_NEAR(u.mass.inertia(0, 2), 0.0, 1e-10);
  EXPECT_NEAR(u.mass.inertia(1, 2), 0.0, 1e-10);
  // The pose maps template spheres back onto the source spheres.
  for (std::size_t i = 0; i < c.spheres.size(); ++i)
    EXPECT_LT((tp.orientation * tp.spheres[i].center + tp.position - c.spheres[i].center).norm(),
              1e-12);
  EXPECT_NEAR(tp.orientation.norm(), 1.0, 1e-15);
}
