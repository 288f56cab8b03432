#include "geom/volume/inclusion_exclusion.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fixed_alpha_shape_3.h>
#include <CGAL/Fixed_alpha_shape_cell_base_3.h>
#include <CGAL/Fixed_alpha_shape_vertex_base_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace clumpkit {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<
    int, K, CGAL::Fixed_alpha_shape_vertex_base_3<K, CGAL::Regular_triangulation_vertex_base_3<K>>>;
using Cb = CGAL::Fixed_alpha_shape_cell_base_3<
    K, CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>,
                                               CGAL::Discard_hidden_points>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using RegularTriangulation = CGAL::Regular_triangulation_3<K, Tds>;
using AlphaComplex = CGAL::Fixed_alpha_shape_3<RegularTriangulation>;
using VertexHandle = RegularTriangulation::Vertex_handle;

// Volume and boundary area of a region.
struct Measure {
  double volume = 0.0, area = 0.0;
};

// Angle between two vectors, in [0, π].
double angle(const Vec3& u, const Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// The far side of the power plane of ball m with ball a, seen from c_m: {u : n·u ≥ h} with
// n = (c_a − c_m)/D and h = (D² + r_m² − r_a²)/(2D): the points where pow_m ≥ pow_a.
struct FarSide {
  Vec3 n;
  double h;
};
FarSide far_side(const Sphere& m, const Sphere& a) {
  const Vec3 d = a.center - m.center;
  const double d2 = d.squaredNorm(), dist = std::sqrt(d2);
  return {d / dist, (d2 + (m.radius - a.radius) * (m.radius + a.radius)) / (2.0 * dist)};
}

// Cap of a ball beyond a plane at signed distance h from its centre: height t = r − h,
// volume π t² (3r − t)/3, spherical area 2π r t.
Measure cap(double r, double h) {
  const double t = r - std::clamp(h, -r, r);
  return {kPi * t * t * (3.0 * r - t) / 3.0, 2.0 * kPi * r * t};
}

// B_i ∩ B_j: the two caps beyond the power plane (a lens; the smaller ball if nested).
Measure two_balls(const Sphere& a, const Sphere& b) {
  const FarSide p = far_side(a, b);
  const double dist = (b.center - a.center).norm();
  const Measure ca = cap(a.radius, p.h), cb = cap(b.radius, dist - p.h);
  return {ca.volume + cb.volume, ca.area + cb.area};
}

// Ball B(0, r) ∩ {n_a·u ≥ h_a} ∩ {n_b·u ≥ h_b} whose edge line L (through zl, direction e)
// pierces the sphere at zl ± s e, s > 0: see three_balls() for the formulas.
Measure double_cap(double r, const Vec3& zl, const Vec3& e, double s, const FarSide& pa,
                   const FarSide& pb) {
  // Arc angle and segment area on the disk of plane p, cut by the other plane o.
  auto arc = [&](const FarSide& p, const FarSide& o, double& phi, double& area) {
    const double dist = (p.h * p.n - zl).norm();
    const double delta = p.h * p.n.dot(o.n) < o.h ? dist : -dist;  // + if disk centre outside o
    phi = 2.0 * std::atan2(s, delta);
    area = 0.5 * (s * s + delta * delta) * (phi - std::sin(phi));
  };
  double phi_a, phi_b, fa, fb;
  arc(pa, pb, phi_a, fa);
  arc(pb, pa, phi_b, fb);
  const Vec3 q = (zl + s * e).normalized();
  const Vec3 ma = pa.n - pa.n.dot(q) * q, mb = pb.n - pb.n.dot(q) * q;
  const double alpha = kPi - angle(ma, mb);
  const double omega = 2.0 * alpha - (pa.h * phi_a + pb.h * phi_b) / r;
  return {(r * r * r * omega - pa.h * fa - pb.h * fb) / 3.0, r * r * omega};
}

// The same region when the two planes do not cross inside the ball (L misses or touches the
// sphere, s = 0 to rounding): each disk lies wholly on one side of the other plane, so the region
// is empty, one cap, or the ball minus both (disjoint) complementary caps.
Measure separated_double_cap(double r, const FarSide& pa, const FarSide& pb) {
  if (pa.h >= r || pb.h >= r) return {};
  const Measure ca = cap(r, pa.h), cb = cap(r, pb.h);
  if (pa.h <= -r) return cb;
  if (pb.h <= -r) return ca;
  const bool a_in_b = pa.h * pa.n.dot(pb.n) >= pb.h;  // disk a on the far side of plane b
  const bool b_in_a = pb.h * pb.n.dot(pa.n) >= pa.h;
  if (a_in_b && b_in_a) {
    const double v = 4.0 / 3.0 * kPi * r * r * r, area = 4.0 * kPi * r * r;
    return {ca.volume + cb.volume - v, ca.area + cb.area - area};
  }
  if (a_in_b) return ca;
  if (b_in_a) return cb;
  return {};
}

// B_1 ∩ B_2 ∩ B_3 for three spheres that share a point (orthogonal-sphere radius² π ≤ 0; true
// for every triangle of the dual complex). The farthest-point power diagram splits it into the
// pieces B_m ∩ {pow_m ≥ pow_a} ∩ {pow_m ≥ pow_b}: "double caps", ball ∩ wedge whose edge is the
// radical line L (through the orthocentre z, normal to the centres' plane), which pierces the
// sphere at q± = z ± s e, s = √(−π). For each double cap (Edelsbrunner & Fu 1994):
//   spherical digon, Gauss–Bonnet: Ω = 2α − Σ_k (h_k / r) φ_k, α the corner angle at q±, φ_k the
//   central angle of the boundary arc on circle k (geodesic curvature cot θ_k, cos θ_k = h_k / r);
//   flat faces: circular segments of the disks, F_k = ½ ρ_k² (φ_k − sin φ_k), φ_k = 2 atan2(s, δ_k)
//   with δ_k the signed distance of the disk centre from L;
//   volume by the divergence theorem from c_m: V = (r³ Ω − Σ h_k F_k)/3, area r² Ω.
Measure three_balls(const std::array<Sphere, 3>& b) {
  const Vec3 d1 = b[1].center - b[0].center, d2 = b[2].center - b[0].center;
  const double r0 = b[0].radius;
  const double b1 = 0.5 * (d1.squaredNorm() + (r0 - b[1].radius) * (r0 + b[1].radius));
  const double b2 = 0.5 * (d2.squaredNorm() + (r0 - b[2].radius) * (r0 + b[2].radius));
  const double g11 = d1.squaredNorm(), g12 = d1.dot(d2), g22 = d2.squaredNorm();
  const double det = g11 * g22 - g12 * g12;
  // Orthocentre relative to c_0 (kept local: adding back large coordinates would round it).
  const Vec3 z0 = ((b1 * g22 - b2 * g12) / det) * d1 + ((b2 * g11 - b1 * g12) / det) * d2;
  const Vec3 e = d1.cross(d2).normalized();
  Measure total;
  for (int m = 0; m < 3; ++m) {
    const Sphere& bm = b[m];
    const double r = bm.radius;
    const Vec3 zl = z0 - (bm.center - b[0].center);
    const double s2 = r * r - zl.squaredNorm();  // −π seen from ball m
    const FarSide pa = far_side(bm, b[(m + 1) % 3]), pb = far_side(bm, b[(m + 2) % 3]);
    const Measure piece = s2 > 1e-12 * r * r ? double_cap(r, zl, e, std::sqrt(s2), pa, pb)
                                             : separated_double_cap(r, pa, pb);
    total.volume += piece.volume;
    total.area += piece.area;
  }
  return total;
}

// B_1 ∩ … ∩ B_4 for four balls whose orthocentre w has power π ≤ 0 (every tetrahedron of the
// dual complex). The farthest-point power diagram splits it into "triple caps" B_m ∩ F_m, F_m a
// trihedral cone with apex w inside B_m. Each triple cap: a spherical triangle with corners where
// the cone's edges leave the sphere, Ω = 2π − Σ (π − α_corner) − Σ_k (h_k / r) φ_k
// (Gauss–Bonnet); flat faces = disk ∩ wedge (apex w) = triangle (w, q1, q2) + circular segment
// ½ ρ² (φ − sin φ); V = (r³ Ω − Σ h_k F_k)/3, area r² Ω. The arc angle φ is summed over the two
// halves of the arc split by the wedge's bisector ray (each below π), which avoids any wrap-around.
Measure four_balls(const std::array<Sphere, 4>& b) {
  const Vec3 d1 = b[1].center - b[0].center, d2 = b[2].center - b[0].center,
             d3 = b[3].center - b[0].center;
  const double r0 = b[0].radius;
  auto rhs = [&](const Vec3& d, double r) { return 0.5 * (d.squaredNorm() + (r0 - r) * (r0 + r)); };
  const double k1 = rhs(d1, b[1].radius), k2 = rhs(d2, b[2].radius), k3 = rhs(d3, b[3].radius);
  const Vec3 w0 = (k1 * d2.cross(d3) + k2 * d3.cross(d1) + k3 * d1.cross(d2)) /
                  d1.dot(d2.cross(d3));  // orthocentre relative to c_0
  Measure total;
  for (int m = 0; m < 4; ++m) {
    const Sphere& bm = b[m];
    const Vec3 wl = w0 - (bm.center - b[0].center);
    // −π = r² − |w − c_m|². If the apex w lies on the sphere (four spheres through one point, to
    // rounding) corners and arcs degenerate; the piece is then evaluated for the concentric ball
    // with −π = 1e-12 r² (corners 1e-6 r from w), whose volume and area differ by about 1e-12
    // relative; rounding in the resulting short corner arcs costs at most about 1e-10.
    double r = bm.radius, r2w = r * r - wl.squaredNorm();
    if (r2w < 1e-12 * r * r) {
      r2w = 1e-12 * r * r;
      r = std::sqrt(wl.squaredNorm() + r2w);
    }
    std::array<FarSide, 3> p;
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != m) p[j++] = far_side(bm, b[k]);
    // Exit point of the ray wl + t v (v unit) from the ball.
    auto exit_point = [&](const Vec3& v) {
      const double wv = wl.dot(v);
      return Vec3(wl + (-wv + std::sqrt(wv * wv + r2w)) * v);
    };
    Vec3 dir[3][3], corner[3][3];
    double omega = 2.0 * kPi;
    for (int k = 0; k < 3; ++k)
      for (int l = k + 1; l < 3; ++l) {
        const int t = 3 - k - l;
        Vec3 v = p[k].n.cross(p[l].n).normalized();
        if (v.dot(p[t].n) < 0.0) v = -v;
        const Vec3 q = exit_point(v);
        dir[k][l] = dir[l][k] = v;
        corner[k][l] = corner[l][k] = q;
        const Vec3 qh = q.normalized();
        const Vec3 mk = p[k].n - p[k].n.dot(qh) * qh, ml = p[l].n - p[l].n.dot(qh) * qh;
        omega -= angle(mk, ml);  // −(π − α), α = π − angle(mk, ml)
      }
    double flat = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3, t = (k + 2) % 3;
      const Vec3 pk = p[k].h * p[k].n;
      Vec3 bis;
      if (dir[k][l].dot(dir[k][t]) >= 0.0) {
        bis = (dir[k][l] + dir[k][t]).normalized();
      } else {  // wide wedge: bisect the in-plane inward normals instead
        const Vec3 ml = (p[l].n - p[l].n.dot(p[k].n) * p[k].n).normalized();
        const Vec3 mt = (p[t].n - p[t].n.dot(p[k].n) * p[k].n).normalized();
        bis = (ml + mt).normalized();
      }
      const Vec3 v1 = corner[k][l] - pk, v2 = corner[k][t] - pk, vm = exit_point(bis) - pk;
      const double phi = angle(v1, vm) + angle(vm, v2);
      const double rho2 = (r - p[k].h) * (r + p[k].h);
      const double face = 0.5 * (corner[k][l] - wl).cross(corner[k][t] - wl).norm() +
                          0.5 * rho2 * (phi - std::sin(phi));
      omega -= p[k].h * phi / r;
      flat += p[k].h * face;
    }
    total.volume += (r * r * r * omega - flat) / 3.0;
    total.area += r * r * omega;
  }
  return total;
}

