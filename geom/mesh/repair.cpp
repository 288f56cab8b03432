#include "geom/mesh/repair.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/cgal_surface.h"
#include "geom/mesh/deviation.h"
#include "geom/mesh/shell_union.h"
#include "geom/mesh/weld.h"
#include "geom/mesh/wrap.h"
#include "geom/sphere.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal_surface::Point;
using cgal_surface::SurfaceMesh;

namespace {

[[noreturn]] void refuse(const std::string& step, const std::string& what) {
  throw InvalidInput("repair, step '" + step + "': " + what);
}

Vec3 vec(const Point& p) {
  return Vec3(p.x(), p.y(), p.z());
}

std::string at(const Vec3& p) {
  return "at (" + format_number(p.x(), 6) + ", " + format_number(p.y(), 6) + ", " +
         format_number(p.z(), 6) + ")";
}

Vec3 face_centroid(const SurfaceMesh& sm, SurfaceMesh::Face_index f) {
  Vec3 c = Vec3::Zero();
  int n = 0;
  for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) c += vec(sm.point(v)), ++n;
  return c / std::max(n, 1);
}

// The border halfedges of the hole of `h`, in order.
std::vector<SurfaceMesh::Halfedge_index> hole_cycle(const SurfaceMesh& sm,
                                                    SurfaceMesh::Halfedge_index h) {
  std::vector<SurfaceMesh::Halfedge_index> cycle;
  for (const auto e : CGAL::halfedges_around_face(h, sm)) cycle.push_back(e);
  return cycle;
}

// Step 1: the triangles kept. A triangle's copies are grouped by their corner set; within a
// group the orientation is the parity of the corners' order.
std::vector<std::array<int, 3>> drop_duplicates(const Mesh& mesh, RepairReport& r) {
  struct Copies {
    int even = 0, odd = 0;
    bool kept = false;
  };
  std::map<std::array<int, 3>, Copies> copies;  // by sorted corners
  auto key_of = [](const std::array<int, 3>& t) {
    std::array<int, 3> k = t;
    std::sort(k.begin(), k.end());
    return k;
  };
  auto even = [](const std::array<int, 3>& t) {  // t a cyclic rotation of its sorted order
    const int m = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
    return t[(m + 1) % 3] < t[(m + 2) % 3];
  };
  auto repeated = [](const std::array<int, 3>& t) {
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
  };
  for (const auto& t : mesh.triangles)
    if (!repeated(t)) ++(even(t) ? copies[key_of(t)].even : copies[key_of(t)].odd);
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : mesh.triangles) {
    if (repeated(t)) {
      ++r.repeated_vertex_triangles;
    } else if (Copies& c = copies[key_of(t)]; c.even > 0 && c.odd > 0) {
      ++r.double_wall_triangles;
    } else if (c.kept) {
      ++r.duplicate_triangles;
    } else {
      c.kept = true;
      kept.push_back(t);
    }
  }
  return kept;
}

// Step 4: components with fewer faces than `fraction` of the largest one's removed.
void remove_small_components(SurfaceMesh& sm, double fraction, RepairReport& r) {
  auto component = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:component").first;
  const std::size_t count = PMP::connected_components(sm, component);
  std::vector<std::size_t> faces(count, 0);
  for (const auto f : sm.faces()) ++faces[component[f]];
  const std::size_t largest = *std::max_element(faces.begin(), faces.end());
  std::vector<std::size_t> small;
  for (std::size_t c = 0; c < count; ++c)
    if (static_cast<double>(faces[c]) < fraction * static_cast<double>(largest)) {
      small.push_back(c);
      ++r.small_components;
      r.small_component_triangles += static_cast<int>(faces[c]);
    }
  if (!small.empty()) PMP::remove_connected_components(sm, small, component);
  sm.remove_property_map(component);
  sm.collect_garbage();
}

