#include "geom/volume/ball_piece.h"

#include "geom/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace clumpkit::detail {
namespace {

using Mat2 = Eigen::Matrix2d;

// A sum of angles arg(x + iy), each in (−π, π], taken as the argument of the product of the
// complex numbers x + iy: one arctangent per sum instead of one per term (the arctangent was a
// sixth of the time on 10⁶ balls). The product's argument is known modulo 2π only; the whole
// turns come from a coarse sum of the angles (each within 0.004 rad), so a sum of up to hundreds
// of terms is placed on the right branch.
class AngleSum {
 public:
  void add(double x, double y) {
    if (x == 0.0 && y == 0.0) return;  // atan2(0, 0) = 0: adds nothing
    const double px = re_ * x - im_ * y, py = re_ * y + im_ * x;
    re_ = px;
    im_ = py;
    // Rescaled by a power of two (exact) before the product leaves the range of doubles.
    const double big = std::max(std::abs(px), std::abs(py));
    if (big > 0x1p+200 || big < 0x1p-200) {
      const double f = std::ldexp(1.0, -std::ilogb(big));
      re_ *= f;
      im_ *= f;
    }
    coarse_ += coarse_atan2(y, x);
  }
  double value() const {
    const double a = std::atan2(im_, re_);
    return a + 2.0 * kPi * std::round((coarse_ - a) / (2.0 * kPi));
  }

 private:
  // atan2 within 0.004 rad: octant reduction and atan t ≈ t (π/4 + 0.273 (1 − |t|)) on |t| ≤ 1.
  static double coarse_atan2(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y);
    const double t = std::min(ax, ay) / std::max(ax, ay);
    double a = t * (0.25 * kPi + 0.273 * (1.0 - t));
    if (ay > ax) a = 0.5 * kPi - a;
    if (x < 0.0) a = kPi - a;
    return y < 0.0 ? -a : a;
  }
  double re_ = 1.0, im_ = 0.0, coarse_ = 0.0;
};

