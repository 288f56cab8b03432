#include "io/formats/mesh_io.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "geom/mesh/cgal_mesh.h"
#include "geom/mesh/repair.h"
#include "geom/mesh/shells.h"
#include "geom/mesh/weld.h"
#include "io/base/atomic_file.h"
#include "io/base/little_endian.h"
#include "io/base/text.h"
#include "io/formats/mesh_formats.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace clumpkit {

namespace {

namespace fs = std::filesystem;
using mesh_format::bad;
using mesh_format::plural;

std::string read_whole_file(const std::string& path) {
  std::string data = read_file(path, "mesh file");
  if (data.empty()) bad(path, "file is empty");
  return data;
}

}  // namespace

MeshFormat mesh_format_from_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  bad(path, ext.empty() ? "no file extension; expected .stl, .obj or .ply"
                        : "unknown mesh format '" + ext + "'; expected .stl, .obj or .ply");
}

Mesh read_mesh_raw(const std::string& path, const MeshReadOptions& options,
                   MeshReadReport* report) {
  const MeshFormat format = mesh_format_from_path(path);
  if (!(options.weld_tolerance >= 0.0 && options.weld_tolerance < 1.0))
    bad(path, "weld tolerance must lie in [0, 1), got " + format_number(options.weld_tolerance));
  const std::string data = read_whole_file(path);
  if (format == MeshFormat::Stl) {
    // STL's float32 corners at 1e-9 of the diagonal as always, welded as they are read.
    std::size_t dropped = 0;
    Mesh mesh = mesh_format::read_stl(path, data, std::max(options.weld_tolerance, 1e-9), dropped);
    if (report) report->removed_triangles = dropped;
    return mesh;
  }
  std::size_t extra = 0;
  Mesh mesh = format == MeshFormat::Obj ? mesh_format::read_obj(path, data)
                                        : mesh_format::read_ply(path, data, &extra);
  const std::size_t vertices = mesh.vertices.size(), triangles = mesh.triangles.size();
  // OBJ and PLY exactly, unless asked.
  weld_vertices(mesh, options.weld_tolerance);
  if (report) {
    report->merged_vertices = vertices - mesh.vertices.size();
    report->removed_triangles = triangles - mesh.triangles.size();
    report->lines_with_extra_values = extra;
  }
  return mesh;
}

Mesh read_mesh(const std::string& path, MeshReadReport* report, const MeshReadOptions& options) {
  MeshReadReport read;
  Mesh mesh = read_mesh_raw(path, options, &read);
  validate_solid(mesh, path, &read);
  if (report) *report = read;
  return mesh;
}

