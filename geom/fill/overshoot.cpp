#include "geom/fill/overshoot.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>

namespace clumpkit {

using Interval = std::pair<double, double>;

struct OvershootLedger::Row {
  std::vector<Interval> inside;   // the mesh's, sorted, disjoint
  std::vector<Interval> outside;  // recorded spheres' chords minus `inside`, sorted, disjoint
};

namespace {

// Parts of [a, b] not covered by the sorted disjoint intervals `v`.
std::vector<Interval> minus(double a, double b, const std::vector<Interval>& v) {
  std::vector<Interval> out;
  double at = a;
  for (const auto& iv : v) {
    if (iv.second <= at) continue;
    if (iv.first >= b) break;
    if (iv.first > at) out.emplace_back(at, std::min(iv.first, b));
    at = std::max(at, iv.second);
    if (at >= b) break;
  }
  if (at < b) out.emplace_back(at, b);
  return out;
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
  }
  return *r;
}

double OvershootLedger::visit(const Sphere& s, bool record) const {
  const Vec3& c = s.center;
  const double r = s.radius;
  const int j0 = std::max(0, int(std::ceil((c.y() - r - lo_.y()) / spacing_ - 0.5)));
  const int j1 = std::min(ny_ - 1, int(std::floor((c.y() + r - lo_.y()) / spacing_ - 0.5)));
  const int k0 = std::max(0, int(std::ceil((c.z() - r - lo_.z()) / spacing_ - 0.5)));
  const int k1 = std::min(nz_ - 1, int(std::floor((c.z() + r - lo_.z()) / spacing_ - 0.5)));
  double length = 0.0;
  for (int k = k0; k <= k1; ++k)
    for (int j = j0; j <= j1; ++j) {
      const double y = lo_.y() + (j + 0.5) * spacing_, z = lo_.z() + (k + 0.5) * spacing_;
      const double w2 = r * r - (y - c.y()) * (y - c.y()) - (z - c.z()) * (z - c.z());
      if (!(w2 > 0.0)) continue;
      const double w = std::sqrt(w2);
      Row& row_jk = row(j, k);
      for (const auto& part : minus(c.x() - w, c.x() + w, row_jk.inside)) {
        const auto fresh = minus(part.first, part.second, row_jk.outside);
        for (const auto& f : fresh) length += f.second - f.first;
        if (record && !fresh.empty()) {
          row_jk.outside.insert(row_jk.outside.end(), fresh.begin(), fresh.end());
          std::sort(row_jk.outside.begin(), row_jk.outside.end());
        }
      }
    }
  return length * spacing_ * spacing_;
}

double OvershootLedger::added(const Sphere& s) const {
  return visit(s, false);
}

void OvershootLedger::add(const Sphere& s) {
  volume_ += visit(s, true);
}

}  // namespace clumpkit
