// End-to-end tests of the library's pictures and ParaView files (library --png --vtp).
#include "cli_helpers.h"

#include "io/formats/clump_io.h"
#include "io/formats/mesh_io.h"
#include "io/formats/png.h"
#include "tests/image_checks.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;
using clumpkit::test::drawn_pixels;

// Pictures and ParaView files: NNNNN.png 900 × 962 with a drawing in each of its four
// panels, contact_sheet.png of 4 tiles (2 × 2 of 200 px under a 40-px title), the same bytes
// for 1 and 2 threads; a resumed run makes only what is missing and ends identical; ParaView's
// reader (python3-vtk9) finds each NNNNN.vtp's triangles, spheres and radii.
TEST(Cli, LibraryPicturesAndParaViewFiles) {
  const fs::path d = scratch();
  // Three blocks and a grain (the first 3 and the last of kLibraryRecipe's 8 + 4).
  std::string recipe = kLibraryRecipe;
  recipe.replace(recipe.find("count = 8"), 9, "count = 3");
  recipe.replace(recipe.find("count = 4"), 9, "count = 1");
  write(d / "r.toml", recipe);
  const std::string base =
      "library --quiet --png --vtp --recipe " + (d / "r.toml").string() + " --out ";
  Result r = run_cli(base + (d / "t1").string() + " --threads 1", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli(base + (d / "t2").string() + " --threads 2", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  expect_same_tree(d / "t1", d / "t2");
  // library.csv, manifest.json and each particle's record, clump and template.
  EXPECT_EQ(expect_units_everywhere(d / "t1"), 2 + 3 * 4);
  for (int i = 0; i < 4; ++i) {
    char stem[16];
    std::snprintf(stem, sizeof stem, "%05d", i);
    const auto im =
        clumpkit::read_png((d / "t1" / "particles" / (std::string(stem) + ".png")).string());
    ASSERT_EQ(im.width, 900) << stem;
    ASSERT_EQ(im.height, 962) << stem;
    for (int v = 0; v < 4; ++v) {
      const int x0 = (v % 2) * 450, y0 = 62 + (v / 2) * 450;
      EXPECT_GT(drawn_pixels(im, x0 + 150, y0 + 150, x0 + 300, y0 + 300), 0)
          << stem << " panel " << v;
    }
  }
  const auto sheet = clumpkit::read_png((d / "t1" / "contact_sheet.png").string());
  EXPECT_EQ(sheet.width, 800);
  EXPECT_EQ(sheet.height, 40 + 2 * 224);
  for (int i = 0; i < 4; ++i) {
    const int x0 = (i % 2) * 200, y0 = 40 + (i / 2) * 224;
    EXPECT_GT(drawn_pixels(sheet, x0 + 60, y0 + 60, x0 + 140, y0 + 140), 0) << "tile " << i;
  }

  fs::copy(d / "t1", d / "t3.partial", fs::copy_options::recursive);
  fs::remove(d / "t3.partial" / "particles" / "00003.png");
  fs::remove(d / "t3.partial" / "particles" / "00002.vtp");
  fs::remove(d / "t3.partial" / "contact_sheet.png");
  r = run_cli(base + (d / "t3").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["resumed"], 4);
  expect_same_tree(d / "t1", d / "t3");

  if (std::system("/usr/bin/python3 -c 'import vtkmodules' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 not installed: run scripts/deps";
  write(d / "read.py", R"(import sys
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
r = vtkXMLPolyDataReader()
r.SetFileName(sys.argv[1])
r.Update()
p = r.GetOutput()
rad = p.GetPointData().GetArray("radius")
dia = p.GetPointData().GetArray("diameter")
n = p.GetNumberOfPoints()
top = max(rad.GetValue(k) for k in range(n))
print(p.GetNumberOfPolys(), p.GetNumberOfVerts(), repr(top), repr(max(dia.GetValue(k) for k in range(n)) / top))
)");
  for (int i : {0, 3}) {
    char stem[16];
    std::snprintf(stem, sizeof stem, "%05d", i);
    const fs::path vtp = d / "t1" / "particles" / (std::string(stem) + ".vtp");
    const fs::path out = d / "vtk.txt";
    ASSERT_EQ(std::system(("/usr/bin/python3 " + (d / "read.py").string() + " " + vtp.string() +
                           " >" + out.string() + " 2>&1")
                              .c_str()),
              0)
        << slurp(out);
    const auto mesh =
        clumpkit::read_mesh_raw((d / "t1" / "particles" / (std::string(stem) + ".stl")).string());
    const auto clump =
        clumpkit::read_clump((d / "t1" / "particles" / (std::string(stem) + ".csv")).string());
    double largest = 0;
    for (const auto& s : clump.spheres) largest = std::max(largest, s.radius);
    std::istringstream in(slurp(out));
    std::size_t polys = 0, verts = 0;
    double top = 0, ratio = 0;
    in >> polys >> verts >> top >> ratio;
    EXPECT_EQ(polys, mesh.triangles.size()) << stem;
    EXPECT_EQ(verts, clump.spheres.size()) << stem;
    EXPECT_NEAR(top, largest, 1e-12 * largest) << stem;
    EXPECT_DOUBLE_EQ(ratio, 2.0) << stem;
  }
}
