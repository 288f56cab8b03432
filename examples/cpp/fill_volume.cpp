// Reads a mesh, fills it with spheres and prints the exact volume of their union: clumpkit used
// from another C++ program.
//   fill_volume MESH SPHERES CLUMP.csv
#include <clumpkit/geom/fill/fill.h>
#include <clumpkit/geom/format.h>
#include <clumpkit/geom/version.h>
#include <clumpkit/geom/volume/union_of_balls.h>
#include <clumpkit/io/formats/clump_io.h>
#include <clumpkit/io/formats/mesh_io.h>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: fill_volume MESH SPHERES CLUMP.csv\n");
    return 2;
  }
  try {
    const clumpkit::Mesh mesh = clumpkit::read_mesh(argv[1]);
    clumpkit::FillOptions options;
    options.spheres = std::stoi(argv[2]);
    const clumpkit::FillResult filled = clumpkit::fill(mesh, options);
    clumpkit::write_clump(argv[3], filled.clump);
    const clumpkit::UnionProperties u = clumpkit::union_properties(filled.clump);
    std::printf("clumpkit %s: %zu spheres, union volume %s\n", clumpkit::version(),
                filled.clump.spheres.size(), clumpkit::format_number(u.mass.volume).c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fill_volume: %s\n", e.what());
    return 1;
  }
}
