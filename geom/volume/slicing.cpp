#include "geom/volume/slicing.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {
namespace {
constexpr double kTwoPi = 2.0 * kPi;

// Antiderivatives P_mn(t) of cos^m(t) sin^n(t), m + n <= 4, in closed form:
//   P10 = s, P01 = −c, P20 = t/2 + sc/2, P02 = t/2 − sc/2, P11 = s²/2,
//   P30 = s − s³/3, P03 = −c + c³/3, P21 = −c³/3, P40 = 3t/8 + sc/2 + sc(c² − s²)/8,
//   P04 = 3t/8 − sc/2 + sc(c² − s²)/8, P31 = −c⁴/4
// (sin 2t = 2sc, sin 4t = 4sc(c² − s²)).
struct TrigAntiderivatives {
  double t, p10, p01, p20, p02, p11, p30, p03, p21, p40, p04, p31;
  explicit TrigAntiderivatives(double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const double sc = s * c, q = sc * (c * c - s * s) / 8.0;
    t = angle;
    p10 = s;
    p01 = -c;
    p20 = 0.5 * angle + 0.5 * sc;
    p02 = 0.5 * angle - 0.5 * sc;
    p11 = 0.5 * s * s;
    p30 = s - s * s * s / 3.0;
    p03 = -c + c * c * c / 3.0;
    p21 = -c * c * c / 3.0;
    p40 = 0.375 * angle + 0.5 * sc + q;
    p04 = 0.375 * angle - 0.5 * sc + q;
    p31 = -0.25 * c * c * c * c;
  }
};

// Adds the Green's-theorem line integrals of the counter-clockwise arc t ∈ [a, b] of the circle
// x = cx + r cos t, y = cy + r sin t (dx = −r sin t dt, dy = r cos t dt):
//   area: ½∮(x dy − y dx) = ½[cx r ΔP10 + cy r ΔP01 + r² Δt]
//   mx:   ½∮x² dy        = ½ r [cx² ΔP10 + 2 cx r ΔP20 + r² ΔP30]
//   my:  −½∮y² dx        = ½ r [cy² ΔP01 + 2 cy r ΔP02 + r² ΔP03]
//   mxx:  ⅓∮x³ dy        = ⅓ r [cx³ ΔP10 + 3 cx² r ΔP20 + 3 cx r² ΔP30 + r³ ΔP40]
//   myy: −⅓∮y³ dx        = ⅓ r [cy³ ΔP01 + 3 cy² r ΔP02 + 3 cy r² ΔP03 + r³ ΔP04]
//   mxy:  ½∮x²y dy       = ½ r [cx² cy ΔP10 + cx² r ΔP11 + 2 cx cy r ΔP20 + 2 cx r² ΔP21
//                               + cy r² ΔP30 + r³ ΔP31]
void add_arc(double cx, double cy, double r, double a, double b, SliceMoments& m) {
  const TrigAntiderivatives A(a), B(b);
  const double dt = B.t - A.t, d10 = B.p10 - A.p10, d01 = B.p01 - A.p01, d20 = B.p20 - A.p20,
               d02 = B.p02 - A.p02, d11 = B.p11 - A.p11, d30 = B.p30 - A.p30, d03 = B.p03 - A.p03,
               d21 = B.p21 - A.p21, d40 = B.p40 - A.p40, d04 = B.p04 - A.p04, d31 = B.p31 - A.p31;
  const double r2 = r * r, r3 = r2 * r;
  m.area += 0.5 * (cx * r * d10 + cy * r * d01 + r2 * dt);
  m.mx += 0.5 * r * (cx * cx * d10 + 2.0 * cx * r * d20 + r2 * d30);
  m.my += 0.5 * r * (cy * cy * d01 + 2.0 * cy * r * d02 + r2 * d03);
  m.mxx +=
      r / 3.0 * (cx * cx * cx * d10 + 3.0 * cx * cx * r * d20 + 3.0 * cx * r2 * d30 + r3 * d40);
  m.myy +=
      r / 3.0 * (cy * cy * cy * d01 + 3.0 * cy * cy * r * d02 + 3.0 * cy * r2 * d03 + r3 * d04);
  m.mxy += 0.5 * r *
           (cx * cx * cy * d10 + cx * cx * r * d11 + 2.0 * cx * cy * r * d20 + 2.0 * cx * r2 * d21 +
            cy * r2 * d30 + r3 * d31);
}

// Moments of the union of disks in the disks' own coordinates (no recentring, no validation).
// Scratch buffers are reused between calls.
struct DiskUnion {
  std::vector<std::pair<double, double>> covered;

