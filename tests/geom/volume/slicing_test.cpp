#include "geom/volume/slicing.h"

#include "geom/errors.h"
#include "geom/sphere.h"
#include "geom/volume/pixel_slicing.h"
#include "geom/volume/voxel_volume.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {
namespace {

// ---- 2-D references ----

// Area of the lens where two disks at distance d overlap (0 < |r1 − r2| < d < r1 + r2):
// r1² acos((d² + r1² − r2²)/(2 d r1)) + r2² acos((d² + r2² − r1²)/(2 d r2))
//   − ½ √((−d + r1 + r2)(d + r1 − r2)(d − r1 + r2)(d + r1 + r2)).
double lens_area(double r1, double r2, double d) {
  return r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
         r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
         0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
}

// Moments of one disk: A = πr², ∫x = A·x, ∫x² = A·x² + πr⁴/4, ∫xy = A·x·y.
SliceMoments disk_moments(const Disk& d) {
  const double a = M_PI * d.r * d.r, j = M_PI * d.r * d.r * d.r * d.r / 4;
  return {a, a * d.x, a * d.y, a * d.x * d.x + j, a * d.y * d.y + j, a * d.x * d.y};
}

// Independent reference: midpoint rule over n horizontal strips; on each strip line the union
// of the disks' chords is merged and x⁰, x¹, x² are integrated exactly. Holes come out right
// because only covered chords are integrated. Error O(n^-1.5) from the disk tops.
SliceMoments strip_moments(const std::vector<Disk>& disks, int n) {
  double ylo = 1e300, yhi = -1e300;
  for (const Disk& d : disks) {
    ylo = std::min(ylo, d.y - d.r);
    yhi = std::max(yhi, d.y + d.r);
  }
  const double h = (yhi - ylo) / n;
  SliceMoments m;
  std::vector<std::pair<double, double>> chords;
  for (int k = 0; k < n; ++k) {
    const double y = ylo + (k + 0.5) * h;
    chords.clear();
    for (const Disk& d : disks) {
      const double dy = y - d.y;
      if (std::abs(dy) < d.r) {
        const double w = std::sqrt(d.r * d.r - dy * dy);
        chords.emplace_back(d.x - w, d.x + w);
      }
    }
    std::sort(chords.begin(), chords.end());
    double l0 = 0, l1 = 0, l2 = 0;
    for (std::size_t i = 0; i < chords.size();) {
      double a = chords[i].first, b = chords[i].second;
      for (++i; i < chords.size() && chords[i].first <= b; ++i) b = std::max(b, chords[i].second);
      l0 += b - a;
      l1 += (b * b - a * a) / 2;
      l2 += (b * b * b - a * a * a) / 3;
    }
    m.area += h * l0;
    m.mx += h * l1;
    m.my += h * y * l0;
    m.mxx += h * l2;
    m.myy += h * y * y * l0;
    m.mxy += h * y * l1;
  }
  return m;
}

void expect_moments_near(const SliceMoments& got, const SliceMoments& want, double tol) {
  EXPECT_NEAR(got.area, want.area, tol);
  EXPECT_NEAR(got.mx, want.mx, tol);
  EXPECT_NEAR(got.my, want.my, tol);
  EXPECT_NEAR(got.mxx, want.mxx, tol);
  EXPECT_NEAR(got.myy, want.myy, tol);
  EXPECT_NEAR(got.mxy, want.mxy, tol);
}

// Seeded uniform in [a, b) from raw 53-bit output (no std:: distributions: their output differs
// between standard libraries).
struct Uniform {
  std::mt19937_64 gen;
  explicit Uniform(std::uint64_t seed) : gen(seed) {}
  double operator()(double a, double b) {
    return a + (b - a) * static_cast<double>(gen() >> 11) * 0x1.0p-53;
  }
};

// ---- union_of_disks ----

TEST(UnionOfDisks, OneDiskAllMoments) {
  const Disk d{1.25, -0.5, 2.0};
  expect_moments_near(union_of_disks({d}), disk_moments(d), 1e-13);
}

TEST(UnionOfDisks, EmptyAndZeroRadius) {
  EXPECT_EQ(union_of_disks({}).area, 0.0);
  EXPECT_EQ(union_of_disks({{1, 2, 0}, {3, 4, -1}}).area, 0.0);
  EXPECT_THROW(union_of_disks({{std::nan(""), 0, 1}}), InvalidInput);
}

TEST(UnionOfDisks, TwoOverlappingDisksLensClosedForm) {
  // Union area = πr1² + πr2² − lens; for equal disks the centroid is the midpoint.
  const double r1 = 1.0, r2 = 0.7, d = 1.1;
  const SliceMoments m = union_of_disks({{0, 0, r1}, {d, 0, r2}});
  EXPECT_NEAR(m.area, M_PI * (r1 * r1 + r2 * r2) - lens_area(r1, r2, d), 1e-14);
  const SliceMoments e = union_of_disks({{-0.3, 0.2, 1.0}, {0.9, 0.2, 1.0}});
  EXPECT_NEAR(e.area, 2 * M_PI - lens_area(1.0, 1.0, 1.2), 1e-14);
  EXPECT_NEAR(e.mx / e.area, 0.3, 1e-14);
  EXPECT_NEAR(e.my / e.area, 0.2, 1e-14);
  // All six moments against the strip reference, rotated off the axes.
  const std::vector<Disk> tilted = {{0.1, -0.2, 1.0}, {0.8, 0.5, 0.6}};
  expect_moments_near(union_of_disks(tilted), strip_moments(tilted, 200000), 2e-7);
}

TEST(UnionOfDisks, NestedDuplicateAndTangentDisks) {
  const Disk big{0.5, 0.25, 1.0};
  const SliceMoments one = disk_moments(big);
  expect_moments_near(union_of_disks({big, {0.8, 0.25, 0.5}}), one, 1e-13);  // nested
  expect_moments_near(union_of_disks({{0.8, 0.25, 0.5}, big}), one, 1e-13);  // nested, 1st
  expect_moments_near(union_of_disks({big, {1.0, 0.25, 0.5}}), one, 1e-13);  // internally tangent
  expect_moments_near(union_of_disks({big, big, big}), one, 1e-13);          // duplicates
  // Externally tangent: the two disks simply add.
  const Disk small{2.0, 0.25, 0.5};
  SliceMoments sum = disk_moments(big), s = disk_moments(small);
  sum.area += s.area, sum.mx += s.mx, sum.my += s.my;
  sum.mxx += s.mxx, sum.myy += s.myy, sum.mxy += s.mxy;
  expect_moments_near(union_of_disks({big, small}), sum, 1e-13);
}

TEST(UnionOfDisks, RingOfDisksEnclosingAHole) {
  // Six unit disks on a circle of radius 1.5: neighbours (1.5 apart) overlap, the others
  // (≥ 2.6 apart) do not, so by inclusion–exclusion the union is 6π − 6·lens(1, 1, 1.5). The
  // centre is uncovered: a hole, a curvilinear hexagon whose corners lie at ρ = 1.5 cos 30° −
  // √(1 − 0.75²) from the centre, of area (3√3/2)ρ² − 6·(θ − sin θ)/2, θ = 2 asin(ρ/2). The
  // boundary-arc method must subtract it (its inner arcs run clockwise about the hole).
  std::vector<Disk> ring;
  for (int k = 0; k < 6; ++k)
    ring.push_back({1.5 * std::cos(k * M_PI / 3), 1.5 * std::sin(k * M_PI / 3), 1.0});
  const double rho = 1.5 * std::cos(M_PI / 6) - std::sqrt(1 - 0.75 * 0.75);
  const double theta = 2 * std::asin(rho / 2);
  const double hole = 1.5 * std::sqrt(3.0) * rho * rho - 3 * (theta - std::sin(theta));
  ASSERT_GT(hole, 0.1);
  const SliceMoments m = union_of_disks(ring);
  EXPECT_NEAR(m.area, 6 * M_PI - 6 * lens_area(1, 1, 1.5), 1e-13);
  EXPECT_NEAR(m.mx, 0, 1e-13);
  EXPECT_NEAR(m.my, 0, 1e-13);
  EXPECT_NEAR(m.mxx, m.myy, 1e-12);  // six-fold symmetry makes the second moment isotropic
  EXPECT_NEAR(m.mxy, 0, 1e-13);
  expect_moments_near(m, strip_moments(ring, 200000), 2e-6);
}

TEST(UnionOfDisks, RandomDisksMatchStripReference) {
  Uniform u(20240611);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Disk> disks;
    for (int i = 0; i < 8; ++i) disks.push_back({u(-2, 2), u(-2, 2), u(0.3, 1.5)});
    expect_moments_near(union_of_disks(disks), strip_moments(disks, 200000), 2e-6);
  }
}

