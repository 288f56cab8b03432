#include "geom/fill/coverage_grid.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace clumpkit {

namespace {

// Bits i0..i1 of a row as word masks: f(word, mask).
template <class F>
void for_words(int i0, int i1, F&& f) {
  const int w0 = i0 >> 6, w1 = i1 >> 6;
  for (int q = w0; q <= w1; ++q) {
    std::uint64_t mask = ~std::uint64_t(0);
    if (q == w0) mask &= ~std::uint64_t(0) << (i0 & 63);
    if (q == w1 && (i1 & 63) != 63) mask &= (std::uint64_t(1) << ((i1 & 63) + 1)) - 1;
    f(q, mask);
  }
}

}  // namespace

CoverageGrid::CoverageGrid(const DistanceField& f)
    : origin_(f.origin), h_(f.h), dims_(f.dims), words_((f.dims[0] + 63) / 64) {
  inside_.resize(f.d.size());
  for (std::size_t q = 0; q < f.d.size(); ++q) inside_[q] = f.d[q] > 0.0f;
  init();
}

void CoverageGrid::init() {
  const std::size_t rows = std::size_t(dims_[1]) * dims_[2];
  bits_.assign(rows * words_, 0);
  count_.assign(inside_.size(), 0);
  for (int k = 0; k < dims_[2]; ++k)
    for (int j = 0; j < dims_[1]; ++j) {
      const std::uint8_t* in = &inside_[(std::size_t(k) * dims_[1] + j) * std::size_t(dims_[0])];
      for (int i = 0; i < dims_[0]; ++i)
        if (in[i]) {
          row(j, k)[i >> 6] |= std::uint64_t(1) << (i & 63);
          ++interior_;
        }
    }
  uncovered_ = interior_;
  block_dims_ = {words_ * 8, (dims_[1] + 7) / 8, (dims_[2] + 7) / 8};
  blocks_.assign(std::size_t(block_dims_[0]) * block_dims_[1] * block_dims_[2], 0);
  pieces_.assign(blocks_.size(), 0);
  for (int k = 0; k < dims_[2]; ++k)
    for (int j = 0; j < dims_[1]; ++j)
      for (int i = 0; i < dims_[0]; ++i)
        if (row(j, k)[i >> 6] >> (i & 63) & 1) ++block(i, j, k);
  for (int k = 0; k < dims_[2]; ++k)
    for (int j = 0; j < dims_[1]; ++j)
      for (int i = 0; i < dims_[0]; i += 8) update_pieces(i, j, k);
}

template <class F>
void CoverageGrid::for_spans(const Sphere& s, F&& f) const {
  const Vec3 g = (s.center - origin_) / h_;
  const double rv = s.radius / h_;
  const int k0 = std::max(0, int(std::ceil(g.z() - rv))),
            k1 = std::min(dims_[2] - 1, int(std::floor(g.z() + rv)));
  const int j0 = std::max(0, int(std::ceil(g.y() - rv))),
            j1 = std::min(dims_[1] - 1, int(std::floor(g.y() + rv)));
  for (int k = k0; k <= k1; ++k) {
    const double dz = k - g.z();
    for (int j = j0; j <= j1; ++j) {
      const double dy = j - g.y();
      const double rem = rv * rv - dy * dy - dz * dz;
      if (rem < 0.0) continue;
      const double w = std::sqrt(rem);
      const int i0 = std::max(0, int(std::ceil(g.x() - w)));
      const int i1 = std::min(dims_[0] - 1, int(std::floor(g.x() + w)));
      if (i0 <= i1) f(j, k, i0, i1);
    }
  }
}

std::int64_t CoverageGrid::uncovered_in(const Sphere& s) const {
  // A ball a few blocks across reads blocks; a small one its rows.
  return s.radius > 12.0 * h_ ? uncovered_in_blocks(s) : uncovered_in_rows(s);
}