  SliceMoments operator()(const std::vector<Disk>& disks) {
    SliceMoments m;
    const std::size_t n = disks.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Disk& di = disks[i];
      if (!(di.r > 0.0)) continue;
      covered.clear();
      bool hidden = false;
      for (std::size_t j = 0; j < n && !hidden; ++j) {
        if (j == i) continue;
        const Disk& dj = disks[j];
        if (!(dj.r > 0.0)) continue;
        const double dx = dj.x - di.x, dy = dj.y - di.y;
        const double d2 = dx * dx + dy * dy, d = std::sqrt(d2);
        if (d >= di.r + dj.r) continue;  // apart or externally tangent: no arc covered
        if (d <= dj.r - di.r) {          // i inside j (internally tangent included)
          // Duplicates (same centre and radius) cover each other: keep the first copy only.
          if (d == 0.0 && di.r == dj.r && j > i) continue;
          hidden = true;
          break;
        }
        if (d <= di.r - dj.r) continue;  // j inside i: i's circle is untouched
        // Proper crossing. Distance from i's centre to the common chord along the centre line,
        // and the half-chord from Heron's product (accurate near tangency).
        const double x = (d2 + (di.r - dj.r) * (di.r + dj.r)) / (2.0 * d);
        const double h2 = (d + di.r + dj.r) * (-d + di.r + dj.r) * (d - di.r + dj.r) *
                          (d + di.r - dj.r) / (4.0 * d2);
        const double alpha = std::atan2(std::sqrt(std::max(h2, 0.0)), x);
        double s = std::atan2(dy, dx) - alpha;
        s = std::fmod(s, kTwoPi);
        if (s < 0.0) s += kTwoPi;
        const double e = s + 2.0 * alpha;
        if (e > kTwoPi) {
          covered.emplace_back(s, kTwoPi);
          covered.emplace_back(0.0, e - kTwoPi);
        } else {
          covered.emplace_back(s, e);
        }
      }
      if (hidden) continue;
      // Uncovered arcs: the complement in [0, 2π] of the union of the covered intervals.
      std::sort(covered.begin(), covered.end());
      double t = 0.0;
      for (const auto& [s, e] : covered) {
        if (s > t) add_arc(di.x, di.y, di.r, t, s, m);
        t = std::max(t, e);
      }
      if (t < kTwoPi) add_arc(di.x, di.y, di.r, t, kTwoPi, m);
    }
    return m;
  }
};

// Gauss–Legendre nodes and weights on [0, 1] for n points: Newton's iteration on P_n with the
// three-term recurrence (n + 1)P_{n+1} = (2n + 1)ξP_n − nP_{n−1}.
struct GaussRule {
  std::vector<double> u, w;
  explicit GaussRule(int n) {
    u.resize(n);
    w.resize(n);
    for (int i = 0; i < n; ++i) {
      double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
      double dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / dp;
        x -= dx;
        if (std::abs(dx) < 1e-16) break;
      }
      u[i] = 0.5 * (1.0 - x);
      w[i] = 1.0 / ((1.0 - x * x) * dp * dp);  // = ½ · 2/((1 − ξ²)P'_n(ξ)²)
    }
  }
};

// Ten z-integrands: A, ∫x, ∫y, zA, ∫x², ∫y², z²A, ∫xy, z∫x, z∫y over the slice.
using Moments10 = std::array<double, 10>;

struct BallSlicer {
  std::vector<Sphere> balls;  // recentred, hidden balls removed
  std::vector<Disk> disks;
  DiskUnion disk_union;