// ---- union_properties_by_slicing: closed-form oracles C1–C11 (as in union_of_balls_test) ----

struct Oracle {
  const char* id;
  std::vector<Sphere> spheres;
  double volume;
  Vec3 centroid;
  Vec3 inertia;  // Ixx, Iyy, Izz; off-diagonals zero
};

std::vector<Oracle> oracles() {
  const double s3 = std::sqrt(3.0);
  auto ball = [](double x, double y, double z, double r) { return Sphere{Vec3(x, y, z), r}; };
  return {
      {"C1", {ball(0, 0, 0, 1)}, 4.188790204786, Vec3(0, 0, 0), Vec3::Constant(1.675516081915)},
      {"C2",
       {ball(0, 0, 0, 1), ball(0, 0, 1, 1)},
       7.068583470577,
       Vec3(0, 0, 0.5),
       Vec3(5.213080309551, 5.213080309551, 3.004147974995)},
      {"C3",
       {ball(0, 0, 0, 1), ball(0, 0, 0.9, 0.5)},
       4.423362456254,
       Vec3(0, 0, 0.058585858586),
       Vec3(1.962313887582, 1.962313887582, 1.700477548166)},
      {"C4",
       {ball(0, 0, 0, 1), ball(0.3, 0, 0, 0.5)},
       4.188790204786,
       Vec3(0, 0, 0),
       Vec3::Constant(1.675516081915)},
      {"C5",
       {ball(0, 0, 0, 1), ball(0.5, 0, 0, 0.5)},
       4.188790204786,
       Vec3(0, 0, 0),
       Vec3::Constant(1.675516081915)},
      {"C6",
       {ball(0, 0, 0, 1), ball(1.5, 0, 0, 0.5)},
       4.712388980385,
       Vec3(1.0 / 6, 0, 0),
       Vec3(1.727875959474, 2.775073510671, 2.775073510671)},
      {"C7",
       {ball(0, 0, 0, 1), ball(0, 0, 0, 1), ball(0, 0, 0, 1)},
       4.188790204786,
       Vec3(0, 0, 0),
       Vec3::Constant(1.675516081915)},
      {"C8",
       {ball(0, 0, 0, 1), ball(1, 0, 0, 1), ball(0.5, s3 / 2, 0, 1)},
       9.311210132578,
       Vec3(0.5, 0.288675134595, 0),
       Vec3(6.191830912793, 6.191830912793, 8.252298437296)},
      {"C9",
       {ball(0, 0, 0, 1), ball(0, 0, 1, 1), ball(0, 0, 2, 1)},
       9.948376736368,
       Vec3(0, 0, 1),
       Vec3(12.284936272475, 12.284936272475, 4.332779868076)},
      {"C10",
       {ball(0, 0, 0, 1), ball(1, 0, 0, 1), ball(0.5, s3 / 2, 0, 1),
        ball(0.5, s3 / 6, std::sqrt(2.0 / 3.0), 1)},
       11.166342792881,
       Vec3(0.5, 0.288675134595, 0.204124145232),
       Vec3::Constant(9.006469356171)},
      {"C11",
       {ball(0, 0, 0, 1), ball(1, 0, 0, 1), ball(0, 1, 0, 1), ball(1, 1, 0, 1),
        ball(0.5, 0.5, 0.5, 1)},
       12.616271200078,
       Vec3(0.5, 0.5, 0.075189969068),
       Vec3(10.23362421673, 10.23362421673, 13.092824144748)},
  };
}