// Step 5: one hole closed, by the best method that works.
RepairHole close_hole(SurfaceMesh& sm, SurfaceMesh::Halfedge_index h) {
  RepairHole hole;
  const std::vector<SurfaceMesh::Halfedge_index> cycle = hole_cycle(sm, h);
  hole.edges = static_cast<int>(cycle.size());
  for (const auto e : cycle) hole.at += vec(sm.point(sm.target(e)));
  hole.at /= std::max<double>(1.0, static_cast<double>(cycle.size()));
  std::vector<SurfaceMesh::Face_index> patch;
  std::vector<SurfaceMesh::Vertex_index> added;
  const auto faired = PMP::triangulate_refine_and_fair_hole(sm, h, std::back_inserter(patch),
                                                            std::back_inserter(added));
  if (!patch.empty()) {
    hole.method = std::get<0>(faired) ? "refined and faired" : "refined";
    return hole;
  }
  PMP::triangulate_hole(sm, h, std::back_inserter(patch));
  if (!patch.empty()) {
    hole.method = "triangulated";
    return hole;
  }
  // A fan from the boundary's centroid: each border halfedge u -> v gets the face (u, v, c).
  const SurfaceMesh::Vertex_index c = sm.add_vertex(Point(hole.at.x(), hole.at.y(), hole.at.z()));
  for (const auto e : cycle)
    if (sm.add_face(sm.source(e), sm.target(e), c) == SurfaceMesh::null_face())
      refuse("holes", "a hole of " + std::to_string(hole.edges) +
                          " edges could not be closed (refined and faired, triangulated, planar "
                          "cap) " +
                          at(hole.at));
  hole.method = "planar cap";
  return hole;
}

// A capped surface bounding less than this fraction of its diagonal cubed encloses nothing: a
// sheet capped on itself bounds exactly zero up to rounding (1e-16 of it), a plate of a
// thousandth of its width 1e-4.
constexpr double kNoVolume = 1e-9;

void check_wrap_options(const RepairOptions& o) {
  auto fraction = [](double v, const char* name) {
    if (!(std::isfinite(v) && v > 0 && v <= 1))
      throw InvalidInput(std::string("repair: ") + name +
                         " must lie in (0, 1] (a fraction of the bounding-box diagonal), got " +
                         format_number(v));
  };
  fraction(o.wrap_alpha, "wrap_alpha");
  fraction(o.wrap_offset, "wrap_offset");
  if (!(o.local_limit >= 0 && o.local_limit <= 1))
    throw InvalidInput("repair: local_limit must lie in [0, 1], got " +
                       format_number(o.local_limit));
  if (o.local_rounds < 0)
    throw InvalidInput("repair: local_rounds must be at least 0, got " +
                       std::to_string(o.local_rounds));
}

// Zero-area and nearly zero-area triangles of a closed manifold mesh collapsed or flipped away
// (CGAL PMP remove_degenerate_faces, then experimental::remove_almost_degenerate_faces for caps
// with an angle over 179° and needles whose edges differ by 10⁴ or more, collapsing edges of at
// most 1e-4 of the diagonal). What remains degenerate is the caller's to judge.
void collapse_slivers(Mesh& mesh) {
  SurfaceMesh sm = cgal_surface::to_surface_mesh(mesh);
  const auto box = bounding_box(mesh);
  PMP::remove_degenerate_faces(sm);
  sm.collect_garbage();
  PMP::experimental::remove_almost_degenerate_faces(sm, std::cos(179.0 * kPi / 180.0), 1e4,
                                                    1e-4 * (box[1] - box[0]).norm());
  sm.collect_garbage();
  mesh = cgal_surface::from_surface_mesh(sm);
}

// Whether the closed surface reads back as a solid once written: its coincident vertices joined
// (as a reader welds them, at the STL reader's 1e-9 of the diagonal), it is a closed manifold,
// or closed lobes that only touch along an edge or at a vertex. A shell pinched onto itself, a
// split that holes met at without rejoining, is neither.
bool reads_back(const Mesh& mesh) {
  Mesh welded = mesh;
  weld_vertices(welded, 1e-9);
  MeshCheck c = check_mesh(welded);
  if (c.closed && c.manifold) return true;
  if (c.boundary_edges != 0) return false;
  split_nonmanifold(welded);
  c = check_mesh(welded);
  return c.closed && c.manifold;
}