// Orthonormal e1, e2 with e1 × e2 = n.
void plane_basis(const Vec3& n, Vec3& e1, Vec3& e2) {
  const Vec3 a = std::abs(n.x()) < 0.6 ? Vec3::UnitX()
                                       : (std::abs(n.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  e1 = (a - a.dot(n) * n).normalized();
  e2 = n.cross(e1);
}

// Sutherland–Hodgman: clips the convex polygon `poly` to the half-space (orientation is kept).
void clip(std::vector<Vec3>& poly, const HalfSpace& hs, std::vector<Vec3>& out,
          std::vector<double>& f) {
  const std::size_t m = poly.size();
  f.resize(m);
  bool any_out = false;
  for (std::size_t a = 0; a < m; ++a) {
    f[a] = hs.n.dot(poly[a]) - hs.h;
    any_out = any_out || f[a] > 0.0;
  }
  if (!any_out) return;
  out.clear();
  for (std::size_t a = 0; a < m; ++a) {
    const std::size_t b = a + 1 == m ? 0 : a + 1;  // not `% m`: an integer division per edge
    if (f[a] <= 0.0) out.push_back(poly[a]);
    if ((f[a] < 0.0 && f[b] > 0.0) || (f[a] > 0.0 && f[b] < 0.0))
      out.push_back(poly[a] + (f[a] / (f[a] - f[b])) * (poly[b] - poly[a]));
  }
  poly.swap(out);
}

// Accumulates the solid-angle moments ∫ω dω and (the edge part of) ∫ωωᵀ dω of a spherical
// polygon from one of its great-circle edges u → v (unit vectors, not antipodal).
//   ∫_Ω ω dω   = ½ ∮ ω × dω      = ½ Σ θ_e m_e            (Stokes; m_e the unit edge normal)
//   ∫_Ω ωωᵀ dω = (I/3) Ω + (1/6) Σ (m_e g_eᵀ + g_e m_eᵀ),  g_e = ∫_e ω ds
// The second follows from Δ_S(ω_k ω_l − δ_kl/3) = −6 (ω_k ω_l − δ_kl/3) on the unit sphere and
// the divergence theorem on the sphere (the outward conormal of a great-circle edge is −m_e).
// With c = u × v, sinθ = |c|, cosθ = u·v: θ m = (θ/|c|) c and m gᵀ = c (u + (c × u)/(1 + u·v))ᵀ.
// `angle`, when not negative, is the arc's length θ already known to the caller (saves the
// arctangent: a third of the arcs run from the foot point to the circle, at the cap's half-angle).
// `m2_edges` gathers Σ m_e g_eᵀ only; the caller adds its transpose once.
void add_great_arc(const Vec3& u, const Vec3& v, Vec3& m1, Mat3& m2_edges, double angle = -1.0) {
  const Vec3 c = u.cross(v);
  const double sn = c.norm();
  if (sn == 0.0) return;
  const double cs = u.dot(v);
  m1 += (0.5 * (angle < 0.0 ? std::atan2(sn, cs) : angle) / sn) * c;
  m2_edges.noalias() += c * (u + c.cross(u) / (1.0 + cs)).transpose();
}

// A face's plane seen from the ball centre: its direction and in-plane basis, and the circle
// (plane ∩ sphere, radius ρ) where the sphere cuts it.
struct FacePlane {
  double d;  // distance of the plane from the centre
  Vec3 np;   // from the centre towards the plane
  Vec3 e1;   // e1 × e2 = np
  Vec3 e2;
  Vec3 foot;  // the foot point P = d np
  bool cuts;
  double rho2, rho;
  double gamma;  // cosine of the cap half-angle θ
  double sigma;  // sine of θ
  double theta;
  double omg;  // 1 − cos θ without cancellation
};

// The plane n·u = h of `pl` at distance d = |h| > 0 from the centre of a ball of radius r.
FacePlane face_plane(const HalfSpace& pl, const Vec3& e1, const Vec3& n_e2, double r, double d) {
  FacePlane f;
  f.d = d;
  f.np = pl.h > 0.0 ? pl.n : Vec3(-pl.n);  // from the centre towards the plane
  f.e1 = e1;
  f.e2 = pl.h > 0.0 ? n_e2 : Vec3(-n_e2);  // e1 × e2 = np
  f.foot = d * f.np;
  f.cuts = d < r;
  f.rho2 = f.cuts ? (r - d) * (r + d) : 0.0;
  f.rho = std::sqrt(f.rho2);
  f.gamma = f.cuts ? d / r : 1.0;  // cosine of the cap half-angle θ
  f.sigma = f.rho / r;             // sine of θ
  f.theta = std::atan2(f.rho, d);
  f.omg = f.sigma * f.sigma / (1.0 + f.gamma);  // 1 − cos θ without cancellation
  return f;
}

// The sums over a face's signed triangles (P, a, b) that integrate_face turns into the piece's
// integrals.
struct FaceSums {
  const FacePlane& f;
  std::vector<Vec3>& dir;  // unit directions of the polygon vertices
  std::vector<int>& radial;
  // Planar moments about the foot point (2-D, face ∩ disk, signed about np).
  double a0 = 0.0;
  Vec2 a1 = Vec2::Zero();
  Mat2 a2 = Mat2::Zero();
  // Sums over the outside pieces of the sector angle Δ, ∫u dφ and ∫u uᵀ dφ (u = (cos φ, sin φ)):
  // the disk sectors and the cap sectors are linear in them.
  AngleSum delta_sum;  // Δ, the half of ∫u uᵀ dφ's diagonal that is Δ/2 added at the end
  Vec2 s_u1 = Vec2::Zero();
  Mat2 s_u2 = Mat2::Zero();
  // Solid-angle moments of the triangles (P, a, b) seen from the centre.
  AngleSum half_om;  // Ω/2 of each triangle (Van Oosterom–Strackee)
  Vec3 m1 = Vec3::Zero();
  Mat3 m2_edges = Mat3::Zero();  // Σ m_e g_eᵀ over the edges

  // Starts the sums of a face in the plane f, with dir and radial sized to its vertices.
  FaceSums(const FacePlane& f, std::vector<Vec3>& dir, std::vector<int>& radial)
      : f(f), dir(dir), radial(radial) {}

  // Triangle (P, A, B) inside the disk: area α = ½ A×B, first α(A+B)/3,
  // second α/12 (2AAᵀ + 2BBᵀ + ABᵀ + BAᵀ).
  void inside(const Vec2& A, const Vec2& B) {
    const double al = 0.5 * (A.x() * B.y() - A.y() * B.x());
    a0 += al;
    a1 += (al / 3.0) * (A + B);
    a2 += (al / 12.0) * (2.0 * A * A.transpose() + 2.0 * B * B.transpose() + A * B.transpose() +
                         B * A.transpose());
  }

  // Triangle (P, A, B) outside the disk (|y| ≥ ρ along AB). Its radial great-circle edges P → A
  // and B → P mostly cancel between consecutive triangles: at a polygon vertex (index ia, ib ≥ 0)
  // they are only counted in `radial` and added once at the end; at a crossing of the circle
  // (index −1) they are added at once.
  void outside(const Vec2& A, const Vec2& B, int ia, int ib) {
    const Vec3 a = ia >= 0 ? dir[ia] : Vec3((f.foot + A.x() * f.e1 + A.y() * f.e2).normalized());
    const Vec3 b = ib >= 0 ? dir[ib] : Vec3((f.foot + B.x() * f.e1 + B.y() * f.e2).normalized());
    add_great_arc(a, b, m1, m2_edges);
    // A crossing lies on the circle: its arc from the foot point is the cap's half-angle θ.
    if (ia >= 0)
      ++radial[ia];
    else
      add_great_arc(f.np, a, m1, m2_edges, f.theta);
    if (ib >= 0)
      --radial[ib];
    else
      add_great_arc(b, f.np, m1, m2_edges, f.theta);
    const double cr = A.x() * B.y() - A.y() * B.x();
    if (cr == 0.0) return;  // collinear with P: no area, no solid angle
    if (f.cuts) {
      delta_sum.add(A.dot(B), cr);
      const Vec2 u1 = A.normalized(), u2 = B.normalized();
      const double sc = 0.5 * (u2.x() * u2.y() - u1.x() * u1.y());
      s_u1 += Vec2(u2.y() - u1.y(), u1.x() - u2.x());
      s_u2(0, 0) += sc;
      s_u2(1, 1) -= sc;
      const double off = 0.5 * (u2.y() * u2.y() - u1.y() * u1.y());
      s_u2(0, 1) += off;
      s_u2(1, 0) += off;
    }
    // Van Oosterom–Strackee solid angle of the triangle (P, A, B).
    half_om.add(1.0 + f.np.dot(a) + a.dot(b) + b.dot(f.np), f.np.dot(a.cross(b)));
  }
};

// Splits the face `poly` (m vertices, `s.dir` and `s.radial` sized to m) into the triangles
// (P, a, b) over its edges, each edge cut where it crosses the circle, and adds them to `s`.
void sum_face_edges(const std::vector<Vec3>& poly, FaceSums& s, std::vector<Vec2>& q) {
  const FacePlane& f = s.f;
  std::vector<Vec3>& dir = s.dir;
  const std::size_t m = poly.size();
  q.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    q[k] = Vec2(poly[k].dot(f.e1), poly[k].dot(f.e2));
    dir[k] = poly[k].normalized();
  }
  for (std::size_t k = 0; k < m; ++k) {
    const int ka = static_cast<int>(k), kb = static_cast<int>(k + 1 == m ? 0 : k + 1);
    const Vec2& a = q[ka];
    const Vec2& b = q[kb];
    const Vec2 dd = b - a;
    const double l2 = dd.squaredNorm();
    if (l2 == 0.0) continue;
    if (!f.cuts) {
      s.outside(a, b, ka, kb);
      continue;
    }
    // The edge a + t dd is inside the circle for t in [tl, tr].
    const double cr = a.x() * b.y() - a.y() * b.x();
    const double dist2 = cr * cr / l2;  // squared distance of P from the edge's line
    if (dist2 >= f.rho2) {
      s.outside(a, b, ka, kb);
      continue;
    }
    const double t0 = -a.dot(dd) / l2;
    const double w = std::sqrt((f.rho2 - dist2) / l2);
    const double tl = t0 - w, tr = t0 + w;
    if (tl >= 1.0 || tr <= 0.0) {
      s.outside(a, b, ka, kb);
      continue;
    }
    const Vec2 A = tl > 0.0 ? Vec2(a + tl * dd) : a;
    const Vec2 B = tr < 1.0 ? Vec2(a + tr * dd) : b;
    if (tl > 0.0) s.outside(a, A, ka, -1);
    s.inside(A, B);
    if (tr < 1.0) s.outside(B, b, -1, kb);
  }
  for (std::size_t k = 0; k < m; ++k) {
    if (s.radial[k] > 0) add_great_arc(f.np, dir[k], s.m1, s.m2_edges);
    if (s.radial[k] < 0) add_great_arc(dir[k], f.np, s.m1, s.m2_edges);
  }
}

// Turns a face's sums into its integrals (the cone over face ∩ disk plus the ball sector over
// face \ disk) and adds them to the piece of the ball of radius r.
void add_face_sums(FaceSums& s, double r, Piece& piece) {
  const FacePlane& f = s.f;
  const double d = f.d;
  const Vec3& np = f.np;
  const Vec3& e1 = f.e1;
  const Vec3& e2 = f.e2;
  const double om = 2.0 * s.half_om.value();
  const double s_delta = f.cuts ? s.delta_sum.value() : 0.0;
  s.s_u2(0, 0) += 0.5 * s_delta;
  s.s_u2(1, 1) += 0.5 * s_delta;
  // Disk sectors (radius ρ) of the outside pieces: area ρ²Δ/2, first ρ³/3 ∫u, second ρ⁴/4 ∫uuᵀ.
  if (f.cuts) {
    s.a0 += 0.5 * f.rho2 * s_delta;
    s.a1 += (f.rho2 * f.rho / 3.0) * s.s_u1;
    s.a2 += (f.rho2 * f.rho2 / 4.0) * s.s_u2;
  }
  const Vec3 ea1 = s.a1.x() * e1 + s.a1.y() * e2;
  const Mat3 ea2e = s.a2(0, 0) * e1 * e1.transpose() +
                    s.a2(0, 1) * (e1 * e2.transpose() + e2 * e1.transpose()) +
                    s.a2(1, 1) * e2 * e2.transpose();
  const Mat3 npnp = np * np.transpose();
  // Face ∩ disk moments about the centre (y = d np + q).
  const Vec3 A1 = d * s.a0 * np + ea1;
  const Mat3 A2 = d * d * s.a0 * npnp + d * (np * ea1.transpose() + ea1 * np.transpose()) + ea2e;

  // Solid-angle moments of face \ disk = triangles − cap sectors. A cap sector (polar angle ≤ θ
  // about np, azimuth over Δ), with ω = cos α np + sin α u(φ), dω = sin α dα dφ:
  //   Ω = (1 − cos θ) Δ,  ∫ω = np Δ sin²θ/2 + (θ − sin θ cos θ)/2 ∫u,
  //   ∫ωωᵀ = np npᵀ Δ (1 − cos³θ)/3 + sin³θ/3 (np ∫uᵀ + ∫u npᵀ) + (2 − 3cos θ + cos³θ)/3 ∫uuᵀ.
  const double sigma = f.sigma, gamma = f.gamma, omg = f.omg;
  const Vec3 eu1 = s.s_u1.x() * e1 + s.s_u1.y() * e2;
  const Mat3 eu2e = s.s_u2(0, 0) * e1 * e1.transpose() +
                    s.s_u2(0, 1) * (e1 * e2.transpose() + e2 * e1.transpose()) +
                    s.s_u2(1, 1) * e2 * e2.transpose();
  const double omega = om - omg * s_delta;
  const Vec3 M1 =
      s.m1 - (0.5 * s_delta * sigma * sigma * np + 0.5 * (f.theta - sigma * gamma) * eu1);
  const Mat3 M2 = (om / 3.0) * Mat3::Identity() + (s.m2_edges + s.m2_edges.transpose()) / 6.0 -
                  (s_delta * omg * (1.0 + gamma + gamma * gamma) / 3.0 * npnp +
                   (sigma * sigma * sigma / 3.0) * (np * eu1.transpose() + eu1 * np.transpose()) +
                   (omg * omg * (2.0 + gamma) / 3.0) * eu2e);

  const double r2 = r * r, r3 = r2 * r;
  piece.volume += d / 3.0 * s.a0 + r3 / 3.0 * omega;
  piece.first += d / 4.0 * A1 + (r3 * r / 4.0) * M1;
  piece.second += d / 5.0 * A2 + (r3 * r2 / 5.0) * M2;
  piece.area += r2 * omega;
}

// Adds the contribution of one planar face of the polytope C (∩ of half-spaces), a convex polygon
// counter-clockwise about the outward normal pl.n in the plane n·u = h, to the integrals of the
// piece B(0, r) ∩ C. The face is split, from the foot point P = h n of the ball centre, into
// signed triangles (P, a, b) over its edges; each edge is cut where it crosses the circle
// (plane ∩ sphere, radius ρ). Inside the disk the piece is the cone over the face (volume h/3
// times the face area, and h/4, h/5 times its first and second area moments); outside it is the
// ball sector over the face's solid angle (r³/3, r⁴/4, r⁵/5 times the solid-angle moments), i.e.
// the cone over the triangle (P, a, b) minus the cone over the cap sector of the disk.
// Faces with h < 0 (centre outside the cell) come out with the right sign automatically.
// (e1, n_e2) is an orthonormal basis of the plane with e1 × n_e2 = pl.n.
void integrate_face(const HalfSpace& pl, const Vec3& e1, const Vec3& n_e2,
                    const std::vector<Vec3>& poly, double r, Piece& piece, Scratch& w) {
  const double d = std::abs(pl.h);
  if (d == 0.0) return;  // plane through the centre: cones of zero height and zero solid angle
  const FacePlane f = face_plane(pl, e1, n_e2, r, d);
  const std::size_t m = poly.size();
  std::vector<Vec3>& dir = w.dir;
  dir.resize(m);
  std::vector<int>& radial = w.radial;
  radial.assign(m, 0);
  FaceSums s(f, dir, radial);
  sum_face_edges(poly, s, w.q);
  add_face_sums(s, r, piece);
}

}  // namespace