TEST(UnionPropertiesBySlicing, OraclesC1toC11) {
  for (const Oracle& o : oracles()) {
    SCOPED_TRACE(o.id);
    const MassProperties mp = union_properties_by_slicing(Clump{o.spheres});
    EXPECT_NEAR(mp.volume, o.volume, 1e-9 * o.volume);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mp.centroid[i], o.centroid[i], 1e-9);
    const double scale = o.inertia.maxCoeff();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(mp.inertia(i, j), i == j ? o.inertia[i] : 0.0, 1e-9 * scale)
            << "I(" << i << "," << j << ")";
  }
}

TEST(UnionPropertiesBySlicing, ScalingAndRigidMotion) {
  // Volume scales by s³ and inertia by s⁵; a rotation R maps I to R I Rᵀ (C10, s = 7 mm).
  const Oracle c10 = oracles()[9];
  const double s = 7.0;
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(100, -50, 20);
  Clump moved;
  for (const Sphere& b : c10.spheres)
    moved.spheres.push_back({R * (s * b.center) + t, s * b.radius});
  const MassProperties mp = union_properties_by_slicing(moved);
  EXPECT_NEAR(mp.volume, c10.volume * s * s * s, 1e-9 * c10.volume * s * s * s);
  EXPECT_LT((mp.centroid - (R * (s * c10.centroid) + t)).norm(), 1e-9 * s);
  const Mat3 want = std::pow(s, 5) * R * Mat3(c10.inertia.asDiagonal()) * R.transpose();
  EXPECT_LT((mp.inertia - want).cwiseAbs().maxCoeff(), 1e-9 * want.trace());
}