// Running signed sums of the inclusion–exclusion terms.
// The inclusion–exclusion sum over the simplices of the dual complex, added up in the order of
// their sorted vertex indices, each simplex's measure computed with its balls in that order. CGAL
// inserts points in a spatial order shuffled by its process-wide random generator, so the complex
// is enumerated in an order that depends on the triangulations made before in the process: summed
// as enumerated, the same balls gave areas differing in the last bits from one call to the next.
class Sum {
 public:
  explicit Sum(const std::vector<Sphere>& ball) : ball_(ball) {}
  // A simplex of `count` (1–4) balls, indices into `ball`.
  void add(std::array<int, 4> ids, int count) {
    std::sort(ids.begin(), ids.begin() + count);
    for (int k = count; k < 4; ++k) ids[k] = -1;
    simplices_.push_back(ids);
  }
  Measure total() {
    std::sort(simplices_.begin(), simplices_.end());
    Measure sum;
    for (const auto& ids : simplices_) {
      const auto& b = ball_;
      Measure m;
      int sign = 1;
      if (ids[1] < 0) {
        const double r = b[ids[0]].radius;
        m = {4.0 / 3.0 * kPi * r * r * r, 4.0 * kPi * r * r};
      } else if (ids[2] < 0) {
        m = two_balls(b[ids[0]], b[ids[1]]);
        sign = -1;
      } else if (ids[3] < 0) {
        m = three_balls({b[ids[0]], b[ids[1]], b[ids[2]]});
      } else {
        m = four_balls({b[ids[0]], b[ids[1]], b[ids[2]], b[ids[3]]});
        sign = -1;
      }
      sum.volume += sign * m.volume;
      sum.area += sign * m.area;
    }
    return sum;
  }