  Moments10 at(double z) {
    disks.clear();
    for (const Sphere& b : balls) {
      const double dz = z - b.center.z();
      if (std::abs(dz) >= b.radius) continue;
      // Slice radius R' = √(R² − (z − z₀)²), Jin et al. 2017 eq. 2 (factored for accuracy).
      disks.push_back({b.center.x(), b.center.y(), std::sqrt((b.radius - dz) * (b.radius + dz))});
    }
    const SliceMoments s = disk_union(disks);
    return {s.area, s.mx,           s.my,  z * s.area, s.mxx,
            s.myy,  z * z * s.area, s.mxy, z * s.mx,   z * s.my};
  }
};

// True when p lies strictly inside some ball other than those listed in `skip`.
bool buried(const Vec3& p, const std::vector<Sphere>& balls, const std::vector<int>& candidates,
            std::initializer_list<int> skip, double margin) {
  for (int k : candidates) {
    if (std::find(skip.begin(), skip.end(), k) != skip.end()) continue;
    const double r = balls[k].radius - margin;
    if (r > 0.0 && (p - balls[k].center).squaredNorm() < r * r) return true;
  }
  return false;
}

}  // namespace

SliceMoments union_of_disks(const std::vector<Disk>& disks) {
  for (std::size_t i = 0; i < disks.size(); ++i)
    if (!std::isfinite(disks[i].x) || !std::isfinite(disks[i].y) || !std::isfinite(disks[i].r))
      throw InvalidInput("union_of_disks: disk " + std::to_string(i) + " is not finite");
  // Work about the mean centre (fewer cancellations), then shift the moments back:
  // ∫x = ∫x' + x₀A, ∫x² = ∫x'² + 2x₀∫x' + x₀²A, ∫xy = ∫x'y' + x₀∫y' + y₀∫x' + x₀y₀A.
  double x0 = 0.0, y0 = 0.0;
  int count = 0;
  for (const Disk& d : disks)
    if (d.r > 0.0) {
      x0 += d.x;
      y0 += d.y;
      ++count;
    }
  if (count == 0) return {};
  x0 /= count;
  y0 /= count;
  std::vector<Disk> local;
  local.reserve(disks.size());
  for (const Disk& d : disks) local.push_back({d.x - x0, d.y - y0, d.r});
  DiskUnion du;
  const SliceMoments l = du(local);
  SliceMoments m;
  m.area = l.area;
  m.mx = l.mx + x0 * l.area;
  m.my = l.my + y0 * l.area;
  m.mxx = l.mxx + 2.0 * x0 * l.mx + x0 * x0 * l.area;
  m.myy = l.myy + 2.0 * y0 * l.my + y0 * y0 * l.area;
  m.mxy = l.mxy + x0 * l.my + y0 * l.mx + x0 * y0 * l.area;
  return m;
}