// Steps 7 and 8 on the closed surface of step 5: crossings mended in place (locally within a
// shell, then shells through each other by union), slivers collapsed, else the surface wrapped.
void mend_crossings(Mesh& mesh, const RepairOptions& o, RepairReport& r) {
  const Crossings found = find_crossings(mesh);
  r.crossings_within = found.within_shells;
  r.crossings_between = found.between_shells;
  Crossings now = found;
  const Mesh closed = mesh;
  bool local = false;
  if (o.wrap != WrapMode::always && found.total() > 0) {
    // Crossings on more than a few percent of the triangles are a soup, not a scan's folds: the
    // local mend would smooth and refill most of the surface, in minutes, and leave it for the
    // wrap all the same (tests/bench/repair_corpus.py on public meshes); the union is still tried.
    const double limit = std::max(32.0, o.local_limit * static_cast<double>(mesh.triangles.size()));
    if (found.within_shells > 0 && o.local_rounds > 0 && found.within_shells <= limit) {
      r.local_rounds = mend_crossings_locally(mesh, o.local_rounds);
      for (const CrossingRound& round : r.local_rounds)
        local = local || round.pairs_after < round.pairs_before;
    }
    if (local) now = find_crossings(mesh);
    if (now.between_shells > 0) {
      r.united_shells = unite_crossing_shells(mesh);
      if (r.united_shells > 0) now = find_crossings(mesh);
    }
    r.changed = local || r.united_shells > 0;
  }
  // Slivers, the input's own or those the mends leave (corefinement's needles where an
  // intersection line passes near a vertex, a refilled patch's caps), which every reader refuses
  // as degenerate: collapsed, and what then still crosses is for the wrap.
  if (o.wrap != WrapMode::always && check_mesh(mesh).degenerate) {
    const std::size_t before = mesh.triangles.size();
    collapse_slivers(mesh);
    r.slivers = static_cast<int>(before - std::min(before, mesh.triangles.size()));
    r.changed = r.changed || r.slivers > 0;
    now = find_crossings(mesh);
  }
  const bool sound = now.total() == 0 && !check_mesh(mesh).degenerate && reads_back(mesh);
  if (sound && found.total() > 0)
    r.mended_by = local && r.united_shells > 0 ? "local and union"
                  : local                      ? "local"
                  : r.united_shells > 0        ? "union"
                                               : "slivers";
  if (o.wrap == WrapMode::always || (o.wrap == WrapMode::fallback && !sound)) {
    const auto t0 = std::chrono::steady_clock::now();
    r.wrap_alpha = o.wrap_alpha * r.diagonal;
    r.wrap_offset = o.wrap_offset * r.diagonal;
    mesh = alpha_wrap(closed, r.wrap_alpha, r.wrap_offset);
    r.wrap_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.wrapped = r.changed = true;
    r.mended_by = sound ? "" : "wrap";
  }
}

// How far the mends or the wrap moved the surface: the sampled distance from `mesh` to the
// closed surface before them, and the warning of a wrap that moved it by more than the bound.
void measure_change(const Mesh& mesh, const Mesh& closed, const RepairOptions& options,
                    RepairReport& r) {
  const SurfaceDeviation d = surface_deviation(mesh, closed);
  r.distance_max = d.max / r.diagonal;
  r.distance_mean = d.mean / r.diagonal;
  r.distance_max_at = d.at;
  if (r.wrapped && r.distance_max > options.wrap_warn_distance)
    r.warnings.push_back("the wrap moved the surface by up to " + format_number(d.max, 4) + " (" +
                         format_number(100 * r.distance_max, 3) +
                         " % of the bounding-box diagonal, more than " +
                         format_number(100 * options.wrap_warn_distance, 3) + " %) " + at(d.at) +
                         ": a cavity or gap narrower than alpha was bridged");
}

}  // namespace

