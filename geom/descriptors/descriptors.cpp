#include "geom/descriptors/descriptors.h"

#include "geom/descriptors/farthest_pair.h"
#include "geom/errors.h"
#include "geom/mesh/cgal_mesh.h"
#include "geom/sphere.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

namespace clumpkit {

namespace {

using Vec2 = Eigen::Vector2d;

// Relative gap below which two principal moments count as equal (axes then undefined).
constexpr double kDegenerateMoments = 1e-8;
// At most this many face-normal candidates are tried for an isotropic inertia tensor.
constexpr int kIsotropicCandidates = 32;

double cross2(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// 2-D convex hull (Andrew's monotone chain), counter-clockwise, without collinear points.
std::vector<Vec2> hull_2d(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  const size_t n = p.size();
  if (n < 3) return p;
  std::vector<Vec2> h(2 * n);
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (size_t i = n - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// Orthonormal (u, v) with (u, v, d) right-handed, d = direction / |direction|. u is built from
// the world axis least aligned with d, so the frame depends only on the direction.
void plane_basis(const Vec3& d, Vec3& u, Vec3& v) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(d[i]) < std::abs(d[k])) k = i;
  const Vec3 a = Vec3::Unit(k);
  u = (a - a.dot(d) * d).normalized();
  v = d.cross(u);
}

// Makes the largest-magnitude component of an axis positive (deterministic sign).
Vec3 canonical_sign(const Vec3& a) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(a[i]) > std::abs(a[k])) k = i;
  return a[k] < 0.0 ? Vec3(-a) : a;
}

double extent_along(const std::vector<Vec3>& pts, const Vec3& axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& p : pts) {
    const double s = p.dot(axis);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return pts.empty() ? 0.0 : hi - lo;
}

// Direction of one side of the minimum-area rectangle enclosing `pts` (one side of it is flush
// with a convex-hull edge). Writes the rectangle area.
Vec2 min_area_rectangle(const std::vector<Vec2>& pts, double& area) {
  const std::vector<Vec2> h = hull_2d(pts);
  area = 0.0;
  if (h.size() < 3) return Vec2(1.0, 0.0);
  Vec2 best_dir(1.0, 0.0);
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < h.size(); ++i) {
    const Vec2 e = (h[(i + 1) % h.size()] - h[i]).normalized();
    const Vec2 n(-e.y(), e.x());
    double lo_e = std::numeric_limits<double>::infinity(), hi_e = -lo_e, lo_n = lo_e, hi_n = -lo_e;
    for (const auto& p : h) {
      lo_e = std::min(lo_e, p.dot(e));
      hi_e = std::max(hi_e, p.dot(e));
      lo_n = std::min(lo_n, p.dot(n));
      hi_n = std::max(hi_n, p.dot(n));
    }
    const double a = (hi_e - lo_e) * (hi_n - lo_n);
    if (a < best * (1.0 - 1e-12)) {
      best = a;
      best_dir = e;
    }
  }
  area = best;
  return best_dir;
}

// Rotates the in-plane pair (p, q) to the sides of the minimum-area rectangle of the points
// projected on that plane. Writes the rectangle area.
void align_in_plane(const std::vector<Vec3>& pts, Vec3& p, Vec3& q, double& area) {
  std::vector<Vec2> flat;
  flat.reserve(pts.size());
  for (const auto& x : pts) flat.emplace_back(x.dot(p), x.dot(q));
  const Vec2 e = min_area_rectangle(flat, area);
  const Vec3 a = (e.x() * p + e.y() * q).normalized();
  const Vec3 b = (-e.y() * p + e.x() * q).normalized();
  p = a;
  q = b;
}