std::int64_t CoverageGrid::uncovered_in_blocks(const Sphere& s) const {
  const Vec3 g = (s.center - origin_) / h_;
  const double rv = s.radius / h_, r2 = rv * rv;
  // Blocks whose voxel centres all lie inside (or all outside) by a margin far above the
  // rounding of the row formula, so each voxel is counted exactly as uncovered_in_rows would.
  const double inner = r2 * (1.0 - 1e-9) - 1e-9, outer = r2 * (1.0 + 1e-9) + 1e-9;
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(0, int(std::ceil(g[a] - rv)));
    hi[a] = std::min(dims_[a] - 1, int(std::floor(g[a] + rv)));
    if (lo[a] > hi[a]) return 0;
  }
  std::int64_t n = 0;
  // The row spans of one row of blocks, each worked out when a block first needs it.
  int span_lo[64], span_hi[64];
  for (int bz = lo[2] >> 3; bz <= hi[2] >> 3; ++bz)
    for (int by = lo[1] >> 3; by <= hi[1] >> 3; ++by) {
      std::uint64_t known = 0;  // spans worked out in this row of blocks
      const int k0 = std::max(lo[2], 8 * bz), k1 = std::min(hi[2], 8 * bz + 7);
      const int j0 = std::max(lo[1], 8 * by), j1 = std::min(hi[1], 8 * by + 7);
      for (int bx = lo[0] >> 3; bx <= hi[0] >> 3; ++bx) {
        ++work_;
        const std::size_t b = (std::size_t(bz) * block_dims_[1] + by) * block_dims_[0] + bx;
        const std::int32_t in_block = blocks_[b];
        if (in_block == 0) continue;
        // Nearest and farthest voxel centres of the block from the ball's centre.
        const int box_lo[3] = {8 * bx, 8 * by, 8 * bz};
        double near2 = 0.0, far2 = 0.0;
        for (int a = 0; a < 3; ++a) {
          const double b0 = box_lo[a], b1 = std::min(box_lo[a] + 7, dims_[a] - 1);
          const double nearest = std::clamp(g[a], b0, b1) - g[a];
          const double farthest = std::max(std::abs(b0 - g[a]), std::abs(b1 - g[a]));
          near2 += nearest * nearest;
          far2 += farthest * farthest;
        }
        if (near2 > outer) continue;
        if (far2 <= inner) {
          n += in_block;
          continue;
        }
        // Only the row pieces with an uncovered voxel, each within its row's span (the formula
        // of for_spans).
        const int x0 = 8 * bx, x1 = 8 * bx + 7;
        for (std::uint64_t left = pieces_[b]; left != 0; left &= left - 1) {
          const int q = __builtin_ctzll(left);
          const int k = 8 * bz + (q >> 3), j = 8 * by + (q & 7);
          if (k < k0 || k > k1 || j < j0 || j > j1) continue;
          if (!(known >> q & 1)) {
            known |= std::uint64_t(1) << q;
            span_lo[q] = 1, span_hi[q] = 0;
            const double dz = k - g.z(), dy = j - g.y();
            const double rem = r2 - dy * dy - dz * dz;
            if (rem >= 0.0) {
              const double w = std::sqrt(rem);
              span_lo[q] = std::max(0, int(std::ceil(g.x() - w)));
              span_hi[q] = std::min(dims_[0] - 1, int(std::floor(g.x() + w)));
            }
          }
          const int a = std::max(span_lo[q], x0), e = std::min(span_hi[q], x1);
          if (a > e) continue;
          ++work_;
          const std::uint64_t byte = row(j, k)[bx >> 3] >> (8 * (bx & 7)) & 0xFF;
          const std::uint64_t mask = ((std::uint64_t(1) << (e - a + 1)) - 1) << (a - x0);
          n += __builtin_popcountll(byte & mask);
        }
      }
    }
  return n;
}

std::int64_t CoverageGrid::uncovered_in_rows(const Sphere& s) const {
  std::int64_t n = 0;
  for_spans(s, [&](int j, int k, int i0, int i1) {
    ++work_;
    const std::uint64_t* w = row(j, k);
    for_words(i0, i1, [&](int q, std::uint64_t mask) { n += __builtin_popcountll(w[q] & mask); });
  });
  return n;
}

void CoverageGrid::cover(const Sphere& s) {
  for_spans(s, [&](int j, int k, int i0, int i1) {
    std::uint64_t* w = row(j, k);
    for_words(i0, i1, [&](int q, std::uint64_t mask) {
      std::uint64_t cleared = w[q] & mask;
      uncovered_ -= __builtin_popcountll(cleared);
      w[q] &= ~mask;
      for (int byte = 0; cleared != 0; ++byte, cleared >>= 8)
        if (cleared & 0xFF) {
          block(64 * q + 8 * byte, j, k) -= __builtin_popcountll(cleared & 0xFF);
          update_pieces(64 * q + 8 * byte, j, k);
        }
    });
    std::uint16_t* c = counts(j, k);
    const std::uint8_t* in = &inside_[(std::size_t(k) * dims_[1] + j) * std::size_t(dims_[0])];
    for (int i = i0; i <= i1; ++i) {
      if (!in[i]) continue;
      if (c[i] == std::numeric_limits<std::uint16_t>::max())
        throw InvalidInput("fill: more than 65535 spheres cover one voxel");
      ++c[i];
    }
  });
}

void CoverageGrid::uncover(const Sphere& s) {
  for_spans(s, [&](int j, int k, int i0, int i1) {
    std::uint64_t* w = row(j, k);
    std::uint16_t* c = counts(j, k);
    const std::uint8_t* in = &inside_[(std::size_t(k) * dims_[1] + j) * std::size_t(dims_[0])];
    for (int i = i0; i <= i1; ++i) {
      if (!in[i]) continue;
      if (c[i] == 0) throw std::logic_error("coverage grid: uncovering a ball never covered");
      if (--c[i] == 0) {
        w[i >> 6] |= std::uint64_t(1) << (i & 63);
        ++uncovered_;
        ++block(i, j, k);
        update_pieces(i, j, k);
      }
    }
  });
}

}  // namespace clumpkit
