#include "geom/fill/overshoot.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace clumpkit {

using Interval = std::pair<double, double>;

// Rows per side of the ledger's blocks (OvershootLedger::Block).
constexpr int kBlock = 8;

struct OvershootLedger::Row {
  std::vector<Interval> inside;   // the mesh's, sorted, disjoint
  std::vector<Interval> outside;  // each recorded sphere's chord parts outside, sorted by start
};

namespace {

// Calls f(lo, hi) for each part of [a, b] that the sorted disjoint intervals `v` leave
// uncovered, in order.
template <class F>
void for_parts_outside(double a, double b, const Interval* begin, const Interval* end, F&& f) {
  double at = a;
  for (const Interval* p = begin; p != end; ++p) {
    const Interval& iv = *p;
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
  recorded_parts_.assign(rows_.size(), 0);
  nby_ = (ny_ + kBlock - 1) / kBlock;
  blocks_.resize(std::size_t(nby_) * ((nz_ + kBlock - 1) / kBlock));
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
    Block& b = blocks_[std::size_t(k / kBlock) * nby_ + j / kBlock];
    if (r->inside.size() == 1) {
      single_inside_[std::size_t(k) * ny_ + j] = {r->inside[0].first, r->inside[0].second};
      ++b.made;
      b.lo = std::max(b.lo, r->inside[0].first);
      b.hi = std::min(b.hi, r->inside[0].second);
    } else {
      b.broken = true;
    }
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
  auto row_y = [&](int j) { return lo_.y() + (j + 0.5) * spacing_; };
  auto row_z = [&](int k) { return lo_.z() + (k + 0.5) * spacing_; };
  // The row of [a, b] nearest to the centre's coordinate (rows' coordinates rise with the index,
  // so the squared offsets fall then rise, in floating point too).
  auto nearest = [](int a, int b, double centre, double index, auto&& coordinate) {
    const int m = std::clamp(int(std::floor(index)), a, b), n = std::min(m + 1, b);
    return std::abs(coordinate(n) - centre) < std::abs(coordinate(m) - centre) ? n : m;
  };
  for (int kb = k0 / kBlock; kb <= k1 / kBlock; ++kb)
    for (int jb = j0 / kBlock; jb <= j1 / kBlock; ++jb) {
      const int ka = std::max(k0, kBlock * kb), kz = std::min(k1, kBlock * kb + kBlock - 1);
      const int ja = std::max(j0, kBlock * jb), jz = std::min(j1, kBlock * jb + kBlock - 1);
      const Block& b = blocks_[std::size_t(kb) * nby_ + jb];
      const int rows_in = (std::min(ny_, kBlock * jb + kBlock) - kBlock * jb) *
                          (std::min(nz_, kBlock * kb + kBlock) - kBlock * kb);
      // A block is made whole on its first visit (a ray per row it lacks, once), so from then on
      // it can be settled at once.
      if (!b.broken && b.made < rows_in)
        for (int k = kBlock * kb; k < std::min(nz_, kBlock * kb + kBlock) && !b.broken; ++k)
          for (int j = kBlock * jb; j < std::min(ny_, kBlock * jb + kBlock); ++j) row(j, k);
      if (!b.broken && b.made == rows_in) {
        // The widest chord of the block's rows in range is the one of the row nearest the
        // centre: computed as each row's is, it bounds theirs in floating point too.
        const double y = row_y(nearest(ja, jz, c.y(), (c.y() - lo_.y()) / spacing_ - 0.5, row_y));
        const double z = row_z(nearest(ka, kz, c.z(), (c.z() - lo_.z()) / spacing_ - 0.5, row_z));
        const double w2 = r * r - (y - c.y()) * (y - c.y()) - (z - c.z()) * (z - c.z());
        if (!(w2 > 0.0)) continue;
        const double w = std::sqrt(w2);
        if (b.lo <= c.x() - w && c.x() + w <= b.hi) continue;
      }
      for (int k = ka; k <= kz; ++k)
        for (int j = ja; j <= jz; ++j) {
          const double y = row_y(j), z = row_z(k);
          const double w2 = r * r - (y - c.y()) * (y - c.y()) - (z - c.z()) * (z - c.z());
          if (!(w2 > 0.0)) continue;
          const double w = std::sqrt(w2);
          // Inside the row's one inside interval: no part outside (for_parts_outside would find
          // none), so nothing to measure, record or erase.
          const std::size_t q = std::size_t(k) * ny_ + j;
          const auto& one = single_inside_[q];
          if (one[0] <= c.x() - w && c.x() + w <= one[1]) continue;
          // Measured against a row with one inside interval and nothing recorded yet: its parts
          // outside count whole, found without touching the row (most rows of a cap).
          if (what == Visit::measure && one[0] <= one[1] && recorded_parts_[q] == 0) {
            const Interval inside{one[0], one[1]};
            for_parts_outside(c.x() - w, c.x() + w, &inside, &inside + 1,
                              [&](double lo, double hi) { length += hi - lo; });
            continue;
          }
          Row& row_jk = row(j, k);
          auto& out = row_jk.outside;
          parts.clear();
          for_parts_outside(c.x() - w, c.x() + w, row_jk.inside.data(),
                            row_jk.inside.data() + row_jk.inside.size(),
                            [&](double lo, double hi) { parts.emplace_back(lo, hi); });
          if (what == Visit::erase)  // one copy of each part; the rest is what no other covers
            for (const auto& part : parts) {
              const auto at = std::find(out.begin(), out.end(), part);
              if (at == out.end())
                throw std::logic_error("overshoot ledger: removing a sphere that was not recorded");
              out.erase(at);
              --recorded_parts_[q];
            }
          for (const auto& part : parts) length += uncovered_length(part.first, part.second, out);
          if (what == Visit::record)
            for (const auto& part : parts) {
              out.insert(std::upper_bound(out.begin(), out.end(), part), part);
              ++recorded_parts_[q];
            }
        }
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