// Axes for an isotropic inertia tensor (cube, regular polyhedra, sphere): the smallest box among
// candidates with one axis along a face normal (normals grouped, largest total area first) and
// the other two along the minimum-area rectangle of the projection on the perpendicular plane.
Mat3 isotropic_axes(const Mesh& mesh, const std::vector<Vec3>& rel) {
  std::map<std::array<long long, 3>, std::pair<Vec3, double>> groups;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const double len = n.norm();
    if (!(len > 0.0)) continue;
    const Vec3 c = canonical_sign(n / len);
    const std::array<long long, 3> key{std::llround(c.x() * 1e8), std::llround(c.y() * 1e8),
                                       std::llround(c.z() * 1e8)};
    auto [it, inserted] = groups.emplace(key, std::make_pair(c, 0.0));
    it->second.second += 0.5 * len;
  }
  std::vector<std::pair<Vec3, double>> cand;
  cand.reserve(groups.size());
  for (const auto& g : groups) cand.push_back(g.second);
  std::stable_sort(cand.begin(), cand.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  if (cand.size() > static_cast<size_t>(kIsotropicCandidates)) cand.resize(kIsotropicCandidates);

  Mat3 best_axes = Mat3::Identity();
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : cand) {
    const Vec3 n = c.first;
    Vec3 p, q;
    plane_basis(n, p, q);
    double area = 0.0;
    align_in_plane(rel, p, q, area);
    const double volume = area * extent_along(rel, n);
    if (volume < best * (1.0 - 1e-12)) {
      best = volume;
      best_axes.col(0) = n;
      best_axes.col(1) = p;
      best_axes.col(2) = q;
    }
  }
  return best_axes;
}

double polygon_signed_area(const std::vector<Vec2>& poly) {
  double a = 0.0;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

double polygon_perimeter(const std::vector<Vec2>& poly) {
  double s = 0.0;
  for (size_t i = 0, n = poly.size(); i < n; ++i) s += (poly[(i + 1) % n] - poly[i]).norm();
  return s;
}

// Caliper dimensions of a point set (see caliper_dimensions); callers pass convex-hull vertices.
CaliperDimensions caliper_of_points(const std::vector<Vec3>& pts) {
  CaliperDimensions c;
  const size_t n = pts.size();
  const FarthestPair longest = farthest_pair(pts);
  if (!(longest.squared_distance > 0.0)) return c;
  c.L = std::sqrt(longest.squared_distance);
  c.dir_L = canonical_sign((pts[longest.j] - pts[longest.i]) / c.L);

  // W: diameter of the projection on the plane perpendicular to L (attained at hull vertices of
  // the projection).
  Vec3 p, q;
  plane_basis(c.dir_L, p, q);
  std::vector<Vec2> flat;
  flat.reserve(n);
  for (const auto& x : pts) flat.emplace_back(x.dot(p), x.dot(q));
  const std::vector<Vec2> h = hull_2d(std::move(flat));
  std::vector<Vec3> lifted;  // z = 0 adds nothing to any squared distance
  lifted.reserve(h.size());
  for (const Vec2& x : h) lifted.emplace_back(x.x(), x.y(), 0.0);
  const FarthestPair widest = farthest_pair(lifted);
  const double wbest = widest.squared_distance;
  const Vec2 wdir = wbest > 0.0 ? Vec2(h[widest.j] - h[widest.i]) : Vec2(1.0, 0.0);
  c.W = std::sqrt(wbest);
  c.dir_W = wbest > 0.0 ? canonical_sign((wdir.x() * p + wdir.y() * q).normalized()) : p;
  c.dir_H = c.dir_L.cross(c.dir_W).normalized();
  c.H = extent_along(pts, c.dir_H);
  return c;
}

// ---- Non-convex silhouette: arrangement of projected contour edges ----

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Arr_segment_traits_2<EK>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using EPoint = EK::Point_2;

std::vector<Vec2> arrangement_outline(const Mesh& mesh, const Vec3& d, const Vec3& u,
                                      const Vec3& v) {
  const int nf = static_cast<int>(mesh.triangles.size());
  // Facing of each triangle: +1 towards d, -1 away, 0 edge-on (within rounding).
  std::vector<signed char> facing(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const double s = n.dot(d);
    facing[f] = std::abs(s) <= 1e-12 * n.norm() ? 0 : (s > 0.0 ? 1 : -1);
  }
  // Undirected edges with their triangles, the uses of each edge adjacent.
  const std::vector<EdgeUse> uses = edge_uses(mesh);

  std::vector<Vec2> proj(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    proj[i] = Vec2(mesh.vertices[i].dot(u), mesh.vertices[i].dot(v));

  std::vector<Traits::Curve_2> segments;
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    // Keep edges where facing changes or a face is edge-on (contour), boundary edges and
    // non-manifold edges. Extra edges are harmless: every edge projects inside the silhouette.
    bool keep = (j - i) != 2;
    if (!keep) {
      const int s1 = facing[uses[i].face], s2 = facing[uses[i + 1].face];
      keep = s1 != s2 || s1 == 0;
    }
    if (keep) {
      const int a = static_cast<int>(uses[i].key >> 32);
      const int b = static_cast<int>(uses[i].key & 0xffffffffu);
      if (proj[a] != proj[b])
        segments.emplace_back(EPoint(proj[a].x(), proj[a].y()), EPoint(proj[b].x(), proj[b].y()));
    }
    i = j;
  }
  if (segments.empty()) return {};

  Arrangement arr;
  CGAL::insert(arr, segments.begin(), segments.end());

  // The outer boundary of each connected piece is an inner CCB of the unbounded face; keep the
  // one enclosing the largest area. Antenna edges (twin on the same face) are dropped.
  const auto uf = arr.unbounded_face();
  std::vector<Vec2> best;
  double best_area = 0.0;
  for (auto cit = uf->inner_ccbs_begin(); cit != uf->inner_ccbs_end(); ++cit) {
    std::vector<EPoint> pts;
    auto he = *cit;
    const auto first = he;
    do {
      if (he->twin()->face() != uf) pts.push_back(he->source()->point());
      he = he->next();
    } while (he != first);
    // Drop vertices lying exactly on the segment between their neighbours.
    bool changed = true;
    while (changed && pts.size() > 3) {
      changed = false;
      std::vector<EPoint> kept;
      kept.reserve(pts.size());
      const size_t n = pts.size();
      for (size_t i = 0; i < n; ++i) {
        const EPoint& prev = kept.empty() ? pts[n - 1] : kept.back();
        const EPoint& next = pts[(i + 1) % n];
        if (CGAL::collinear(prev, pts[i], next) &&
            CGAL::collinear_are_ordered_along_line(prev, pts[i], next)) {
          changed = true;
          continue;
        }
        kept.push_back(pts[i]);
      }
      pts.swap(kept);
    }
    std::vector<Vec2> poly;
    poly.reserve(pts.size());
    for (const auto& p : pts) poly.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    const double a = polygon_signed_area(poly);
    if (std::abs(a) > best_area) {
      best_area = std::abs(a);
      if (a < 0.0) std::reverse(poly.begin(), poly.end());
      best = std::move(poly);
    }
  }
  return best;
}

}  // namespace

