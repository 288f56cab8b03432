#include "io/reports/render.h"

#include "geom/errors.h"
#include "geom/shapes/primitives.h"
#include "io/formats/png.h"
#include "io/reports/plot.h"
#include "io/reports/views.h"
#include "tests/image_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace clumpkit {
namespace {

namespace fs = std::filesystem;
using test::drawn_pixels;

double drawn_fraction(const RgbImage& im) {
  return double(drawn_pixels(im, 0, 0, im.width, im.height)) / (double(im.width) * im.height);
}

// Pixels tinted red: a sphere cap outside the mesh (red well above green and blue).
long red_pixels(const RgbImage& im) {
  long n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.at(x, y);
      n += p[0] > 150 && p[0] > p[1] + 80 && p[0] > p[2] + 80;
    }
  return n;
}

fs::path scratch() {
  const fs::path d =
      fs::temp_directory_path() /
      ("clumpkit_render_" +
       std::to_string(::testing::UnitTest::GetInstance()->current_test_info()->line()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Orthographic views frame the ball of radius R around mesh and spheres at a half width of
// 1.04 R, so a lone sphere covers π / (4 · 1.04²) of the image from any side, and a cube of side
// s (R = s√3/2) seen along an axis covers a square of side s: 1 / (3 · 1.04²).
TEST(Render, SilhouettesCoverTheirProjectedAreas) {
  const Clump one{{Sphere{Vec3(0.3, -0.2, 0.5), 0.7}}};
  const ClumpRenderer sphere(Mesh{}, one);
  EXPECT_NEAR(sphere.frame_width(), 2 * 1.04 * 0.7, 1e-12);
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(-1.2, 1.0, -0.8)}) {
    const RgbImage im = sphere.render(d, d.z() == 0 ? Vec3(0, 0, 1) : Vec3(0, 1, 0.3), 400);
    ASSERT_EQ(im.width, 400);
    ASSERT_EQ(im.height, 400);
    EXPECT_NEAR(drawn_fraction(im), M_PI / (4 * 1.04 * 1.04), 0.005) << d.transpose();
  }
  const Mesh box = make_box(Vec3(2, 2, 2));
  const ClumpRenderer cube(box, Clump{});
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)})
    EXPECT_NEAR(drawn_fraction(cube.render(d, d.z() == 0 ? Vec3(0, 0, 1) : Vec3(0, 1, 0), 400)),
                1.0 / (3 * 1.04 * 1.04), 0.005)
        << d.transpose();
}

// A sphere inside the cube shows no red; one that pokes out of its faces does, and the same
// scene renders identically twice (each pixel its own ray).
TEST(Render, SphereCapsOutsideTheMeshAreRed) {
  const Mesh box = make_box(Vec3(2, 2, 2));
  const Clump inside{{Sphere{Vec3::Zero(), 0.9}}}, poking{{Sphere{Vec3::Zero(), 1.15}}};
  const Vec3 d(-1.2, 1.0, -0.8), up(0, 0, 1);
  const RgbImage a = ClumpRenderer(box, inside).render(d, up, 300);
  const RgbImage b = ClumpRenderer(box, poking).render(d, up, 300);
  EXPECT_EQ(red_pixels(a), 0);
  EXPECT_GT(red_pixels(b), 300 * 300 / 100);
  EXPECT_EQ(ClumpRenderer(box, poking).render(d, up, 300).pixels, b.pixels);
  EXPECT_THROW(ClumpRenderer(Mesh{}, Clump{}), InvalidInput);
  EXPECT_THROW(ClumpRenderer(box, inside).render(Vec3(0, 0, 1), Vec3(0, 0, 2), 10), InvalidInput);
}