Clump random_balls(int n, std::uint64_t seed) {
  Uniform u(seed);
  Clump c;
  for (int i = 0; i < n; ++i) c.spheres.push_back({Vec3(u(0, 10), u(0, 10), u(0, 10)), u(1, 3)});
  return c;
}

TEST(UnionPropertiesBySlicing, FiftyRandomBallsAgreeWhenSlicedAlongAnotherAxis) {
  // Slicing a rotated copy meets completely different events; both must agree to 1e-9.
  const Clump c = random_balls(50, 7);
  const auto t0 = std::chrono::steady_clock::now();
  const MassProperties a = union_properties_by_slicing(c);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ info ] 50 random balls: V = %.12f, slicing took %.3f s\n", a.volume, seconds);
  const Mat3 R = Eigen::AngleAxisd(1.1, Vec3(-1, 3, 2).normalized()).toRotationMatrix();
  Clump rotated;
  for (const Sphere& b : c.spheres) rotated.spheres.push_back({R * b.center, b.radius});
  const MassProperties b = union_properties_by_slicing(rotated);
  EXPECT_NEAR(b.volume, a.volume, 1e-9 * a.volume);
  EXPECT_LT((b.centroid - R * a.centroid).norm(), 1e-9 * 10);
  const Mat3 want = R * a.inertia * R.transpose();
  EXPECT_LT((b.inertia - want).cwiseAbs().maxCoeff(), 1e-9 * want.trace());
  // Sanity: the union is smaller than the sum of the balls.
  double sum = 0;
  for (const Sphere& s : c.spheres) sum += 4.0 / 3.0 * M_PI * std::pow(s.radius, 3);
  EXPECT_LT(a.volume, sum);
}