PrincipalFrame principal_frame(const Mesh& mesh) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    throw InvalidInput("principal_frame: the mesh has no triangles");
  const double volume = signed_volume(mesh);
  if (!(volume > 0.0))
    throw InvalidInput("principal_frame: mesh volume must be positive, got " +
                       std::to_string(volume));
  PrincipalFrame f;
  f.centroid = solid_centroid(mesh);
  std::vector<Vec3> rel;
  rel.reserve(mesh.vertices.size());
  for (const auto& p : mesh.vertices) rel.push_back(p - f.centroid);

  Eigen::SelfAdjointEigenSolver<Mat3> es(solid_inertia(mesh, f.centroid));
  if (es.info() != Eigen::Success)
    throw NumericError("principal_frame: eigen-decomposition of the inertia tensor failed");
  const Vec3 lam = es.eigenvalues();  // ascending
  Mat3 axes = es.eigenvectors();
  const double tol = kDegenerateMoments * lam.cwiseAbs().maxCoeff();
  const bool eq01 = lam(1) - lam(0) <= tol;
  const bool eq12 = lam(2) - lam(1) <= tol;
  if (eq01 && eq12) {
    axes = isotropic_axes(mesh, rel);
  } else if (eq01 || eq12) {
    // Two equal moments: any axes in their plane are principal; take the ones of the smallest
    // enclosing rectangle so that boxes keep their edge directions.
    const int i = eq01 ? 0 : 1;
    Vec3 p = axes.col(i), q = axes.col(i + 1);
    double area = 0.0;
    align_in_plane(rel, p, q, area);
    axes.col(i) = p;
    axes.col(i + 1) = q;
  }

  Vec3 ext;
  for (int j = 0; j < 3; ++j) ext(j) = extent_along(rel, axes.col(j));
  // S ≤ I ≤ L by extent. Extents equal to rounding (the polyhedra of E = F = 1 are stretched to
  // three equal ones) are ordered by moment of inertia, largest first (the mass spreads farthest
  // about that axis: mass-wise it is the shortest), else the labels, and the per-view roundness
  // with them, would swap under any rotation or retriangulation of the mesh. Equal moments too:
  // the order the frame was built in. An insertion sort: three items, and a comparator with
  // tolerances need not be a strict weak order.
  const double tie = 1e-9 * ext.maxCoeff();
  auto before = [&](int a, int b) {
    if (std::abs(ext(a) - ext(b)) > tie) return ext(a) < ext(b);
    if (std::abs(lam(a) - lam(b)) > tol) return lam(a) > lam(b);
    return a < b;
  };
  std::array<int, 3> order{0, 1, 2};
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && before(order[j], order[j - 1]); --j) std::swap(order[j], order[j - 1]);
  // The extents themselves stay sorted, so S ≤ I ≤ L holds exactly and S is the smallest (the
  // fill's voxel size): within a tie the axis they are attached to differs by under 1e-9 of L.
  Vec3 sorted = ext;
  std::sort(sorted.data(), sorted.data() + 3);
  for (int j = 0; j < 3; ++j) {
    f.axes.col(j) = canonical_sign(axes.col(order[j]).normalized());
    f.extents(j) = sorted(j);
  }
  if (f.axes.determinant() < 0.0) f.axes.col(0) = -f.axes.col(0);
  return f;
}

