#include "geom/shapes/block.h"

#include "geom/errors.h"
#include "geom/limits.h"

#include <cmath>
#include <map>
#include <string>

namespace clumpkit {

namespace {
void positive(double v, const char* field) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InvalidInput(std::string("block: ") + field + " must be positive and finite, got " +
                       std::to_string(v));
}
}  // namespace

void validate(const BlockParams& p) {
  check_size(p.L, "block: L");
  check_size(p.W, "block: W");
  check_size(p.H, "block: H");
  positive(p.sl, "sl");
  positive(p.su, "su");
  if (p.nd < 1 || p.nd > 64)
    throw InvalidInput("block: nd must be in [1, 64], got " + std::to_string(p.nd));
  if (p.sl > p.su)
    throw InvalidInput("block: sl must not exceed su, got sl=" + std::to_string(p.sl) +
                       " su=" + std::to_string(p.su));
}

Mesh make_block(const BlockParams& p, Rng& rng) {
  validate(p);
  const int n = p.nd;
  const Vec3 size(p.L, p.W, p.H);
  Mesh m;
  // Surface nodes of the (n+1)³ lattice, keyed by lattice coordinates so that nodes on shared
  // edges and corners are created once.
  std::map<std::array<int, 3>, int> node;
  auto id = [&](std::array<int, 3> ijk) {
    auto [it, inserted] = node.emplace(ijk, static_cast<int>(m.vertices.size()));
    if (inserted) {
      Vec3 x;
      for (int k = 0; k < 3; ++k) x[k] = size[k] * (double(ijk[k]) / n - 0.5);
      m.vertices.push_back(x);
    }
    return it->second;
  };
  // Each face: fixed axis a at side s (0 or n); (u, v) the other two axes in cyclic order so
  // that u × v points along +a; the s = 0 side reverses the winding.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side <= n; side += n) {
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int di, int dj) {
            std::array<int, 3> ijk{};
            ijk[a] = side;
            ijk[u] = i + di;
            ijk[v] = j + dj;
            return id(ijk);
          };
          const int q00 = at(0, 0), q10 = at(1, 0), q11 = at(1, 1), q01 = at(0, 1);
          // Alternate the diagonal in a checkerboard so the faceting has no preferred direction.
          std::array<int, 3> t1, t2;
          if ((i + j) % 2 == 0) {
            t1 = {q00, q10, q11};
            t2 = {q00, q11, q01};
          } else {
            t1 = {q00, q10, q01};
            t2 = {q10, q11, q01};
          }
          if (side == 0) {
            std::swap(t1[1], t1[2]);
            std::swap(t2[1], t2[2]);
          }
          m.triangles.push_back(t1);
          m.triangles.push_back(t2);
        }
      if (n == 0) break;
    }
  }
  // Node order is fixed by the lattice walk, so the random factors are reproducible.
  for (auto& x : m.vertices) x *= rng.uniform(p.sl, p.su);
  return m;
}

}  // namespace clumpkit
