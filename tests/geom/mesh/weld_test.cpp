// Welding a triangle soup, against a plain quadratic oracle, and as the STL reader welds.
#include "geom/mesh/weld.h"
#include "geom/random.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace clumpkit;

namespace {

// The meaning of welding, written the slow way: vertex i joins the first vertex j <= i with the
// same key (exact coordinates, -0 equal to +0, or the same cell of size tol from the box corner),
// survivors in the order of first occurrence.
Mesh weld_oracle(const Mesh& soup, double relative_tolerance) {
  const auto bb = bounding_box(soup);
  const double tol = relative_tolerance * (bb[1] - bb[0]).norm();
  auto same = [&](const Vec3& p, const Vec3& q) {
    for (int k = 0; k < 3; ++k) {
      if (tol > 0.0 ? std::llround((p[k] - bb[0][k]) / tol) != std::llround((q[k] - bb[0][k]) / tol)
                    : p[k] != q[k])
        return false;
    }
    return true;
  };
  Mesh out;
  std::vector<int> remap(soup.vertices.size());
  for (std::size_t i = 0; i < soup.vertices.size(); ++i) {
    int found = -1;
    for (std::size_t j = 0; j < i && found < 0; ++j)
      if (same(soup.vertices[j], soup.vertices[i])) found = remap[j];
    if (found < 0) {
      found = static_cast<int>(out.vertices.size());
      out.vertices.push_back(soup.vertices[i]);
    }
    remap[i] = found;
  }
  for (auto t : soup.triangles) {
    for (int& k : t) k = remap[k];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) out.triangles.push_back(t);
  }
  return out;
}

// A soup of `n` triangles whose corners come from a few grid points, each copy exact, with -0
// for +0, or moved by less than `jitter` (relative to the unit box).
Mesh random_soup(Rng& rng, int n, double jitter) {
  Mesh soup;
  for (int f = 0; f < n; ++f) {
    for (int k = 0; k < 3; ++k) {
      Vec3 p = rng.uniform(Vec3::Zero(), Vec3::Constant(4)).array().floor().matrix() / 4.0;
      const double u = rng.uniform();
      if (u < 0.2) p += rng.uniform(Vec3::Constant(-jitter), Vec3::Constant(jitter));
      if (u > 0.9)
        for (int c = 0; c < 3; ++c)
          if (p[c] == 0.0) p[c] = -0.0;
      soup.vertices.push_back(p);
    }
    const int v = 3 * f;
    soup.triangles.push_back({v, v + 1, v + 2});
  }
  return soup;
}

}  // namespace

TEST(WeldVertices, SameAsTheQuadraticOracleExactAndWithATolerance) {
  Rng rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const Mesh soup = random_soup(rng, 60, trial % 2 ? 1e-7 : 0.0);
    for (double tol : {0.0, 1e-9, 1e-5, 0.1}) {
      Mesh welded = soup;
      weld_vertices(welded, tol);
      const Mesh expected = weld_oracle(soup, tol);
      ASSERT_EQ(welded.vertices.size(), expected.vertices.size()) << trial << " " << tol;
      for (std::size_t v = 0; v < expected.vertices.size(); ++v)
        for (int k = 0; k < 3; ++k)  // bitwise: the first copy's own coordinates are kept
          ASSERT_EQ(std::signbit(welded.vertices[v][k]), std::signbit(expected.vertices[v][k]));
      ASSERT_EQ(welded.vertices, expected.vertices) << trial << " " << tol;
      ASSERT_EQ(welded.triangles, expected.triangles) << trial << " " << tol;
    }
  }
}

TEST(WeldVertices, ASoupOfACubeBecomesTheClosedCube) {
  const Mesh cube = make_box(Vec3(1, 2, 3));
  Mesh soup;
  for (const auto& t : cube.triangles) {
    const int v = static_cast<int>(soup.vertices.size());
    for (int k : t) soup.vertices.push_back(cube.vertices[k]);
    soup.triangles.push_back({v, v + 1, v + 2});
  }
  EXPECT_EQ(check_mesh(soup).boundary_edges, 3 * static_cast<int>(cube.triangles.size()));
  weld_vertices(soup);
  EXPECT_EQ(soup.vertices.size(), 8u);
  const MeshCheck c = check_mesh(soup);
  EXPECT_TRUE(c.closed && c.manifold && c.oriented && !c.degenerate);
  EXPECT_NEAR(c.volume, 6.0, 1e-12);
}

// The STL reader welds exact copies as it reads, then the intake welds within its tolerance:
// the same mesh as welding the whole soup at once.
TEST(VertexWelder, ExactWeldAsReadThenTheToleranceIsTheWholeSoupsWeld) {
  Rng rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Mesh soup = random_soup(rng, 80, trial % 2 ? 1e-7 : 0.0);
    Mesh read;
    VertexWelder weld;
    for (const auto& t : soup.triangles) {
      const int a = weld.add(soup.vertices[t[0]]), b = weld.add(soup.vertices[t[1]]),
                c = weld.add(soup.vertices[t[2]]);
      read.triangles.push_back({a, b, c});
    }
    read.vertices = weld.take_vertices();
    for (double tol : {0.0, 1e-9, 1e-5}) {
      Mesh once = soup, twice = read;
      weld_vertices(once, tol);
      weld_vertices(twice, tol);
      ASSERT_EQ(once.vertices, twice.vertices) << trial << " " << tol;
      ASSERT_EQ(once.triangles, twice.triangles) << trial << " " << tol;
    }
  }
}

// The batch add (which fetches the table's lines ahead) numbers points as one add at a time
// does, exact and by cells, across blocks and while the table grows; by cells it is
// weld_vertices of the whole soup.
TEST(VertexWelder, BatchAddIsOneAtATimeAndCellsAreTheWholeSoupsWeld) {
  Rng rng(8);
  for (int trial = 0; trial < 6; ++trial) {
    const Mesh soup = random_soup(rng, 400, 1e-7);
    const auto bb = bounding_box(soup);
    for (double tol : {0.0, 1e-9, 1e-5}) {
      const double cell = tol * (bb[1] - bb[0]).norm();
      VertexWelder one(4, bb[0], cell), batch(4, bb[0], cell);
      std::vector<int> expected, got(soup.vertices.size());
      for (const Vec3& p : soup.vertices) expected.push_back(one.add(p));
      batch.add(soup.vertices.data(), soup.vertices.size(), got.data());
      ASSERT_EQ(got, expected) << trial << " " << tol;
      Mesh read;
      read.vertices = batch.take_vertices();
      ASSERT_EQ(read.vertices, one.take_vertices());
      for (const auto& t : soup.triangles) {
        const std::array<int, 3> w{got[t[0]], got[t[1]], got[t[2]]};
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) read.triangles.push_back(w);
      }
      Mesh welded = soup;
      weld_vertices(welded, tol);
      ASSERT_EQ(read.vertices, welded.vertices) << trial << " " << tol;
      ASSERT_EQ(read.triangles, welded.triangles) << trial << " " << tol;
    }
  }
}

TEST(VertexWelder, GrowsPastItsHintAndKeepsTheFirstIndexOfEachVertex) {
  VertexWelder weld(4);
  for (int i = 0; i < 10000; ++i) ASSERT_EQ(weld.add(Vec3(i, 0.5 * i, -i)), i);
  for (int i = 9999; i >= 0; --i) ASSERT_EQ(weld.add(Vec3(i, 0.5 * i, -i)), i);
  EXPECT_EQ(weld.add(Vec3(-0.0, 0.0, 0.0)), 0);  // -0 is +0
  EXPECT_EQ(weld.take_vertices().size(), 10000u);
}