namespace {

// The vertices that can be corners of the mesh's convex hull: all but the flat ones, those whose
// incident triangles share one plane (unit normals within 1e-9) and whose edges each have two
// triangles (not on a boundary). A flat vertex lies inside the polygon of its neighbours, so in
// their hull: dropping it leaves the hull as it was, and a subdivided or scanned-and-decimated
// mesh's planar regions no longer feed the hull's triangulation thousands of coplanar points.
std::vector<Vec3> hull_points(const Mesh& mesh) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<Vec3> normal(nv, Vec3::Zero());
  std::vector<std::uint8_t> flat(nv, 0), seen(nv, 0);
  for (const auto& t : mesh.triangles) {
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double len = n.norm();
    for (int k = 0; k < 3; ++k) {
      const int v = t[k];
      if (!(len > 0.0)) {
        seen[v] = 1;
        flat[v] = 0;
      } else if (!seen[v]) {
        seen[v] = 1;
        flat[v] = 1;
        normal[v] = n / len;
      } else if ((n / len - normal[v]).norm() > 1e-9) {
        flat[v] = 0;
      }
    }
  }
  // Each edge once (its uses are adjacent); one not used by exactly two triangles is a boundary.
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  std::vector<std::array<int, 2>> edges;
  for (std::size_t a = 0; a < uses.size();) {
    std::size_t b = a;
    while (b < uses.size() && uses[b].key == uses[a].key) ++b;
    const int lo = int(uses[a].key >> 32), hi = int(uses[a].key & 0xffffffffu);
    if (b - a != 2) flat[lo] = flat[hi] = 0;
    edges.push_back({lo, hi});
    a = b;
  }
  // A crease vertex between two of its neighbours on a line is no corner either (a subdivided
  // edge's points): dropped when it lies within 1e-12 of the box diagonal of the line through
  // them, which moves the hull by at most that much. Neighbours from the edges, in compressed
  // rows.
  std::vector<int> start(nv + 1, 0);
  for (const auto& e : edges) {
    ++start[e[0] + 1];
    ++start[e[1] + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> ring(static_cast<std::size_t>(start[nv]));
  std::vector<int> cursor(start.begin(), start.end() - 1);
  for (const auto& e : edges) {
    ring[std::size_t(cursor[e[0]]++)] = e[1];
    ring[std::size_t(cursor[e[1]]++)] = e[0];
  }
  const auto box = bounding_box(mesh);
  const double tol = 1e-12 * (box[1] - box[0]).norm();
  auto between_neighbours = [&](std::size_t v) {
    const Vec3& p = mesh.vertices[v];
    for (int x = start[v]; x < start[v + 1]; ++x)
      for (int y = x + 1; y < start[v + 1]; ++y) {
        const Vec3 u = mesh.vertices[std::size_t(ring[std::size_t(x)])] - p;
        const Vec3 w = mesh.vertices[std::size_t(ring[std::size_t(y)])] - p;
        if (u.dot(w) < 0.0 && u.cross(w).norm() <= tol * (w - u).norm()) return true;
      }
    return false;
  };
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < nv; ++v)
    if (!flat[v] && !between_neighbours(v)) points.push_back(mesh.vertices[v]);
  return points;
}

}  // namespace

