// Interior voxels of a distance field covered by a set of balls: how many balls cover each, and
// one bit per voxel no ball covers, so a ball's uncovered voxels are counted a row span at a time.
#pragma once

#include "geom/fill/distance_field.h"
#include "geom/sphere.h"

#include <array>
#include <cstdint>
#include <vector>

namespace clumpkit {

/// The interior voxels (field value > 0) of a field; a voxel is in a ball when its centre is.
/// Rows along x are packed in 64-bit words for popcount; the counts (one per voxel) let a ball
/// be taken out again, so a refinement can move a sphere. Blocks of 8³ voxels keep how many of
/// theirs are uncovered, so a large ball counts a block wholly inside it, or with nothing
/// uncovered, at once: the count stays exact, but late in a fill, when little is left, it reads
/// a few blocks instead of thousands of rows. Each block also knows which of its 64 row pieces
/// hold an uncovered voxel, so a block the ball's surface cuts reads only those.
class CoverageGrid {
 public:
  explicit CoverageGrid(const DistanceField& field);

  double voxel() const { return h_; }
  std::int64_t interior() const { return interior_; }
  std::int64_t uncovered() const { return uncovered_; }
  double covered_fraction() const {
    return interior_ > 0 ? 1.0 - double(uncovered_) / double(interior_) : 0.0;
  }

  /// Interior voxels inside `s` that no ball covers.
  std::int64_t uncovered_in(const Sphere& s) const;
  /// Row spans, blocks and row pieces uncovered_in has read so far: the fill's measure of work, the
  /// same on every machine, so a budget in it keeps the clump independent of the machine's speed.
  std::int64_t work() const { return work_; }
  /// Adds `s` to the cover.
  void cover(const Sphere& s);
  /// Takes out `s`, which cover() added before (the same bits).
  void uncover(const Sphere& s);

 private:
  void init();  // bits, blocks and row pieces from inside_
  // Calls f(j, k, i0, i1) for every row span of voxel centres inside `s`.
  template <class F>
  void for_spans(const Sphere& s, F&& f) const;
  std::int64_t uncovered_in_rows(const Sphere& s) const;
  std::int64_t uncovered_in_blocks(const Sphere& s) const;
  std::size_t block_index(int i, int j, int k) const {
    return (std::size_t(k >> 3) * block_dims_[1] + (j >> 3)) * block_dims_[0] + (i >> 3);
  }
  std::int32_t& block(int i, int j, int k) { return blocks_[block_index(i, j, k)]; }
  // Keeps bit (k & 7)·8 + (j & 7) of the block of voxel (i, j, k) set iff its row piece has an
  // uncovered voxel, after a change to the word of bits holding voxel i.
  void update_pieces(int i, int j, int k) {
    const std::uint64_t bit = std::uint64_t(1) << ((k & 7) * 8 + (j & 7));
    std::uint64_t& pieces = pieces_[block_index(i, j, k)];
    pieces = (row(j, k)[i >> 6] >> (8 * ((i >> 3) & 7)) & 0xFF) ? pieces | bit : pieces & ~bit;
  }
  std::uint64_t* row(int j, int k) { return &bits_[(std::size_t(k) * dims_[1] + j) * words_]; }
  const std::uint64_t* row(int j, int k) const {
    return &bits_[(std::size_t(k) * dims_[1] + j) * words_];
  }
  std::uint16_t* counts(int j, int k) {
    return &count_[(std::size_t(k) * dims_[1] + j) * std::size_t(dims_[0])];
  }

  Vec3 origin_;
  double h_;
  std::array<int, 3> dims_;
  int words_;
  std::vector<std::uint64_t> bits_;    // 1: interior and covered by no ball
  std::vector<std::uint8_t> inside_;   // 1: interior
  std::vector<std::uint16_t> count_;   // balls covering each voxel
  std::array<int, 3> block_dims_;      // blocks of 8³ voxels (x: 8 per word of a row)
  std::vector<std::int32_t> blocks_;   // uncovered voxels per block
  std::vector<std::uint64_t> pieces_;  // per block: its row pieces with an uncovered voxel
  std::int64_t interior_ = 0, uncovered_ = 0;
  mutable std::int64_t work_ = 0;
};

}  // namespace clumpkit