TEST(UnionPropertiesBySlicing, RejectsBadSpheres) {
  EXPECT_THROW(union_properties_by_slicing(Clump{}), InvalidInput);
  EXPECT_THROW(union_properties_by_slicing(Clump{{{Vec3(0, 0, 0), -1.0}}}), InvalidInput);
}

// ---- Pixel slicing (Jin et al. 2017 §3, Table 1) ----

const double kSphere7 = 4.0 / 3.0 * M_PI * 343.0;  // 1436.755 mm³ (paper: 1.4367 cm³)

double pixel_error(const Clump& c, PixelRule rule, double exact) {
  PixelSliceOptions opt;
  opt.rule = rule;
  return pixel_slice_volume(c, opt).volume / exact - 1.0;
}

TEST(PixelSlicing, Table1SingleSphereTouchOvercountsCentreDoesNot) {
  // One ball of radius 7 mm, 100 slices across it, pixel = spacing = 0.14 mm. The paper reports
  // 1.4755 cm³ (+2.7 %); the bias comes from counting every pixel the circle touches.
  const Clump c{{{Vec3(0, 0, 0), 7.0}}};
  EXPECT_NEAR(kSphere7, 1436.755, 1e-3);
  PixelSliceOptions opt;
  const PixelSliceResult touch = pixel_slice_volume(c, opt);
  EXPECT_EQ(touch.slices, 100);
  EXPECT_NEAR(touch.spacing, 0.14, 1e-15);
  EXPECT_NEAR(touch.pixel, 0.14, 1e-15);
  ASSERT_EQ(touch.z.size(), 100u);
  const double e_touch = touch.volume / kSphere7 - 1;
  const double e_centre = pixel_error(c, PixelRule::Centre, kSphere7);
  std::printf("[ info ] 7 mm sphere: Touch %+.3f %%, Centre %+.3f %%\n", 100 * e_touch,
              100 * e_centre);
  EXPECT_GT(e_touch, 0.025);
  EXPECT_LT(e_touch, 0.032);
  EXPECT_LT(std::abs(e_centre), 0.003);
  // Per-slice exact areas: π R'², R'² = R² − z² (Jin et al. 2017 eq. 2); their midpoint sum is the
  // slab estimate of the volume, without the pixel bias.
  double slab = 0;
  for (std::size_t k = 0; k < touch.z.size(); ++k) {
    EXPECT_NEAR(touch.exact_area[k], M_PI * (49 - touch.z[k] * touch.z[k]), 1e-10);
    EXPECT_GE(touch.pixel_area[k], touch.exact_area[k]);  // Touch covers every disk
    slab += touch.exact_area[k] * touch.spacing;
  }
  EXPECT_NEAR(slab / kSphere7 - 1, 0, 2e-4);
}