WrapMode wrap_mode_from_string(const std::string& text, const std::string& field) {
  if (text == "fallback") return WrapMode::fallback;
  if (text == "always") return WrapMode::always;
  if (text == "never") return WrapMode::never;
  throw InvalidInput(field + " must be fallback, always or never, got '" + text + "'");
}

const char* to_string(WrapMode mode) {
  switch (mode) {
    case WrapMode::fallback:
      return "fallback";
    case WrapMode::always:
      return "always";
    case WrapMode::never:
      return "never";
  }
  return "fallback";
}

RepairReport repair_mesh(Mesh& mesh, const RepairOptions& options) {
  if (!(options.min_component >= 0.0 && options.min_component <= 1.0))
    throw InvalidInput("repair: min_component must lie in [0, 1], got " +
                       format_number(options.min_component));
  check_wrap_options(options);
  RepairReport r;
  {
    const MeshCheck before = check_mesh(mesh);
    r.boundary_edges_before = before.boundary_edges;
    r.volume_before = before.volume;
  }
  const std::vector<std::array<int, 3>> kept = drop_duplicates(mesh, r);
  if (kept.empty())
    refuse("duplicates",
           "no triangle is left (repeated corners, double walls): the mesh encloses no volume");

  r.nonmanifold_edges = check_mesh(Mesh{mesh.vertices, kept}).nonmanifold_edges;
  cgal_surface::Soup soup = cgal_surface::used_soup(mesh, kept);
  std::vector<Point>& points = soup.points;
  std::vector<std::vector<std::size_t>>& polys = soup.polygons;
  const std::vector<std::vector<std::size_t>> as_read = polys;
  const std::size_t points_before = points.size();
  PMP::orient_polygon_soup(points, polys);
  r.split_vertices = static_cast<int>(points.size() - points_before);
  for (std::size_t k = 0; k < polys.size() && k < as_read.size() && !r.reoriented; ++k)
    r.reoriented = polys[k] != as_read[k];
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polys, sm);

  const std::size_t faces_before = sm.number_of_faces();
  PMP::remove_degenerate_faces(sm);
  sm.collect_garbage();
  r.degenerate_triangles =
      static_cast<int>(faces_before - std::min<std::size_t>(faces_before, sm.number_of_faces()));
  if (sm.number_of_faces() == 0)
    refuse("degenerate",
           "no triangle is left (every one has zero area): the "
           "mesh encloses no volume");

  if (options.min_component > 0.0) remove_small_components(sm, options.min_component, r);

  std::vector<SurfaceMesh::Halfedge_index> holes;
  PMP::extract_boundary_cycles(sm, std::back_inserter(holes));
  for (const SurfaceMesh::Halfedge_index h : holes) {
    r.closed_holes.push_back(close_hole(sm, h));
    ++r.holes;
  }
  for (const auto h : sm.halfedges())
    if (sm.is_border(h))
      refuse("holes", "the surface is still open " + at(vec(sm.point(sm.target(h)))));
  // Holes that met at a split vertex were closed as one boundary through both copies: welded
  // again, the copies' zero-length edges vanish and the vertex is whole, when that leaves a
  // closed manifold; lobes that only touch (a bow-tie, cubes on an edge) stay split.
  if (r.split_vertices > 0) {
    Mesh welded = cgal_surface::from_surface_mesh(sm);
    weld_vertices(welded);
    const MeshCheck c = check_mesh(welded);
    if (c.closed && c.manifold) {
      sm = cgal_surface::to_surface_mesh(welded);
      r.rejoined_vertices = r.split_vertices;
    }
  }

  Mesh capped = cgal_surface::from_surface_mesh(sm);
  {
    const auto box = bounding_box(capped);  // without the debris removed above
    r.diagonal = (box[1] - box[0]).norm();
  }
  r.volume_capped = check_mesh(capped).volume;
  // A sheet, a single triangle or the faces of a point cloud close onto themselves: the capped
  // surface bounds nothing, and wrapping it would invent a slab of twice the offset.
  if (!(std::abs(r.volume_capped) > kNoVolume * std::pow(r.diagonal, 3)))
    refuse("volume", "the surface encloses no volume: a sheet or loose faces, capped, bound " +
                         format_number(r.volume_capped) + " (bounding-box diagonal " +
                         format_number(r.diagonal) + ")");
  const Mesh closed = capped;  // what the mends and the wrap are measured against
  mend_crossings(capped, options, r);
  // Faces of the shells split at a non-manifold edge or vertex touch there without crossing.
  sm = cgal_surface::to_surface_mesh(capped);
  // Unchanged and found free of crossings above, the surface needs no second search.
  const bool check = r.changed || r.crossings_within + r.crossings_between > 0;
  const auto crossing =
      check ? cgal_surface::crossing_faces(sm) : decltype(cgal_surface::crossing_faces(sm)){};
  if (!crossing.empty())
    refuse("self-intersection check",
           "the closed surface intersects itself, so it bounds no volume (" +
               std::to_string(crossing.size()) +
               " pairs of faces cross: shells through each other, a fold, or a hole's patch "
               "through the surface" +
               (options.wrap == WrapMode::never ? "; --wrap fallback would wrap it" : "") +
               "); first " + at(face_centroid(sm, crossing.front().first)));
  PMP::orient_to_bound_a_volume(sm);
  sm.collect_garbage();
  mesh = cgal_surface::from_surface_mesh(sm);
  const MeshCheck after = check_mesh(mesh);
  const std::string wrap_hint =
      options.wrap == WrapMode::never ? "; --wrap fallback would wrap it" : "";
  if (after.degenerate)
    refuse("degenerate", "the closed surface keeps a triangle of (nearly) zero area" + wrap_hint);
  if (!reads_back(mesh))
    refuse("self-intersection check",
           "the closed surface touches itself along an edge or at a vertex of one shell, so a "
           "reader joining equal positions would find it non-manifold" +
               wrap_hint);
  r.boundary_edges_after = after.boundary_edges;
  r.volume_after = after.volume;
  if (!(r.volume_after > 1e-12 * std::pow(r.diagonal, 3)))
    refuse("orientation", "the closed surface encloses no volume (signed volume " +
                              format_number(r.volume_after) + ")");
  if (r.changed) measure_change(mesh, closed, options, r);
  return r;
}