namespace {

// Event heights where the slice's arc structure changes; an event strictly inside another
// ball leaves the union's boundary alone and is skipped. Returns them sorted, unique, within
// [zlo, zhi], the union's extent in z (set here).
std::vector<double> event_heights(const std::vector<Sphere>& balls,
                                  const std::vector<std::vector<int>>& nbr, double extent,
                                  double& zlo, double& zhi) {
  const double margin = 1e-9 * extent;
  const int n = static_cast<int>(balls.size());
  zlo = balls[0].center.z() - balls[0].radius, zhi = balls[0].center.z() + balls[0].radius;
  std::vector<double> events;
  for (int i = 0; i < n; ++i) {
    const Sphere& b = balls[i];
    zlo = std::min(zlo, b.center.z() - b.radius);
    zhi = std::max(zhi, b.center.z() + b.radius);
    for (double sgn : {-1.0, 1.0}) {
      const Vec3 p = b.center + Vec3(0, 0, sgn * b.radius);
      if (!buried(p, balls, nbr[i], {i}, margin)) events.push_back(p.z());
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j : nbr[i]) {
      if (j < i) continue;
      // Intersection circle: centre cᵢ + t·n̂, radius ρ, in the plane normal to n̂.
      const Vec3 a = balls[j].center - balls[i].center;
      const double d = a.norm(), ri = balls[i].radius, rj = balls[j].radius;
      const Vec3 nh = a / d;
      const double t = (d * d + (ri - rj) * (ri + rj)) / (2.0 * d);
      const double rho = std::sqrt(std::max(0.0, (ri - t) * (ri + t)));
      const Vec3 c = balls[i].center + t * nh;
      const Vec3 w = Vec3::UnitZ() - nh.z() * nh;  // steepest ascent within the circle's plane
      if (w.norm() < 1e-12) {
        events.push_back(c.z());  // horizontal circle: the whole circle is one event
        continue;
      }
      for (double sgn : {-1.0, 1.0}) {
        const Vec3 p = c + sgn * rho * w.normalized();
        if (!buried(p, balls, nbr[i], {i, j}, margin)) events.push_back(p.z());
      }
    }
  for (int i = 0; i < n; ++i)
    for (int j : nbr[i]) {
      if (j < i) continue;
      for (int k : nbr[i]) {
        if (k <= j || std::find(nbr[j].begin(), nbr[j].end(), k) == nbr[j].end()) continue;
        // Triple points p = cᵢ + p₀ ± τ(a × b): 2a·p = rᵢ² − rⱼ² + |a|², 2b·p = rᵢ² − rₖ² + |b|²
        // (relative to cᵢ), p₀ in span{a, b}, |p|² = rᵢ².
        const Vec3 a = balls[j].center - balls[i].center, b = balls[k].center - balls[i].center;
        const double ri2 = balls[i].radius * balls[i].radius;
        const Vec3 nn = a.cross(b);
        const double nn2 = nn.squaredNorm();
        if (nn2 <= 1e-24 * a.squaredNorm() * b.squaredNorm()) continue;  // collinear centres
        const double ra = 0.5 * (ri2 - balls[j].radius * balls[j].radius + a.squaredNorm());
        const double rb = 0.5 * (ri2 - balls[k].radius * balls[k].radius + b.squaredNorm());
        const double aa = a.squaredNorm(), ab = a.dot(b), bb = b.squaredNorm();
        const double det = aa * bb - ab * ab;
        const Vec3 p0 = ((ra * bb - rb * ab) * a + (rb * aa - ra * ab) * b) / det;
        const double tau2 = (ri2 - p0.squaredNorm()) / nn2;
        if (tau2 < 0.0) continue;
        for (double sgn : {-1.0, 1.0}) {
          const Vec3 p = balls[i].center + p0 + sgn * std::sqrt(tau2) * nn;
          if (!buried(p, balls, nbr[i], {i, j, k}, margin)) events.push_back(p.z());
        }
      }
    }
  events.push_back(zlo);
  events.push_back(zhi);
  for (double& e : events) e = std::clamp(e, zlo, zhi);
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  return events;
}

}  // namespace

MassProperties union_properties_by_slicing(const Clump& clump) {
  validate(clump);
  // Copies a few ulps apart count once, as in the other union engines (distinct_balls): their
  // circles in a slice nearly coincide, and the z-integration did not converge around them (an
  // ellipsoid fill's clump ran for an hour).
  std::vector<Sphere> in;
  for (const int k : distinct_balls(clump.spheres)) in.push_back(clump.spheres[k]);
  const int n0 = static_cast<int>(in.size());

  // Reference point: the bounding-box centre; all work is done relative to it.
  Vec3 lo = in[0].center.array() - in[0].radius, hi = in[0].center.array() + in[0].radius;
  for (const Sphere& s : in) {
    lo = lo.cwiseMin(Vec3(s.center.array() - s.radius));
    hi = hi.cwiseMax(Vec3(s.center.array() + s.radius));
  }
  const Vec3 ref = 0.5 * (lo + hi);
  const double extent = (hi - lo).norm();

  // Drop balls inside another ball: they change nothing (distinct_balls left no two alike).
  BallSlicer slicer;
  for (int i = 0; i < n0; ++i) {
    bool hidden = false;
    for (int j = 0; j < n0 && !hidden; ++j)
      hidden = j != i && (in[j].center - in[i].center).norm() + in[i].radius <= in[j].radius;
    if (!hidden) slicer.balls.push_back({in[i].center - ref, in[i].radius});
  }
  const std::vector<Sphere>& balls = slicer.balls;
  const int n = static_cast<int>(balls.size());

  // Neighbours: pairs of balls whose surfaces cross.
  std::vector<std::vector<int>> nbr(n);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double d = (balls[j].center - balls[i].center).norm();
      if (d < balls[i].radius + balls[j].radius &&
          d > std::abs(balls[i].radius - balls[j].radius)) {
        nbr[i].push_back(j);
        nbr[j].push_back(i);
      }
    }

