// Pictures of clumps against their meshes: one particle in four views, and a library's sheet.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/sphere.h"
#include "io/formats/png.h"
#include "io/reports/render.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Writes the picture of one particle (io/reports/render.h shading): a caption line, then four
/// `panel`-px views in a 2 × 2 grid — front (along +y, z up), side (along −x, z up), top
/// (along −z, y up) and oblique — all at one scale, whose width the caption states. 2·panel
/// wide, 2·panel + 62 high. Atomic write; throws IoError naming the path.
/// `metres`: the mesh is in metres (a library), so the scale is written in m, mm or µm; else
/// in the mesh's own units (`fill` keeps them).
void write_particle_png(const std::string& path, const Mesh& mesh, const Clump& clump,
                        const std::string& caption, int panel = 450, bool metres = true);
/// The same from a renderer already built (its Embree scenes serve several pictures).
void write_particle_png(const std::string& path, const ClumpRenderer& renderer,
                        const std::string& caption, int panel = 450, bool metres = true);

/// The oblique view of write_particle_png alone, `pixels` square: a contact sheet's tile.
RgbImage render_oblique(const Mesh& mesh, const Clump& clump, int pixels);
RgbImage render_oblique(const ClumpRenderer& renderer, int pixels);

/// One tile of a contact sheet: its image (all tiles the same size) and the label under it.
struct SheetTile {
  std::string label;
  RgbImage image;
};

/// Writes the tiles in rows of ⌈√n⌉ (at most `max_columns`), each labelled, under a title.
void write_contact_sheet(const std::string& path, const std::string& title,
                         const std::vector<SheetTile>& tiles, int max_columns = 20);

}  // namespace clumpkit
