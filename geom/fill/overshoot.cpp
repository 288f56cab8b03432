#include "geom/fill/overshoot.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace clumpkit {

using Interval = std::pair<double, double>;

struct OvershootLedger::Row {
  std::vector<Interval> inside;   // the mesh's, sorted, disjoint
  std::vector<Interval> outside;  // each recorded sphere's chord parts outside, sorted by start
};

namespace {

// Calls f(lo, hi) for each part of [a, b] that the sorted disjoint intervals `v` leave
// uncovered, in order.
template <class F>
void for_parts_outside(double a, double b, const std::vector<Interval>& v, F&& f) {
  double at = a;
  for (const auto& iv : v) {
    if (iv.second <= at) continue;
    if (iv.first >= b) break;
    if (iv.first > at) f(at, std::min(iv.first, b));
    at = std::max(at, iv.second);
    if (at >= b) return;
  }
  if (at < b) f(at, b);
}

// Length of [a, b] that no interval of `v` (sorted by start, overlapping) covers.
double uncovered_length(double a, double b, const std::vector<Interval>& v) {
  double length = 0.0, at = a;
  for (const auto& iv : v) {
    if (iv.first >= b) break;
    if (iv.second <= at) continue;
    if (iv.first > at) length += iv.first - at;
    at = std::max(at, iv.second);
    if (at >= b) break;
  }
  return at < b ? length + (b - at) : length;
}

}  // namespace

OvershootLedger::OvershootLedger(const MeshIndex& index, const std::array<Vec3, 2>& box,
                                 double spacing)
    : index_(index), spacing_(spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InvalidInput("overshoot ledger: spacing must be positive");
  // Row centres at lo + spacing·(j + ½, k + ½), irrationally offset off mesh edges.
  lo_ = box[0] - spacing * Vec3(0.0, 0.0123456, 0.0234567);
  ny_ = static_cast<int>(std::ceil((box[1].y() - lo_.y()) / spacing)) + 1;
  nz_ = static_cast<int>(std::ceil((box[1].z() - lo_.z()) / spacing)) + 1;
  if (double(ny_) * nz_ > 5e7)
    throw InvalidInput("overshoot ledger: more than 5e7 rows (spacing too small)");
  rows_.resize(std::size_t(ny_) * nz_);
  constexpr double inf = std::numeric_limits<double>::infinity();
  single_inside_.assign(rows_.size(), {inf, -inf});
}

OvershootLedger::~OvershootLedger() = default;

OvershootLedger::Row& OvershootLedger::row(int j, int k) const {
  auto& r = rows_[std::size_t(k) * ny_ + j];
  if (!r) {
    r = std::make_unique<Row>();
    const double y = lo_.y() + (j + 0.5) * spacing_, z = lo_.z() + (k + 0.5) * spacing_;
    const auto xs = index_.even_crossings_x(y, z, 1e-6 * spacing_);
    if (xs.size() % 2 == 0)  // else: no inside known, all outside (over-counts, never under)
      for (std::size_t q = 0; q + 1 < xs.size(); q += 2)
        r->inside.emplace_back(xs[q].x, xs[q + 1].x);
    if (r->inside.size() == 1)
      single_inside_[std::size_t(k) * ny_ + j] = {r->inside[0].first, r->inside[0].second};
  }
  return *r;
}

double OvershootLedger::visit(const Sphere& s, Visit what) const {
  const Vec3& c = s.center;
  const double r = s.radius;
  const int j0 = std::max(0, int(std::ceil((c.y() - r - lo_.y()) / spacing_ - 0.5)));
  const int j1 = std::min(ny_ - 1, int(std::floor((c.y() + r - lo_.y()) / spacing_ - 0.5)));
  const int k0 = std::max(0, int(std::ceil((c.z() - r - lo_.z()) / spacing_ - 0.5)));
  const int k1 = std::min(nz_ - 1, int(std::floor((c.z() + r - lo_.z()) / spacing_ - 0.5)));
  double length = 0.0;
  std::vector<Interval> parts;  // the chord's parts outside the mesh in one row
  for (int k = k0; k <= k1; ++k)
    for (int j = j0; j <= j1; ++j) {
      const double y = lo_.y() + (j + 0.5) * spacing_, z = lo_.z() + (k + 0.5) * spacing_;
      const double w2 = r * r - (y - c.y()) * (y - c.y()) - (z - c.z()) * (z - c.z());
      if (!(w2 > 0.0)) continue;
      const double w = std::sqrt(w2);
      // Inside the row's one inside interval: no part outside (for_parts_outside would find
      // none), so nothing to measure, record or erase.
      const auto& one = single_inside_[std::size_t(k) * ny_ + j];
      if (one[0] <= c.x() - w && c.x() + w <= one[1]) continue;
      Row& row_jk = row(j, k);
      auto& out = row_jk.outside;
      parts.clear();
      for_parts_outside(c.x() - w, c.x() + w, row_jk.inside,
                        [&](double lo, double hi) { parts.emplace_back(lo, hi); });
      if (what == Visit::erase)  // one copy of each part; the rest is what no other covers
        for (const auto& part : parts) {
          const auto at = std::find(out.begin(), out.end(), part);
          if (at == out.end())
            throw std::logic_error("overshoot ledger: removing a sphere that was not recorded");
          out.erase(at);
        }
      for (const auto& part : parts) length += uncovered_length(part.first, part.second, out);
      if (what == Visit::record)
        for (const auto& part : parts)
          out.insert(std::upper_bound(out.begin(), out.end(), part), part);
    }
  return length * spacing_ * spacing_;
}

double OvershootLedger::added(const Sphere& s) const {
  return visit(s, Visit::measure);
}

void OvershootLedger::add(const Sphere& s) {
  volume_ += visit(s, Visit::record);
}

void OvershootLedger::remove(const Sphere& s) {
  volume_ = std::max(0.0, volume_ - visit(s, Visit::erase));
}

}  // namespace clumpkit
