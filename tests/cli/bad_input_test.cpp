// The bad-input matrix: every command × {missing file, a directory, empty, binary garbage,
// truncated, NaN, zero/negative sizes, extreme magnitudes, --out whose parent is a file, --out
// equal to an input} gives one line "clumpkit: error: ..." naming the file, field or value,
// exit 2, and nothing at the output (no DIR.partial, no temporary file either).
#include "cli_helpers.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

struct Case {
  std::string command;  // what follows `clumpkit`
  std::string needle;   // the file, field or value the message must name
  std::string out;      // the output that must not appear ("" when the command writes none)
};

// The inputs every case draws on: good ones to corrupt, and each kind of bad file.
struct Inputs {
  fs::path d;
  explicit Inputs(const fs::path& dir) : d(dir) {
    const Result r = run_cli("shape box --size 1,2,3 -o " + (d / "box.stl").string(), d);
    EXPECT_EQ(r.rc, 0) << r.err;
    const std::string stl = slurp(d / "box.stl");
    write(d / "trunc.stl", stl.substr(0, stl.size() / 2));
    write(d / "empty.stl", "");
    write(d / "empty.csv", "");
    write(d / "empty.toml", "");
    std::string garbage;
    for (int k = 0; k < 4096; ++k) garbage.push_back(static_cast<char>((k * 7919 + 13) % 256));
    for (const char* n : {"garbage.stl", "garbage.csv", "garbage.toml", "garbage.obj"})
      write(d / n, garbage);
    write(d / "nan.obj",
          "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    write(d / "huge.obj",
          "v 0 0 0\nv 1e300 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    // Two copies of one triangle: closed and manifold by its edges, but it bounds no volume
    // (found by fuzz_mesh_obj: orienting it read out of bounds in CGAL).
    write(d / "twice.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n");
    write(d / "flat.obj",
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nf 1 3 2\nf 2 3 4\n");
    // The PLY and OBJ parsing paths: big-endian data cut short, a count no file can hold, a list
    // longer than the file, a garbled property line, a continued face that ends the file.
    const std::string be_head =
        "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 4\n"
        "property list uchar int vertex_indices\nend_header\n";
    write(d / "trunc_be.ply", be_head + std::string(30, '\x3f'));
    write(d / "huge_count.ply",
          "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
          "property float z\nend_header\n0 0 0\n");
    write(d / "long_list.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
          "property float y\nproperty float z\nelement face 1\n"
          "property list uint int vertex_indices\nend_header\n\xff\xff\xff\x7f");
    write(d / "garbled.ply",
          "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar\nend_header\n3 0 1 2\n");
    write(d / "short_line.ply",  // an ASCII item line with too few values
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
    write(d / "continued.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n");
    write(d / "good.csv", "x,y,z,r\n0,0,0,1\n0.5,0,0,1\n");
    write(d / "trunc.csv", "x,y,z,r\n0,0,0,1\n0.5,0,");
    write(d / "nan.csv", "x,y,z,r\n0,0,0,1\n0.5,nan,0,1\n");
    write(d / "zero.csv", "x,y,z,r\n0,0,0,0\n");
    write(d / "negative.csv", "x,y,z,r\n0,0,0,-1\n");
    write(d / "huge.csv", "x,y,z,r\n0,0,0,1e300\n");
    write(d / "tiny.csv", "x,y,z,r\n0,0,0,1e-300\n");
    write(d / "rocks.toml", kTinyRocks);
    const std::string rocks = kTinyRocks, spec = kTinySpecimen;
    write(d / "trunc.toml", rocks.substr(0, rocks.find("W = {") + 8));
    // `text` with `from` replaced by `to`.
    auto edited = [](std::string text, const std::string& from, const std::string& to) {
      return text.replace(text.find(from), from.size(), to);
    };
    const std::string w = "W = { uniform = [0.010, 0.015] }";
    write(d / "nan.toml", edited(rocks, w, "W = nan"));
    write(d / "negative.toml", edited(rocks, w, "W = -0.01"));
    write(d / "huge.toml", edited(rocks, w, "W = 1e300"));
    write(d / "zero.toml", edited(rocks, w, "W = 0"));
    write(d / "many.toml", edited(rocks, "count = 6", "count = 1000000000000"));
    tiny_specimen_recipe(d);  // tiny.toml (its rock recipe: rocks.toml)
    write(d / "spec_nan.toml", edited(spec, "diameter = 0.060", "diameter = nan"));
    write(d / "spec_negative.toml", edited(spec, "height = 0.100", "height = -0.1"));
    write(d / "spec_huge.toml", edited(spec, "diameter = 0.060", "diameter = 1e300"));
    // Zoned chambers (CTGU 2017): overlapping zones, sizes 4 times apart, a mixed layer thinner
    // than two large particles, a segment angle outside (0, 180].
    const std::string zoned =
        "soil_rock_threshold = 1.0\nrock_mass_fraction = 0.0\n[container]\nshape = "
        "\"segment\"\nangle = 90\ndiameter = 0.3\nheight = 0.2\n[preparation]\nmethod = "
        "\"compression\"\nporosity = 0.36\n[gradation]\nsieves = [0.00601, 0.00599]\npassing = "
        "[100, 0]\n[zones]\n[[zones.region]]\nouter = 0.075\nscale = 1\n[[zones.region]]\n"
        "mixed = true\nouter = 0.125\nsmall_volume_fraction = 0.4\n[[zones.region]]\nouter = "
        "0.15\nscale = 3\n";
    write(d / "zones_overlap.toml", edited(zoned, "outer = 0.125", "outer = 0.07"));
    write(d / "zones_ratio.toml", edited(zoned, "scale = 3", "scale = 4"));
    write(d / "zones_thin.toml", edited(zoned, "outer = 0.125", "outer = 0.09"));
    write(d / "segment_angle.toml", edited(zoned, "angle = 90", "angle = 270"));
    // A unit cube with one corner pushed in: closed, but not convex (for `cells`).
    write(d / "dented.obj",
          "v 0.3 0.3 0.3\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
          "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\n"
          "f 1 8 4\nf 2 3 7\nf 2 7 6\n");
    // A closed unit cube and a half-size cube facing inward (a void) through its corner: neither
    // the local mend (no shell crosses itself) nor the union (a void is no operand) mends it, so
    // `repair --wrap never` refuses it at its final check.
    std::string crossing;
    for (const auto& [o, size] : {std::pair<double, double>{0, 1}, {0.75, 0.5}})
      for (int v = 0; v < 8; ++v)
        crossing += "v " + std::to_string((v & 1) * size + o) + " " +
                    std::to_string(((v >> 1) & 1) * size + o) + " " +
                    std::to_string(((v >> 2) & 1) * size + o) + "\n";
    for (int base : {0, 8}) {
      const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                               {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      for (const auto& q : quads) {
        const int a = base == 0 ? q[1] : q[3], c = base == 0 ? q[3] : q[1];  // the void reversed
        crossing += "f " + std::to_string(base + q[0] + 1) + " " + std::to_string(base + a + 1) +
                    " " + std::to_string(base + q[2] + 1) + " " + std::to_string(base + c + 1) +
                    "\n";
      }
    }
    write(d / "crossing.obj", crossing);
    write(d / "parent_file", "a file, not a directory\n");
    fs::create_directories(d / "a_dir");
  }
  std::string operator()(const std::string& name) const { return (d / name).string(); }
};

}  // namespace

TEST(CliBadInput, EveryCommandRefusesEveryKindOfBadInputCleanly) {
  const fs::path d = scratch();
  const Inputs in(d);
  const std::string out = in("out"), csv_out = in("out.csv"), mesh_out = in("out.stl");
  const std::string pf = in("parent_file") + "/x";
  std::vector<Case> cases;
  // describe MESH
  for (const char* f : {"missing.stl", "a_dir", "empty.stl", "garbage.stl", "trunc.stl", "nan.obj",
                        "huge.obj", "flat.obj", "twice.obj", "trunc_be.ply", "huge_count.ply",
                        "long_list.ply", "garbled.ply", "continued.obj", "short_line.ply"})
    cases.push_back({"describe " + in(f), f, ""});
  // repair MESH -o OUT
  for (const char* f : {"missing.stl", "a_dir", "empty.stl", "garbage.obj", "trunc_be.ply",
                        "long_list.ply", "nan.obj", "twice.obj", "short_line.ply"})
    cases.push_back({"repair " + in(f) + " -o " + mesh_out, f, mesh_out});
  cases.push_back({"repair " + in("crossing.obj") + " -o " + mesh_out + " --wrap never",
                   "step 'self-intersection check'", mesh_out});
  cases.push_back({"repair " + in("flat.obj") + " -o " + mesh_out, "encloses no volume", mesh_out});
  cases.push_back(
      {"repair " + in("box.stl") + " -o " + mesh_out + " --wrap sometimes", "--wrap", mesh_out});
  cases.push_back(
      {"fill " + in("flat.obj") + " --repair -o " + csv_out, "encloses no volume", csv_out});
  cases.push_back({"repair " + in("box.stl") + " -o " + in("box.stl"), "would be overwritten", ""});
  cases.push_back({"repair " + in("box.stl") + " -o " + in("out.off"), "out.off", in("out.off")});
  cases.push_back({"describe " + in("box.stl") + " --weld-tolerance -1", "-1", ""});
  // fill MESH -o OUT
  for (const char* f : {"missing.stl", "a_dir", "empty.stl", "garbage.obj", "trunc.stl", "nan.obj",
                        "huge.obj", "flat.obj"})
    cases.push_back({"fill " + in(f) + " -o " + csv_out, f, csv_out});
  cases.push_back({"fill " + in("box.stl") + " -o " + in("box.stl"), "would be overwritten", ""});
  cases.push_back({"fill " + in("box.stl") + " -o " + pf + ".csv", "parent_file", ""});
  cases.push_back({"fill " + in("box.stl") + " -o " + csv_out + " --min-radius -1", "-1", csv_out});
  cases.push_back({"fill " + in("box.stl") + " -o " + csv_out + " --spheres 0", "0", csv_out});
  cases.push_back(
      {"fill " + in("box.stl") + " -o " + csv_out + " --max-overshoot -0.5", "-0.5", csv_out});
  // refine MESH --triangles N -o OUT
  for (const char* f : {"missing.stl", "garbage.obj", "nan.obj", "flat.obj"})
    cases.push_back({"refine " + in(f) + " --triangles 100 -o " + mesh_out, f, mesh_out});
  cases.push_back(
      {"refine " + in("box.stl") + " --triangles 0 -o " + mesh_out, "--triangles", mesh_out});
  cases.push_back(
      {"refine " + in("box.stl") + " --triangles 100000000 -o " + mesh_out, "5e7", mesh_out});
  // Requests that would exhaust memory are refused before allocating, with the estimate.
  cases.push_back({"fill " + in("box.stl") + " -o " + csv_out + " --voxel-size 1e-6",
                   "distance field would have", csv_out});
  cases.push_back({"fill " + in("box.stl") + " -o " + csv_out + " --voxels 400 --max-memory 1",
                   "would need an estimated", csv_out});
  // volume CLUMP
  for (const char* f : {"missing.csv", "a_dir", "empty.csv", "garbage.csv", "trunc.csv", "nan.csv",
                        "zero.csv", "negative.csv", "huge.csv", "tiny.csv"})
    cases.push_back({"volume " + in(f), f, ""});
  cases.push_back({"volume " + in("good.csv") + " --method voxel --voxel 1e-10", "32-bit", ""});
  cases.push_back({"volume " + in("good.csv") + " --method voxel --voxel 1e-4 --max-memory 1",
                   "would need an estimated", ""});
  cases.push_back({"volume " + in("good.csv") + " --method pixel-slice --slices 1000000",
                   "beyond the 2e9", ""});
  cases.push_back({"volume " + in("good.csv") + " --method all --slices 20000 --max-memory 1",
                   "pixel-slice on " + in("good.csv") + " would need an estimated", ""});
  cases.push_back({"volume " + in("good.csv") + " --max-memory -1", "--max-memory", ""});
  // shape box --size -o OUT
  for (const char* size : {"0,1,1", "-1,1,1", "1e300,1,1", "1e-300,1,1", "nan,1,1"})
    cases.push_back(
        {"shape box --size " + std::string(size) + " -o " + mesh_out, "box size", mesh_out});
  cases.push_back({"shape box --size 1,1,1 -o " + pf + ".stl", "parent_file", ""});
  // shapes and library --recipe R --out D
  for (const char* command : {"shapes", "library"}) {
    for (const char* f : {"missing.toml", "a_dir", "empty.toml", "garbage.toml", "trunc.toml",
                          "nan.toml", "negative.toml", "huge.toml", "zero.toml"})
      cases.push_back(
          {std::string(command) + " --quiet --recipe " + in(f) + " --out " + out, f, out});
    cases.push_back(
        {std::string(command) + " --quiet --recipe " + in("rocks.toml") + " --out " + pf,
         "parent_file", ""});
    cases.push_back({std::string(command) + " --quiet --recipe " + in("rocks.toml") + " --out " +
                         in("rocks.toml"),
                     "rocks.toml", ""});
    cases.push_back(
        {std::string(command) + " --quiet --recipe " + in("many.toml") + " --out " + out,
         "fraction[0].count", out});
  }
  cases.push_back(
      {"library --quiet --max-memory 0.01 --recipe " + in("rocks.toml") + " --out " + out,
       "would need an estimated", out});
  // specimen --recipe R --out D
  for (const char* f : {"missing.toml", "a_dir", "empty.toml", "garbage.toml", "trunc.toml",
                        "spec_nan.toml", "spec_negative.toml", "spec_huge.toml"})
    cases.push_back({"specimen --quiet --recipe " + in(f) + " --out " + out, f, out});
  for (const auto& [f, needle] :
       std::vector<std::pair<const char*, const char*>>{{"zones_overlap.toml", "zones overlap"},
                                                        {"zones_ratio.toml", "scale 4 next to 1"},
                                                        {"zones_thin.toml", "narrower than two"},
                                                        {"segment_angle.toml", "container.angle"}})
    cases.push_back({"specimen --quiet --recipe " + in(f) + " --out " + out, needle, out});
  // A request over the memory budget is refused before anything is built, with the estimate.
  cases.push_back(
      {"specimen --quiet --max-memory 0.000001 --recipe " + in("tiny.toml") + " --out " + out,
       "would need about", out});
  cases.push_back({"specimen --quiet --recipe " + in("tiny.toml") + " --out " + in("tiny.toml"),
                   "tiny.toml", ""});
  // export FORMAT SRC --out D (a clump CSV source)
  for (const char* f : {"missing.csv", "a_dir", "empty.csv", "garbage.csv", "trunc.csv", "nan.csv",
                        "zero.csv", "negative.csv", "huge.csv", "tiny.csv"})
    cases.push_back({"export lammps " + in(f) + " --density 2650 --out " + out, f, out});
  cases.push_back({"export vtk " + in("good.csv") + " --density 0 --out " + out, "--density", out});
  cases.push_back(
      {"export vtk " + in("good.csv") + " --density 2650 --out " + pf, "parent_file", ""});
  cases.push_back(
      {"export vtk " + in("a_dir") + " --density 2650 --out " + in("a_dir"), "would replace", ""});
  // import lammps RUN --specimen S --out D
  write(d / "run" / "atoms.0.txt", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n3\n");
  cases.push_back(
      {"import lammps " + in("missing") + " --specimen " + in("a_dir") + " --out " + out, "a_dir",
       out});
  cases.push_back(
      {"import lammps " + in("run") + " --specimen " + in("run") + " --out " + in("run"),
       "would replace", ""});

  // cells MESH --count N --out DIR: unreadable meshes, a non-convex one, a cell as large as the
  // parent, both or neither of --count and --cell-size, bad steps and spreads, a bad --out.
  for (const char* f :
       {"missing.stl", "a_dir", "empty.stl", "garbage.stl", "nan.obj", "flat.obj", "dented.obj"})
    cases.push_back({"cells " + in(f) + " --count 8 --out " + out, f, out});
  const std::string box = in("box.stl");
  cases.push_back({"cells " + in("dented.obj") + " --count 8 --out " + out, "not convex", out});
  cases.push_back({"cells " + box + " --cell-size 10 --out " + out, "fewer than two cells", out});
  cases.push_back({"cells " + box + " --cell-size -0.5 --out " + out, "-0.5", out});
  cases.push_back({"cells " + box + " --count 8 --cell-size 0.5 --out " + out, "--count", out});
  cases.push_back({"cells " + box + " --out " + out, "exactly one", out});
  cases.push_back({"cells " + box + " --count 1 --out " + out, "count", out});
  cases.push_back({"cells " + box + " --count 8 --lloyd -1 --out " + out, "lloyd", out});
  cases.push_back({"cells " + box + " --count 8 --strength-sd -1 --out " + out, "-1", out});
  cases.push_back({"cells " + box + " --count 8 --out " + pf, "parent_file", ""});
  cases.push_back({"cells " + box + " --count 8 --out " + box, "box.stl", ""});

  // compare-curves A B: missing or unreadable files, a missing column, a cell that is not a
  // number, x that goes back, one row, ranges that do not overlap, columns in other units, too
  // few points, a window that leaves nothing or is not a number
  write(d / "qc_a.csv", "step,depth_m,qc_pa\n1,0,0\n2,0.1,1e6\n3,0.2,2e6\n");
  write(d / "qc_nan.csv", "step,depth_m,qc_pa\n1,0,0\n2,0.1,nan\n");
  write(d / "qc_back.csv", "step,depth_m,qc_pa\n1,0,0\n2,0.1,1\n3,0.05,2\n");
  write(d / "qc_one.csv", "step,depth_m,qc_pa\n1,0,0\n");
  write(d / "qc_far.csv", "step,depth_m,qc_pa\n1,1,0\n2,2,1\n");
  write(d / "qc_mm.csv", "step[1],depth[mm],qc[Pa]\n1,0,0\n2,100,1e6\n3,200,2e6\n");
  const std::string qa = in("qc_a.csv");
  for (const char* f : {"missing.csv", "a_dir", "empty.csv", "garbage.csv", "qc_nan.csv",
                        "qc_back.csv", "qc_one.csv", "good.csv"})
    cases.push_back({"compare-curves " + qa + " " + in(f), f, ""});
  cases.push_back({"compare-curves " + qa + " " + qa + " --y fs", "'fs'", ""});
  cases.push_back({"compare-curves " + qa + " " + in("qc_far.csv"), "do not overlap", ""});
  cases.push_back({"compare-curves " + qa + " " + in("qc_mm.csv"), "same units", ""});
  cases.push_back({"compare-curves " + qa + " " + qa + " --points 1", "points", ""});
  cases.push_back({"compare-curves " + qa + " " + qa + " --from 0.15 --to 0.1", "0.15", ""});
  cases.push_back({"compare-curves " + qa + " " + qa + " --from 0.3", "leaves nothing", ""});
  cases.push_back({"compare-curves " + qa + " " + qa + " --to nan", "window", ""});

  // crush --recipe R --out D: unknown keys, negative energies, a cell size above the particle,
  // no sets, a bad axis, a NaN rate, a missing file; nothing is simulated or written.
  const std::string crush_set = "[[set]]\nname = \"a\"\ndiameter = 0.016\nsamples = 3\n";
  const std::pair<const char*, std::string> crush_recipes[] = {
      {"unknown", "[crush]\nbogus = 1\n" + crush_set},
      {"energy", "[bond]\ng_n = -5\n" + crush_set},
      {"big_cell", "[cells]\ncell_size = 0.05\n" + crush_set},
      {"no_set", "[crush]\nseed = 2\n"},
      {"axis", crush_set + "axis = \"diagonal\"\n"},
      {"rate", "[crush]\nstrain_rate = nan\n" + crush_set},
      {"low_energy", "[bond]\ng_n = 100\n" + crush_set}};
  const char* crush_needles[] = {"bogus",       "g_n", "fewer than 2 cells", "[[set]]", "diagonal",
                                 "strain_rate", "g_n"};
  for (std::size_t k = 0; k < std::size(crush_recipes); ++k) {
    const std::string f = std::string("crush_") + crush_recipes[k].first + ".toml";
    write(d / f, crush_recipes[k].second);
    cases.push_back({"crush --quiet --recipe " + in(f) + " --out " + out, crush_needles[k], out});
  }
  cases.push_back(
      {"crush --quiet --recipe " + in("missing.toml") + " --out " + out, "missing.toml", out});

  for (const Case& c : cases) {
    SCOPED_TRACE(c.command);
    expect_one_line_error(run_cli(c.command, d), c.needle);
    if (!c.out.empty()) {
      EXPECT_FALSE(fs::exists(c.out));
      EXPECT_FALSE(fs::exists(c.out + ".partial"));
    }
    for (const auto& e : fs::directory_iterator(d))
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  // The inputs are untouched.
  EXPECT_EQ(slurp(d / "rocks.toml"), std::string(kTinyRocks));
  EXPECT_TRUE(fs::is_regular_file(d / "box.stl"));
  std::printf("bad-input matrix: %zu cases over 13 commands\n", cases.size());
}