std::size_t split_nonmanifold(Mesh& mesh) {
  const std::vector<std::array<int, 3>> all = mesh.triangles;
  cgal_surface::Soup soup = cgal_surface::used_soup(mesh, all);
  const std::size_t before = soup.points.size();
  PMP::orient_polygon_soup(soup.points, soup.polygons);
  const std::size_t added = soup.points.size() - before;
  Mesh out;
  for (const Point& p : soup.points) out.vertices.push_back(vec(p));
  for (const auto& poly : soup.polygons) {
    if (poly.size() != 3) throw NumericError("CGAL produced a polygon that is not a triangle");
    out.triangles.push_back(
        {static_cast<int>(poly[0]), static_cast<int>(poly[1]), static_cast<int>(poly[2])});
  }
  mesh = std::move(out);
  return added;
}

std::size_t collapse_degenerate_triangles(Mesh& mesh) {
  SurfaceMesh sm = cgal_surface::to_surface_mesh(mesh);
  std::size_t degenerate = 0;
  for (auto f : sm.faces()) degenerate += PMP::is_degenerate_triangle_face(f, sm) ? 1 : 0;
  if (!PMP::remove_degenerate_faces(sm))
    throw InvalidInput("a degenerate triangle (zero area) could not be removed");
  sm.collect_garbage();
  mesh = cgal_surface::from_surface_mesh(sm);
  return degenerate;
}

}  // namespace clumpkit
