// check_mesh's counts on small meshes whose defects are known.
#include "geom/mesh/mesh.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

using namespace clumpkit;

TEST(CheckMesh, CountsTheDefectsOfSmallMeshes) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  const MeshCheck whole = check_mesh(cube);
  EXPECT_TRUE(whole.closed && whole.manifold && whole.oriented && !whole.degenerate);
  EXPECT_EQ(whole.boundary_edges, 0);

  Mesh open = cube;  // one triangle less: its three edges are used once
  open.triangles.pop_back();
  const MeshCheck o = check_mesh(open);
  EXPECT_EQ(o.boundary_edges, 3);
  EXPECT_FALSE(o.closed);
  EXPECT_FALSE(o.oriented);

  Mesh flipped = cube;  // one triangle the wrong way round: closed, manifold, not oriented
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  const MeshCheck f = check_mesh(flipped);
  EXPECT_TRUE(f.closed && f.manifold);
  EXPECT_FALSE(f.oriented);

  Mesh fin = cube;  // a third triangle on one edge of the cube
  const auto e = cube.triangles[0];
  fin.vertices.push_back(Vec3(5, 5, 5));
  fin.triangles.push_back({e[0], e[1], static_cast<int>(fin.vertices.size()) - 1});
  const MeshCheck n = check_mesh(fin);
  EXPECT_EQ(n.nonmanifold_edges, 1);
  EXPECT_FALSE(n.manifold);

  Mesh bowtie = cube;  // a second cube sharing one corner only: a non-manifold vertex
  Mesh other = make_box(Vec3(1, 1, 1));
  const auto corner = [](const Mesh& m, const Vec3& p) {
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      if (m.vertices[v] == p) return static_cast<int>(v);
    return -1;
  };
  const auto bb = bounding_box(cube);
  const Vec3 shift = bb[1] - bb[0];
  for (Vec3& p : other.vertices) p += shift;
  append_mesh(bowtie, other);
  const int shared = corner(bowtie, bb[1]);
  const int copy = static_cast<int>(cube.vertices.size()) + corner(other, bb[1]);
  ASSERT_GE(shared, 0);
  for (auto& t : bowtie.triangles)
    for (int& k : t)
      if (k == copy) k = shared;
  const MeshCheck b = check_mesh(bowtie);
  EXPECT_EQ(b.nonmanifold_edges, 0);
  EXPECT_EQ(b.boundary_edges, 0);
  EXPECT_FALSE(b.manifold);

  Mesh flat = cube;  // a zero-area triangle
  flat.vertices.push_back(0.5 * (cube.vertices[e[0]] + cube.vertices[e[1]]));
  flat.triangles.push_back({e[0], e[1], static_cast<int>(flat.vertices.size()) - 1});
  EXPECT_TRUE(check_mesh(flat).degenerate);
}