  // Event heights where the slice's arc structure changes.
  double zlo = 0.0, zhi = 0.0;
  const std::vector<double> events = event_heights(balls, nbr, extent, zlo, zhi);

  // Scales for the convergence test of each integrand (absolute floor per unit height).
  double vsum = 0.0;
  for (const Sphere& b : balls) vsum += 4.0 / 3.0 * kPi * b.radius * b.radius * b.radius;
  const double L = zhi - zlo, R = 0.5 * extent;
  const Moments10 floor_per_z = {
      vsum / L,         vsum * R / L,     vsum * R / L,     vsum * R / L,     vsum * R * R / L,
      vsum * R * R / L, vsum * R * R / L, vsum * R * R / L, vsum * R * R / L, vsum * R * R / L};
  static const GaussRule lo_rule(12), hi_rule(24);
  constexpr double tol = 1e-13;
  const double min_width = 1e-12 * L;

  // Gauss–Legendre of the integrand over [a, b] after the smoothstep substitution
  // z = a + (b − a)(3u² − 2u³), dz = 6(b − a)u(1 − u) du, which turns endpoint terms in
  // √(z − a), √(b − z) into polynomials in u.
  auto quad = [&](const GaussRule& rule, double a, double b) {
    Moments10 q{};
    for (std::size_t k = 0; k < rule.u.size(); ++k) {
      const double u = rule.u[k];
      const double z = a + (b - a) * u * u * (3.0 - 2.0 * u);
      const double jac = 6.0 * (b - a) * u * (1.0 - u) * rule.w[k];
      const Moments10 f = slicer.at(z);
      for (int c = 0; c < 10; ++c) q[c] += jac * f[c];
    }
    return q;
  };

  Moments10 total{};
  std::vector<std::pair<double, double>> stack;
  // Work budget: a guard against non-convergence, far above what real clumps need.
  const std::size_t budget = std::max<std::size_t>(1000000, 1000 * events.size());
  std::size_t pieces = 0;
  for (std::size_t e = 0; e + 1 < events.size(); ++e) {
    stack.emplace_back(events[e], events[e + 1]);
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      const Moments10 q1 = quad(lo_rule, a, b), q2 = quad(hi_rule, a, b);
      if (++pieces > budget ||
          !std::all_of(q2.begin(), q2.end(), [](double v) { return std::isfinite(v); }))
        throw NumericError("union_properties_by_slicing: z-integration did not converge");
      bool ok = true;
      for (int c = 0; c < 10 && ok; ++c)
        ok = std::abs(q2[c] - q1[c]) <= tol * (std::abs(q2[c]) + floor_per_z[c] * (b - a));
      if (ok || b - a < min_width) {
        for (int c = 0; c < 10; ++c) total[c] += q2[c];
      } else {
        const double m = 0.5 * (a + b);
        stack.emplace_back(m, b);
        stack.emplace_back(a, m);
      }
    }
  }

  MassProperties mp;
  const double V = total[0];
  if (!(V > 0.0) || !std::isfinite(V))
    throw NumericError("union_properties_by_slicing: volume is not positive and finite");
  const Vec3 c(total[1] / V, total[2] / V, total[3] / V);
  Mat3 J;  // ∫ r rᵀ dV about the reference point
  J << total[4], total[7], total[8], total[7], total[5], total[9], total[8], total[9], total[6];
  const Mat3 C = J - V * c * c.transpose();  // about the centroid
  mp.volume = V;
  mp.centroid = ref + c;
  mp.inertia = C.trace() * Mat3::Identity() - C;
  return mp;
}

}  // namespace clumpkit