// Integrals over B(0, r) ∩ ⋂ planes. Half-spaces that contain the ball are dropped, a half-space
// that excludes it (h ≤ −r) empties the piece; the rest are bounded by the cube |u|∞ ≤ 2r (which
// leaves the ball untouched) so that every face is a bounded polygon, built by clipping a large
// square in its plane by all other half-spaces.
Piece ball_piece(double r, const std::vector<HalfSpace>& planes, Scratch& w) {
  Piece piece;
  std::vector<HalfSpace>& kept = w.kept;
  kept.clear();
  for (const HalfSpace& p : planes) {
    if (p.h <= -r) {
      piece.empty = true;
      return piece;
    }
    if (p.h >= r) continue;
    // Coincident planes (to rounding) would be double counted: keep one. Opposite coincident
    // planes make the cell flat: nothing of the ball is left.
    bool duplicate = false;
    for (const HalfSpace& k : kept) {
      if ((p.n - k.n).squaredNorm() < 1e-26 && std::abs(p.h - k.h) <= 1e-13 * r) duplicate = true;
      if ((p.n + k.n).squaredNorm() < 1e-26 && std::abs(p.h + k.h) <= 1e-13 * r) {
        piece.empty = true;
        return piece;
      }
    }
    if (!duplicate) kept.push_back(p);
  }
  // Most restrictive planes first: faces of redundant planes are clipped away sooner.
  std::sort(kept.begin(), kept.end(),
            [](const HalfSpace& a, const HalfSpace& b) { return a.h < b.h; });
  const double box = 2.0 * r;
  for (int axis = 0; axis < 3; ++axis) {
    kept.push_back({Vec3::Unit(axis), box});
    kept.push_back({-Vec3::Unit(axis), box});
  }
  const double half = 2.0 * box;  // the square covers the cube's section (radius √3·box)
  // When the polytope holds the centre (every h > 0; the usual case), a plane whose face comes
  // out empty bounds nothing (the polytope is the same without it), so it clips no later face.
  // (Had the polytope been empty, every face would be empty and dropping planes would open it.)
  // The cube's faces go first: inside its neighbours' cage a ball's cube faces are all empty, and
  // the other faces are then clipped by the neighbours' planes alone.
  std::vector<char>& gone = w.gone;
  gone.assign(kept.size(), 0);
  const std::size_t cube = kept.size() - 6;
  const bool holds_centre = kept.front().h > 0.0;  // sorted: the smallest h first
  // Face k: a square in its plane clipped by every other plane still bounding the polytope.
  auto face = [&](std::size_t k, std::vector<Vec3>& poly, Vec3& e1, Vec3& e2) {
    const HalfSpace& pk = kept[k];
    plane_basis(pk.n, e1, e2);  // e1 × e2 = n: the square is counter-clockwise about n
    const Vec3 foot = pk.h * pk.n;
    poly = {foot - half * e1 - half * e2, foot + half * e1 - half * e2,
            foot + half * e1 + half * e2, foot - half * e1 + half * e2};
    for (std::size_t j = 0; j < kept.size() && poly.size() >= 3; ++j)
      if (j != k && !gone[j]) clip(poly, kept[j], w.clipped, w.f);
  };

  std::vector<Vec3>& poly = w.poly;
  for (std::size_t pass = 0; pass < kept.size(); ++pass) {
    const std::size_t k = (cube + pass) % kept.size();  // the cube's six, then the neighbours'
    Vec3 e1, e2;
    face(k, poly, e1, e2);
    if (poly.size() >= 3)
      integrate_face(kept[k], e1, e2, poly, r, piece, w);
    else
      gone[k] = holds_centre;
  }
  return piece;
}

}  // namespace clumpkit::detail