// The particle picture is 2 panels wide and 2 high under a 62-px caption band, every panel has
// a drawing in it; the contact sheet is tiles in rows of ⌈√n⌉, at least 800 px wide.
TEST(Render, ParticlePictureAndContactSheetHaveTheirSizesAndDrawings) {
  const fs::path d = scratch();
  const Mesh box = make_box(Vec3(0.02, 0.012, 0.008));
  const Clump clump{{Sphere{Vec3(-0.004, 0, 0), 0.004}, Sphere{Vec3(0.004, 0, 0), 0.004}}};
  write_particle_png((d / "p.png").string(), box, clump, "test particle", 450);
  const RgbImage p = read_png((d / "p.png").string());
  ASSERT_EQ(p.width, 900);
  ASSERT_EQ(p.height, 962);
  for (int v = 0; v < 4; ++v) {
    const int x0 = (v % 2) * 450, y0 = 62 + (v / 2) * 450;
    // The middle half of the panel: away from its label.
    EXPECT_GT(drawn_pixels(p, x0 + 112, y0 + 112, x0 + 338, y0 + 338), 226 * 226 / 10)
        << "panel " << v;
  }
  // One renderer serves the picture and the tile (library --png): the same bytes as each
  // made from mesh and clump.
  const ClumpRenderer renderer(box, clump);
  write_particle_png((d / "q.png").string(), renderer, "test particle", 450);
  EXPECT_EQ(read_png((d / "q.png").string()).pixels, p.pixels);
  const RgbImage tile = render_oblique(box, clump, 200);
  EXPECT_EQ(render_oblique(renderer, 200).pixels, tile.pixels);
  std::vector<SheetTile> tiles;
  for (int i = 0; i < 7; ++i) tiles.push_back({"tile " + std::to_string(i), tile});
  write_contact_sheet((d / "s.png").string(), "sheet", tiles);
  const RgbImage s = read_png((d / "s.png").string());
  EXPECT_EQ(s.width, 800);            // 3 columns of 200 px, widened to 800
  EXPECT_EQ(s.height, 40 + 3 * 224);  // 3 rows of tile and label under the title
  EXPECT_GT(drawn_fraction(s), 0.05);
  tiles.back().image = render_oblique(box, clump, 100);
  EXPECT_THROW(write_contact_sheet((d / "t.png").string(), "sheet", tiles), InvalidInput);
  EXPECT_FALSE(fs::exists(d / "t.png"));
  fs::remove_all(d);
}

// A plot has its axis labels drawn (ink in the y label's strip and under the x axis), the
// series in its colour, and no file for nothing to plot.
TEST(Render, PlotsHaveLabelledAxesAndTheirSeries) {
  const fs::path d = scratch();
  PlotSeries a, b;
  for (int k = 0; k <= 20; ++k) {
    a.points.x.push_back(0.01 * k);
    a.points.y.push_back(1e6 * std::sqrt(k));
  }
  a.label = "curve";
  b.points = {{0.1}, {2e6}};
  b.rgb = {210, 30, 30};
  b.line = false;
  b.marker = 6;
  write_plot((d / "p.png").string(), {a, b}, "axial strain (-)", "deviator stress (Pa)", "t");
  const RgbImage im = read_png((d / "p.png").string());
  ASSERT_EQ(im.width, 800);
  ASSERT_EQ(im.height, 560);
  EXPECT_GT(drawn_pixels(im, 0, 50, 32, 480), 200);      // the y label's strip
  EXPECT_GT(drawn_pixels(im, 110, 515, 770, 545), 200);  // the x label under the axis
  EXPECT_GT(red_pixels(im), 60);                         // the marker: a disc of radius 6
  // A label longer than the frame is wide: the legend is clipped to the image, nothing more.
  a.label = std::string(150, 'x');
  write_plot((d / "long.png").string(), {a}, "x", "y", "t");
  EXPECT_EQ(read_png((d / "long.png").string()).width, 800);
  PlotSeries nan;
  nan.points = {{NAN}, {1.0}};
  EXPECT_THROW(write_plot((d / "n.png").string(), {nan}, "x", "y", "t"), InvalidInput);
  EXPECT_FALSE(fs::exists(d / "n.png"));
  fs::remove_all(d);
}

}  // namespace
}  // namespace clumpkit
