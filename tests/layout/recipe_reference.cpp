// Prints docs/recipes.md, generated whole from the recipe section tables
// (io/recipes/section_table.h) with the page's prose around them (tests/layout/docs_check.py
// compares and writes it); with --test-kinds, the table of `clumpkit test` kinds from their
// registry (io/pipeline/test_kinds.h), the generated part of docs/lab-tests.md.
#include "io/pipeline/test_kinds.h"
#include "io/recipes/crush_recipe.h"
#include "io/recipes/lab_recipe.h"
#include "io/recipes/recipe.h"
#include "io/recipes/specimen_recipe.h"

#include <cstring>
#include <iostream>

namespace {

using namespace clumpkit;

void test_kinds_table() {
  std::cout << "| kind | loading and report | curve.png | page plots |\n|---|---|---|---|\n";
  for (const TestKind& k : test_kinds()) {
    std::string plots;
    for (const PagePlot& p : k.page_plots) plots += (plots.empty() ? "" : ", ") + p.title;
    const std::string picture =
        k.path ? std::string(k.picture.y_label) + " against " + k.picture.x_label
               : "qc against depth";
    std::cout << "| `" << k.name << "` | " << k.summary << " | " << picture << " | " << plots
              << " |\n";
  }
}

// The page's prose before the specimen sections: what a recipe is, the shape library's keys.
const char* const kIntro = R"md(# Recipes

A recipe is a TOML file in SI units (metres, kilograms, seconds, pascals). Every command that
reads one refuses, before it writes anything, a missing file, a TOML syntax error, an unknown key,
a NaN or a value out of range, with one line naming the file, the field and the value
(`clumpkit: error: FILE: FIELD: what, got VALUE`, exit code 2). The bundled recipes in
`assets/recipes/` are commented key by key: copy the nearest one and change it.

| kind | read by | bundled | section tables in |
|---|---|---|---|
| shape library | `shapes`, `library` | `srm-rock-blocks.toml`, `sand-roundness.toml`, `rockfill-shapes.toml`, `quick-rocks.toml` | `io/recipes/recipe.h` |
| specimen | `specimen` | `quick-specimen.toml`, `srm40-triaxial.toml`, `cpt-A.toml` … `cpt-E.toml`, `elastic-scaling-specimen.toml` | `io/recipes/specimen_recipe.h` |
| test | `test`, `export lammps --test` | `test-triaxial-quick.toml`, `test-cpt.toml`, `elastic-scaling-table1.toml` | `io/recipes/lab_recipe.h` |
| crushing | `crush` | `crush-quick.toml`, `crush-brazilian.toml`, `crush-table1.toml`, `crush-table2.toml` | `io/recipes/crush_recipe.h` |

This page is generated whole from the section tables (`io/recipes/section_table.h`: each key's
unit, values, default and help beside the code that reads it) by `tests/layout/recipe_reference`;
`Layout.CommandsPageMatchesHelp` fails when it differs (regenerate with
`tests/layout/docs_check.py build/io/clumpkit . build/tests/recipe_reference --write`). A range
the engine also enforces is the engine's own `Range` (`geom/range.h`: `kTargetPorosity`,
`kFriction`, `kPolyhedronPlanes` …, declared beside the spec it limits), read through
`range_key`: the recipe refuses a value in the engine's words and this page quotes the same
object, so the three cannot disagree.

## Shape library recipes

```toml
seed = 2017                       # optional, default 1
name = "..."                      # optional
description = "..."               # optional
refine_triangles = 100000         # optional: subdivide every mesh to at least this many triangles

[[fraction]]                      # one table per fraction
name = "rock 20-40 mm"
method = "block"                  # block | hull | polyhedron | ellipsoid | mesh
count = 200
W = { uniform = [0.020, 0.040] }
L_over_H = { lognormal = { mu = 0.4, sigma = 0.2, min = 1.0, max = 3.0 } }
nd = 2                            # a number is a constant

[fill]                            # optional, for `clumpkit library`
spheres = 47                      # or coverage = 0.9, min_radius = 0.002
voxels = 40                       # optional: the grid; default from the sphere count
max_overshoot = 0.01              # volume the clump may put outside, over the mesh volume
refine_iterations = 8             # sweeps of the refinement after the greedy pass (0: none)
```