 private:
  const std::vector<Sphere>& ball_;
  std::vector<std::array<int, 4>> simplices_;
};

// Dual complex of a triangulation of dimension 0, 1 or 2 (Fixed_alpha_shape_3 needs dimension
// 3), classified with CGAL's exact predicates exactly as the alpha shape does: a simplex is in
// the complex at alpha 0 if it is Gabriel (its orthocentre lies in its dual power face) and its
// smallest orthogonal sphere has squared radius ≤ 0, or if one of its cofaces is in the complex.
void lower_dimensional(const RegularTriangulation& rt, const std::vector<Sphere>& ball, Sum& sum) {
  const int dim = rt.dimension();
  const K::FT zero(0);
  const auto radius_cmp = rt.geom_traits().compare_weighted_squared_radius_3_object();
  const auto side = rt.geom_traits().power_side_of_bounded_power_sphere_3_object();
  if (dim == 0) {
    sum.add({rt.finite_vertices_begin()->info(), 0, 0, 0}, 1);
    return;
  }
  struct EdgeState {
    VertexHandle a, b;
    std::vector<VertexHandle> opposite;  // third vertices of the finite triangles on the edge
    bool coface_in = false;
  };
  const std::int64_t n = static_cast<std::int64_t>(ball.size());
  auto key = [n](int a, int b) {
    return static_cast<std::int64_t>(std::min(a, b)) * n + std::max(a, b);
  };
  std::unordered_map<std::int64_t, EdgeState> edges;
  std::vector<std::int64_t> edge_order;  // deterministic iteration order
  for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e) {
    const VertexHandle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
    const std::int64_t k = key(a->info(), b->info());
    edges[k] = EdgeState{a, b, {}, false};
    edge_order.push_back(k);
  }
  if (dim == 2) {
    for (auto f = rt.finite_facets_begin(); f != rt.finite_facets_end(); ++f) {
      VertexHandle v[3];
      for (int j = 0; j < 3; ++j) v[j] = f->first->vertex((f->second + j + 1) & 3);
      const bool in = radius_cmp(v[0]->point(), v[1]->point(), v[2]->point(), zero) != CGAL::LARGER;
      if (in) sum.add({v[0]->info(), v[1]->info(), v[2]->info(), 0}, 3);
      for (int j = 0; j < 3; ++j) {
        EdgeState& es = edges[key(v[(j + 1) % 3]->info(), v[(j + 2) % 3]->info())];
        es.opposite.push_back(v[j]);
        es.coface_in = es.coface_in || in;
      }
    }
  }
  std::vector<char> vertex_in(ball.size(), 0);
  std::vector<std::vector<VertexHandle>> neighbours(ball.size());
  for (std::int64_t k : edge_order) {
    const EdgeState& es = edges[k];
    neighbours[es.a->info()].push_back(es.b);
    neighbours[es.b->info()].push_back(es.a);
    bool in = es.coface_in;
    if (!in && radius_cmp(es.a->point(), es.b->point(), zero) != CGAL::LARGER) {
      in = std::none_of(es.opposite.begin(), es.opposite.end(), [&](const VertexHandle& t) {
        return side(es.a->point(), es.b->point(), t->point()) == CGAL::ON_BOUNDED_SIDE;
      });
    }
    if (!in) continue;
    sum.add({es.a->info(), es.b->info(), 0, 0}, 2);
    vertex_in[es.a->info()] = vertex_in[es.b->info()] = 1;
  }
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) {
    const int i = v->info();
    bool in = vertex_in[i];
    if (!in) {  // a vertex's orthogonal sphere has radius² −r² < 0: in iff Gabriel
      in = std::none_of(neighbours[i].begin(), neighbours[i].end(), [&](const VertexHandle& u) {
        return side(v->point(), u->point()) == CGAL::ON_BOUNDED_SIDE;
      });
    }
    if (in) sum.add({i, 0, 0, 0}, 1);
  }
}

}  // namespace