TEST(PixelSlicing, Table1OverlappingSpheresFigures) {
  // The paper's 2- and 3-ball models (smallest radius 7 mm; exact 5.0961 and 9.2326 cm³) are
  // only drawn, not given (not unique either). These chains along x reproduce the printed exact
  // volumes: 7 mm and 10 mm balls 10.003 mm apart (5096.15 mm³; 10 mm apart gives 5095.74 mm³),
  // and 7 mm, 10 mm at 10 mm, and 10 mm a further 18.154 mm on (9232.65 mm³).
  const Clump two{{{Vec3(0, 0, 0), 7.0}, {Vec3(10.003022114627893, 0, 0), 10.0}}};
  const Clump three{{{Vec3(0, 0, 0), 7.0},
                     {Vec3(10.0, 0, 0), 10.0},
                     {Vec3(10.0 + 18.15398847294012, 0, 0), 10.0}}};
  const double v2 = union_properties_by_slicing(two).volume;
  const double v3 = union_properties_by_slicing(three).volume;
  EXPECT_NEAR(v2, 5096.15, 1e-6);
  EXPECT_NEAR(v3, 9232.65, 1e-6);
  const double t2 = pixel_error(two, PixelRule::Touch, v2),
               c2 = pixel_error(two, PixelRule::Centre, v2);
  const double t3 = pixel_error(three, PixelRule::Touch, v3),
               c3 = pixel_error(three, PixelRule::Centre, v3);
  std::printf("[ info ] 2 balls (%.4f cm3): Touch %+.3f %%, Centre %+.3f %%\n", v2 / 1000, 100 * t2,
              100 * c2);
  std::printf("[ info ] 3 balls (%.4f cm3): Touch %+.3f %%, Centre %+.3f %%\n", v3 / 1000, 100 * t3,
              100 * c3);
  // Like Table 1: positive and shrinking as the model grows relative to the slice spacing.
  const double t1 = pixel_error(Clump{{{Vec3(0, 0, 0), 7.0}}}, PixelRule::Touch, kSphere7);
  EXPECT_GT(t2, 0);
  EXPECT_GT(t3, 0);
  EXPECT_LT(t2, t1);
  EXPECT_LT(t3, t2);
  EXPECT_LT(std::abs(c2), 0.003);
  EXPECT_LT(std::abs(c3), 0.003);
}

TEST(PixelSlicing, WritesSliceImagesAndRejectsBadOptions) {
  PixelSliceOptions opt;
  opt.slices_across_smallest = 4;
  int calls = 0;
  double filled = 0;
  opt.on_slice = [&](int k, int w, int h, const std::uint8_t* px) {
    EXPECT_EQ(k, calls++);
    for (int q = 0; q < w * h; ++q) filled += px[q] == 255;
  };
  const PixelSliceResult r = pixel_slice_volume(Clump{{{Vec3(1, 2, 3), 2.0}}}, opt);
  EXPECT_EQ(r.slices, 4);
  EXPECT_EQ(calls, 4);
  // The images hold exactly the counted pixels.
  double counted = 0;
  for (double a : r.pixel_area) counted += a / (r.pixel * r.pixel);
  EXPECT_NEAR(filled, counted, 1e-6);
  opt.on_slice = nullptr;
  opt.slices_across_smallest = 0;
  EXPECT_THROW(pixel_slice_volume(Clump{{{Vec3(0, 0, 0), 1.0}}}, opt), InvalidInput);
  opt.slices_across_smallest = 10;
  opt.pixel = -1;
  EXPECT_THROW(pixel_slice_volume(Clump{{{Vec3(0, 0, 0), 1.0}}}, opt), InvalidInput);
}

// ---- Voxel volume (OpenVDB) ----

TEST(VoxelVolume, ConvergesToExactVolume) {
  // C2 (two unit balls 1 apart), shifted off the grid: both estimates converge as h → 0.
  const Clump c{{{Vec3(0.123, 0.456, 0.789), 1.0}, {Vec3(0.123, 0.456, 1.789), 1.0}}};
  const double exact = 7.068583470577;
  double last = 1e300;
  for (double n : {5.0, 10.0, 20.0, 40.0}) {
    const VoxelVolumeResult r = voxel_volume(c, 1.0 / n);
    const double e_count = r.volume_count / exact - 1, e_ls = r.volume_levelset / exact - 1;
    std::printf("[ info ] voxel h = r/%g: count %+.4f %%, level set %+.4f %%\n", n, 100 * e_count,
                100 * e_ls);
    EXPECT_LT(std::abs(e_ls), last);
    last = std::abs(e_ls);
    if (n >= 20) {
      EXPECT_LT(std::abs(e_count), 0.02);
      EXPECT_LT(std::abs(e_ls), 0.02);
    }
  }
  EXPECT_THROW(voxel_volume(c, 0.0), InvalidInput);
}

}  // namespace
}  // namespace clumpkit