CaliperDimensions caliper_dimensions(const Mesh& mesh) {
  if (mesh.vertices.empty()) throw InvalidInput("caliper_dimensions: the mesh has no vertices");
  if (mesh.vertices.size() >= 4) {
    try {
      return caliper_of_points(convex_hull(hull_points(mesh)).vertices);
    } catch (const InvalidInput&) {
      // Flat or collinear vertex set: fall through to all vertices.
    }
  }
  return caliper_of_points(mesh.vertices);
}

double polygon_roundness(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3)
    throw InvalidInput("polygon_roundness: a polygon needs at least 3 vertices, got " +
                       std::to_string(polygon.size()));
  const double area = std::abs(polygon_signed_area(polygon));
  if (!(area > 0.0)) throw InvalidInput("polygon_roundness: the polygon has zero area");
  const double p = polygon_perimeter(polygon);
  return p * p / (4.0 * kPi * area);
}

std::vector<Eigen::Vector2d> silhouette(const Mesh& mesh, const Vec3& direction, bool convex) {
  const double len = direction.norm();
  if (!(len > 0.0) || !std::isfinite(len))
    throw InvalidInput("silhouette: the view direction must be a non-zero finite vector");
  const Vec3 d = direction / len;
  Vec3 u, v;
  plane_basis(d, u, v);
  if (convex) {
    std::vector<Vec2> flat;
    flat.reserve(mesh.vertices.size());
    for (const auto& p : mesh.vertices) flat.emplace_back(p.dot(u), p.dot(v));
    return hull_2d(std::move(flat));
  }
  return arrangement_outline(mesh, d, u, v);
}

Roundness weighted_roundness(const Mesh& mesh, const PrincipalFrame& frame, bool convex) {
  Roundness r;
  double sum_ca = 0.0, sum_a = 0.0;
  for (int i = 0; i < 3; ++i) {
    const std::vector<Vec2> poly = silhouette(mesh, frame.axes.col(i), convex);
    r.view[i] = polygon_roundness(poly);
    r.view_area[i] = std::abs(polygon_signed_area(poly));
    sum_ca += r.view[i] * r.view_area[i];
    sum_a += r.view_area[i];
  }
  r.weighted = sum_ca / sum_a;
  return r;
}

Descriptors describe(const Mesh& mesh) {
  Descriptors d;
  d.volume = signed_volume(mesh);
  if (!(d.volume > 0.0))
    throw InvalidInput(
        "describe: mesh volume must be positive (closed, outward-oriented mesh), got " +
        std::to_string(d.volume));
  d.area = surface_area(mesh);
  d.sphericity = std::cbrt(kPi) * std::pow(6.0 * d.volume, 2.0 / 3.0) / d.area;
  d.equivalent_diameter = std::cbrt(6.0 * d.volume / kPi);

  const Mesh hull = convex_hull(hull_points(mesh));
  const CaliperDimensions cal = caliper_of_points(hull.vertices);
  d.L = cal.L;
  d.W = cal.W;
  d.H = cal.H;

  const PrincipalFrame frame = principal_frame(mesh);
  d.axes = frame.extents;
  d.E = d.axes(1) / d.axes(2);
  d.F = d.axes(0) / d.axes(1);
  d.AR = d.axes(0) / d.axes(2);

  d.convexity = d.volume / signed_volume(hull);
  d.roundness = weighted_roundness(mesh, frame, d.convexity > 1.0 - 1e-9);
  return d;
}

}  // namespace clumpkit