UnionMeasure union_measure_inclusion_exclusion(const Clump& clump) {
  validate(clump);
  const std::vector<int> keep = distinct_balls(clump.spheres);
  std::vector<Sphere> ball;
  ball.reserve(keep.size());
  for (int i : keep) ball.push_back(clump.spheres[i]);

  std::vector<std::pair<K::Weighted_point_3, int>> points;
  points.reserve(ball.size());
  for (std::size_t k = 0; k < ball.size(); ++k) {
    const Vec3& c = ball[k].center;
    points.emplace_back(
        K::Weighted_point_3(K::Point_3(c.x(), c.y(), c.z()), ball[k].radius * ball[k].radius),
        static_cast<int>(k));
  }
  RegularTriangulation rt;
  rt.insert(points.begin(), points.end());

  Sum sum(ball);
  if (rt.dimension() < 3) {
    lower_dimensional(rt, ball, sum);
  } else {
    // Alpha complex at alpha 0 = the dual complex (Fixed_alpha_shape_3, not the REGULARIZED
    // Alpha_shape_3 default). A simplex is in it unless classified EXTERIOR.
    AlphaComplex complex(rt, 0);
    const auto out = AlphaComplex::EXTERIOR;
    for (auto v = complex.finite_vertices_begin(); v != complex.finite_vertices_end(); ++v) {
      if (complex.classify(VertexHandle(v)) == out) continue;
      sum.add({v->info(), 0, 0, 0}, 1);
    }
    for (auto e = complex.finite_edges_begin(); e != complex.finite_edges_end(); ++e) {
      if (complex.classify(*e) == out) continue;
      sum.add({e->first->vertex(e->second)->info(), e->first->vertex(e->third)->info(), 0, 0}, 2);
    }
    for (auto f = complex.finite_facets_begin(); f != complex.finite_facets_end(); ++f) {
      if (complex.classify(*f) == out) continue;
      std::array<int, 4> tri{};
      for (int j = 0; j < 3; ++j) tri[j] = f->first->vertex((f->second + j + 1) & 3)->info();
      sum.add(tri, 3);
    }
    for (auto c = complex.finite_cells_begin(); c != complex.finite_cells_end(); ++c) {
      if (complex.classify(AlphaComplex::Cell_handle(c)) == out) continue;
      std::array<int, 4> tet{};
      for (int j = 0; j < 4; ++j) tet[j] = c->vertex(j)->info();
      sum.add(tet, 4);
    }
  }
  const Measure total = sum.total();
  if (!(total.volume > 0.0) || !std::isfinite(total.volume) || !std::isfinite(total.area))
    throw NumericError("union_measure_inclusion_exclusion: volume is not positive and finite");
  return {total.volume, total.area};
}

}  // namespace clumpkit
