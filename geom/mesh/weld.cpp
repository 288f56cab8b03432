#include "geom/mesh/weld.h"

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

// The cell of size `tol` that holds `p`, counted from `origin`.
VertexWelder::Key cell_key(const Vec3& p, const Vec3& origin, double tol) {
  VertexWelder::Key key;
  for (int k = 0; k < 3; ++k)
    key[k] = static_cast<std::uint64_t>(std::llround((p[k] - origin[k]) / tol));
  return key;
}

}  // namespace

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
  std::size_t h = hash(key) & mask_;
  for (;; h = (h + 1) & mask_) {
    const int s = slots_[h];
    if (s < 0) break;
    if (keys_[std::size_t(s)] == key) {
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

int VertexWelder::add(const Vec3& p) {
  bool added = false;
  const int s = add_key(exact_key(p), added);
  if (added) vertices_.push_back(p);
  return s;
}

void weld_vertices(Mesh& mesh, double relative_tolerance) {
  if (mesh.vertices.empty()) return;
  const auto bb = bounding_box(mesh);
  const double tol = relative_tolerance * (bb[1] - bb[0]).norm();
  // One pass in order: exact copies share a cell, so this is the same as welding exact copies
  // first (as the STL reader does) and then their survivors by cell.
  std::vector<int> remap(mesh.vertices.size());
  std::vector<Vec3> kept;
  VertexWelder seen(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const VertexWelder::Key key = tol > 0.0 ? cell_key(p, bb[0], tol) : exact_key(p);
    bool added = false;
    remap[i] = seen.add_key(key, added);
    if (added) kept.push_back(p);
  }
  std::vector<std::array<int, 3>> tris;
  tris.reserve(mesh.triangles.size());
  for (auto t : mesh.triangles) {
    for (int& k : t) k = remap[k];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) tris.push_back(t);
  }
  mesh.vertices = std::move(kept);
  mesh.triangles = std::move(tris);
}

}  // namespace clumpkit
