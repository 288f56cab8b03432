#include "geom/mesh/weld.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clumpkit {

namespace {

std::size_t hash(const VertexWelder::Key& key) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::uint64_t w : key) {
    h = (h ^ w) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return static_cast<std::size_t>(h);
}

VertexWelder::Key exact_key(const Vec3& p) {
  VertexWelder::Key key;
  for (int k = 0; k < 3; ++k) {
    const double v = p[k] + 0.0;  // one key for −0 and +0
    std::memcpy(&key[k], &v, sizeof v);
  }
  return key;
}

// std::llround (halves away from zero) without the library call, three per corner of a scan:
// below 2⁵² the truncation and the remainder are exact.
long long round_half_away(double x) {
  if (!(std::abs(x) < 0x1p52)) return std::llround(x);
  const auto t = static_cast<long long>(x);
  const double rest = x - static_cast<double>(t);
  return rest >= 0.5 ? t + 1 : rest <= -0.5 ? t - 1 : t;
}

// The cell of size `tol` that holds `p`, counted from `origin`.
VertexWelder::Key cell_key(const Vec3& p, const Vec3& origin, double tol) {
  VertexWelder::Key key;
  for (int k = 0; k < 3; ++k)
    key[k] = static_cast<std::uint64_t>(round_half_away((p[k] - origin[k]) / tol));
  return key;
}

// Three words compared directly: std::array's == calls memcmp, a tenth of a scan's reading.
bool same(const VertexWelder::Key& a, const VertexWelder::Key& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

}  // namespace

VertexWelder::VertexWelder(std::size_t expected, const Vec3& origin, double cell)
    : VertexWelder(expected) {
  origin_ = origin;
  cell_ = cell > 0.0 ? cell : 0.0;
}

VertexWelder::VertexWelder(std::size_t expected) {
  std::size_t capacity = 16;
  while (capacity < 2 * expected) capacity *= 2;
  mask_ = capacity - 1;
  slots_.assign(capacity, -1);
  keys_.reserve(expected);
}

void VertexWelder::grow() {
  mask_ = 2 * mask_ + 1;
  slots_.assign(mask_ + 1, -1);
  for (std::size_t s = 0; s < keys_.size(); ++s) {
    std::size_t h = hash(keys_[s]) & mask_;
    while (slots_[h] >= 0) h = (h + 1) & mask_;
    slots_[h] = static_cast<int>(s);
  }
}

int VertexWelder::add_key(const Key& key, bool& added) {
  return add_key(key, hash(key), added);
}

int VertexWelder::add_key(const Key& key, std::size_t full_hash, bool& added) {
  std::size_t h = full_hash & mask_;
  for (;; h = (h + 1) & mask_) {
    const int s = slots_[h];
    if (s < 0) break;
    if (same(keys_[std::size_t(s)], key)) {
      added = false;
      return s;
    }
  }
  const int s = static_cast<int>(keys_.size());
  slots_[h] = s;
  keys_.push_back(key);
  added = true;
  if (2 * keys_.size() > mask_ + 1) grow();  // load at most 1/2: short probe runs
  return s;
}

VertexWelder::Key VertexWelder::key_of(const Vec3& p) const {
  return cell_ > 0.0 ? cell_key(p, origin_, cell_) : exact_key(p);
}

int VertexWelder::add(const Vec3& p) {
  bool added = false;
  const int s = add_key(key_of(p), added);
  if (added) vertices_.push_back(p);
  return s;
}

void VertexWelder::add(const Vec3* points, std::size_t n, int* index) {
  // Two stages ahead: the slot of the point kAhead on, then the key that slot names for the
  // point half as far on, so both lines are in cache when the point's turn comes.
  constexpr std::size_t kBlock = 256, kAhead = 16;
  std::array<Key, kBlock> keys;
  std::array<std::size_t, kBlock> hashes;
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = std::min(kBlock, n - b);
    for (std::size_t i = 0; i < m; ++i) {
      keys[i] = key_of(points[b + i]);
      hashes[i] = hash(keys[i]);
    }
    for (std::size_t i = 0; i < std::min(kAhead, m); ++i)
      __builtin_prefetch(&slots_[hashes[i] & mask_]);
    for (std::size_t i = 0; i < m; ++i) {
      if (i + kAhead < m) __builtin_prefetch(&slots_[hashes[i + kAhead] & mask_]);
      if (i + kAhead / 2 < m) {
        const int s = slots_[hashes[i + kAhead / 2] & mask_];
        if (s >= 0) __builtin_prefetch(&keys_[std::size_t(s)]);
      }
      bool added = false;
      index[b + i] = add_key(keys[i], hashes[i], added);
      if (added) vertices_.push_back(points[b + i]);
    }
  }
}

void weld_vertices(Mesh& mesh, double relative_tolerance) {
  // A non-finite coordinate would collapse the whole grid: such a mesh stays as it is, so that
  // its reader reports the coordinate instead of a misleading "no triangles".
  if (mesh.vertices.empty() || !std::all_of(mesh.vertices.begin(), mesh.vertices.end(),
                                            [](const Vec3& p) { return p.allFinite(); }))
    return;
  const auto bb = bounding_box(mesh);
  const double tol = relative_tolerance * (bb[1] - bb[0]).norm();
  // One pass in order: exact copies share a cell, so this is the same as welding exact copies
  // first (as the STL reader does for a mesh with a non-finite corner) and then their survivors
  // by cell.
  std::vector<int> remap(mesh.vertices.size());
  VertexWelder seen(mesh.vertices.size(), bb[0], tol);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) remap[i] = seen.add(mesh.vertices[i]);
  std::vector<std::array<int, 3>> tris;
  tris.reserve(mesh.triangles.size());
  for (auto t : mesh.triangles) {
    for (int& k : t) k = remap[k];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) tris.push_back(t);
  }
  mesh.vertices = seen.take_vertices();
  mesh.triangles = std::move(tris);
}

}  // namespace clumpkit