void validate_solid(Mesh& mesh, const std::string& path, MeshReadReport* report) {
  MeshReadReport local;
  MeshReadReport& read = report ? *report : local;
  const long n = static_cast<long>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        bad(path, "triangle " + std::to_string(t) + " (counting from 0) has vertex index " +
                      std::to_string(v) + ", outside 0.." + std::to_string(n - 1));
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    if (!p.allFinite() || !(p.cwiseAbs().maxCoeff() <= kMaxLength))
      bad(path, "vertex " + std::to_string(i) +
                    " (counting from 0) has a coordinate that is not finite or beyond 1e30 (" +
                    format_number(p.x()) + ", " + format_number(p.y()) + ", " +
                    format_number(p.z()) + ")");
  }
  if (mesh.triangles.empty()) bad(path, "mesh has no triangles");
  MeshCheck check = check_mesh(mesh);
  // Degeneracy first: check_mesh skips triangles with repeated vertices when counting edges,
  // which would otherwise surface as a misleading "open" message. Zero-area triangles of a
  // closed manifold mesh (needles and caps of a tessellation) are collapsed away.
  if (check.degenerate && check.boundary_edges == 0 && check.nonmanifold_edges == 0 &&
      check.manifold) {
    try {
      read.removed_triangles += collapse_degenerate_triangles(mesh);
    } catch (const std::exception&) {
      // refused below as degenerate (CGAL's own exceptions included)
    }
    check = check_mesh(mesh);
  }
  if (check.degenerate) bad(path, "mesh has a degenerate triangle (zero area or repeated vertex)");
  // Closed lobes that touch along an edge or at a vertex bound a volume: split apart, they are
  // touching shells (orient_shells adds their volumes; the inside test is the same).
  if (check.boundary_edges == 0 && (check.nonmanifold_edges > 0 || !check.manifold)) {
    Mesh split = mesh;
    std::size_t added = 0;
    try {
      added = split_nonmanifold(split);
    } catch (const std::exception&) {
      added = 0;  // refused below as non-manifold
    }
    const MeshCheck c = check_mesh(split);
    if (added > 0 && c.boundary_edges == 0 && c.nonmanifold_edges == 0 && c.manifold &&
        !c.degenerate) {
      mesh = std::move(split);
      check = c;
      read.split_vertices = added;
    }
  }
  if (check.boundary_edges > 0)
    bad(path, "mesh is open: " + plural(check.boundary_edges, "boundary edge") +
                  " (fill it anyway with `clumpkit fill --allow-open`, or close it with "
                  "`clumpkit repair " +
                  path + " -o CLOSED.stl`)");
  if (check.nonmanifold_edges > 0)
    bad(path, "mesh is not manifold: " + plural(check.nonmanifold_edges, "edge") +
                  " shared by more than two triangles, and split there it is not closed lobes "
                  "(`clumpkit repair " +
                  path + " -o CLOSED.stl` removes fins and debris and closes what is left)");
  if (!check.manifold)
    bad(path,
        "mesh is not manifold: a vertex joins separate surface sheets that do not close when "
        "split (`clumpkit repair " +
            path + " -o CLOSED.stl`)");
  bool reoriented = false;
  try {
    if (!check.oriented || check.volume < 0) reoriented = orient_outward(mesh);
    // Several shells: read by their orientation, never with an overlap counted twice.
    reoriented = orient_shells(mesh, &read.shells) || reoriented;
  } catch (const InvalidInput& e) {
    bad(path, std::string("cannot orient the mesh: ") + e.what());
  }
  // Relative to the bounding box so that a flat "solid" with round-off volume is rejected too.
  const auto bb = bounding_box(mesh);
  if (!((bb[1] - bb[0]).norm() >= kMinLength))
    bad(path, "mesh is smaller than 1e-30 across: bounding-box diagonal " +
                  format_number((bb[1] - bb[0]).norm()));
  const double volume = reoriented ? signed_volume(mesh) : check.volume;  // the same sum
  if (!(volume > 1e-12 * std::pow((bb[1] - bb[0]).norm(), 3)))
    bad(path, "mesh encloses no volume: signed volume " + format_number(volume, 6) +
                  " after orientation");
  read.reoriented = reoriented;
}

std::vector<std::string> mesh_read_notes(const std::string& path, const MeshReadReport& r) {
  std::vector<std::string> notes;
  if (r.merged_vertices > 0)
    notes.push_back(path + ": merged " + plural(r.merged_vertices, "vertex copy") +
                    " into the vertex at the same position (seams of normals or UVs)");
  if (r.removed_triangles > 0)
    notes.push_back(path + ": removed " + plural(r.removed_triangles, "degenerate triangle") +
                    " (zero area or a repeated corner)");
  if (r.lines_with_extra_values > 0)
    notes.push_back(path + ": ignored the values at the end of " +
                    plural(r.lines_with_extra_values, "line") +
                    " beyond those the PLY header declares");
  if (r.split_vertices > 0)
    notes.push_back(path +
                    ": closed lobes touch along an edge or at a vertex; read as touching "
                    "shells (" +
                    std::to_string(r.split_vertices) +
                    (r.split_vertices == 1 ? " vertex" : " vertices") + " split)");
  if (r.reoriented)
    notes.push_back(path + ": triangles were not consistently outward; re-oriented");
  if (r.shells > 1)
    notes.push_back(path + ": " + std::to_string(r.shells) +
                    " closed shells read as one solid (nested shells by their orientation)");
  return notes;
}

void write_mesh(const std::string& path, const Mesh& mesh) {
  write_mesh(path, mesh, mesh_format_from_path(path));
}

void write_mesh(const std::string& path, const Mesh& mesh, MeshFormat format) {
  const int nv = static_cast<int>(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    for (int k : t)
      if (k < 0 || k >= nv)
        bad(path, "cannot write mesh: vertex index " + std::to_string(k) + " out of range (" +
                      std::to_string(nv) + " vertices)");
  if (format == MeshFormat::Stl && mesh.triangles.size() > UINT32_MAX)
    bad(path, "too many triangles for binary STL");
  const bool text = format == MeshFormat::StlAscii || format == MeshFormat::Obj;
  write_file_atomically(
      path,
      [&](std::ostream& os) {
        switch (format) {
          case MeshFormat::Stl:
            return mesh_format::write_stl_binary(os, mesh);
          case MeshFormat::StlAscii:
            return mesh_format::write_stl_ascii(os, mesh);
          case MeshFormat::Obj:
            return mesh_format::write_obj(os, mesh);
          case MeshFormat::Ply:
            return mesh_format::write_ply(os, mesh);
        }
      },
      !text);
}

}  // namespace clumpkit