A fraction of method `mesh` takes its particles from files instead of drawing them: every .stl,
.obj and .ply file of `folder` (relative to the recipe's folder), one particle each in the order
of their names (`count`, if given, must equal their number), scaled by `scale` (default 1; 0.001
for scans in millimetres, since recipes are in metres):

```toml
[[fraction]]
name = "scanned grains"
method = "mesh"
folder = "scans"
scale = 0.001
```

Each file must be a solid (what `describe` accepts) unless `clumpkit library --repair` is given:
then each is repaired in memory first, as `clumpkit repair` does (holes closed, crossings mended,
a wrap as the last resort), and its particle record's `repair` says what was done, so a folder of
raw scans becomes a library in one command. Each record names its `source` file.

Every parameter of a fraction is a number or a distribution: `{ uniform = [a, b] }`,
`{ integers = [a, b] }`, `{ normal = { mu, sigma, min, max } }`,
`{ lognormal = { mu, sigma, min, max } }` (truncated to `[min, max]`); hull fractions also take
`roundness = [min, max]`, the band of weighted roundness the hull is redrawn into. The parameters
of each method are those of `clumpkit shape METHOD --help` ([commands](commands.md)).

)md";
const char* const kSpecimens = R"md(## Specimen recipes

Specimen recipes name their container, gradation, fines, rock library (`[rock] recipe`), contact
law, preparation method and, for CTGU 2017's chambers, `[zones]`; [specimens](specimens.md)
explains each stage and what its keys do. A crushable specimen's `[rock]` says `crushable = true`
and carries the crushing recipes' `[cells]` and `[bond]` (below); see [crushing](crushing.md).
)md";
const char* const kTests = R"md(## Test recipes

Test recipes hold `[test]` (confining stress, rates, stops, records), optional contact-law
overrides and, for the CPT, `[probe]`; see [element tests and CPT](lab-tests.md).
)md";
const char* const kCrushing = R"md(## Crushing recipes

Crushing recipes hold `[crush]`, `[cells]`, `[bond]` and one `[[set]]` per size or shape; see
[crushing](crushing.md).
)md";

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--test-kinds") == 0) {
    test_kinds_table();
    return 0;
  }
  const SpecimenRecipe specimen;
  const CrushRecipe crush;
  const TestRecipe test;
  std::cout << kIntro << section_reference(fraction_section(), FractionTable{}, "[[fraction]]")
            << "\n"
            << section_reference(fill_section(), FillOptions{}) << "\n"
            << kSpecimens << "\n"
            << section_reference(specimen_top_section(), specimen, "top level (no table)") << "\n"
            << section_reference(container_section(), specimen) << "\n"
            << section_reference(preparation_section(), specimen) << "\n"
            << section_reference(gradation_section(), specimen) << "\n"
            << section_reference(fines_section(), specimen) << "\n"
            << section_reference(rock_section(), specimen) << "\n"
            << section_reference(density_section(), specimen) << "\n"
            << section_reference(contact_section(), specimen) << "\n"
            << section_reference(zones_section(), specimen) << "\n"
            << section_reference(zone_region_section(), dem::ZoneRegion{}, "[[zones.region]]")
            << "\n"
            << kTests << "\n"
            << section_reference(test_section(), test) << "\n"
            << section_reference(contact_override_section(), test, "[contact] of a test recipe")
            << "\n"
            << section_reference(probe_section(), dem::ProbeSettings{}) << "\n"
            << kCrushing << "\n"
            << section_reference(crush_section(), crush) << "\n"
            << section_reference(cells_section(), crush) << "\n"
            << section_reference(bond_section(), crush) << "\n"
            << section_reference(set_section(), CrushSet{}, "[[set]]");
  return 0;
}
