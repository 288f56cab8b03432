// The volume a clump puts outside its mesh, kept sphere by sphere on a lattice of rows, so a
// fill can hold it under a bound (fill --max-overshoot) while it adds, moves and removes spheres.
#pragma once

#include "geom/mesh/mesh_index.h"
#include "geom/sphere.h"

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace clumpkit {

/// Rows along x on a (y, z) lattice of the given spacing. Each row knows the mesh's inside
/// intervals (from the index's crossings, exact in x) and every recorded sphere's chord parts
/// outside them; the outside volume is the length of their union times spacing² — exact along
/// x, the 2-D midpoint rule across. A row whose crossings stay odd after nudging (it runs
/// in a face's plane) counts as all outside, so the ledger never under-counts for it.
class OvershootLedger {
 public:
  /// Rows cover `box` (the region spheres can reach); spacing > 0.
  OvershootLedger(const MeshIndex& index, const std::array<Vec3, 2>& box, double spacing);
  ~OvershootLedger();
  OvershootLedger(const OvershootLedger&) = delete;
  OvershootLedger& operator=(const OvershootLedger&) = delete;

  /// Outside volume that `s` would add to the spheres recorded so far.
  double added(const Sphere& s) const;
  /// Records `s`.
  void add(const Sphere& s);
  /// Forgets one recorded copy of `s` (the same centre and radius bits as recorded); the volume
  /// drops by what no other recorded sphere covers.
  void remove(const Sphere& s);
  /// Outside volume of the recorded spheres.
  double volume() const { return volume_; }

 private:
  struct Row;
  Row& row(int j, int k) const;
  enum class Visit { measure, record, erase };
  double visit(const Sphere& s, Visit what) const;

  const MeshIndex& index_;
  Vec3 lo_;
  double spacing_;
  int ny_ = 0, nz_ = 0;
  mutable std::vector<std::unique_ptr<Row>> rows_;  // made when first touched
  // Per row, the mesh's inside interval when the row is made and has exactly one, else an empty
  // one (+inf, -inf): a chord inside it has no part outside, which most chords of a sphere are,
  // so visit() settles them from this flat array without touching the row.
  mutable std::vector<std::array<double, 2>> single_inside_;
  mutable std::vector<std::uint32_t> recorded_parts_;  // per row: its recorded parts outside
  // Blocks of 8 × 8 rows: the intersection of their rows' one inside intervals, once every row
  // of the block is made and has one (`complete`), so visit() settles a whole block at once when
  // the widest chord of its rows lies inside it — most of a large sphere's rows.
  struct Block {
    int made = 0;         // rows made with exactly one inside interval
    bool broken = false;  // a row made with none or several
    double lo = -1e300, hi = 1e300;
  };
  mutable std::vector<Block> blocks_;
  int nby_ = 0;  // blocks along y
  double volume_ = 0.0;
};

}  // namespace clumpkit
