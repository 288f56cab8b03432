#include "geom/mesh/mesh_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <vector>

namespace clumpkit {

namespace {
// Distances need no exact predicates: plain double arithmetic.
using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
}  // namespace

struct MeshDistance::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
};

MeshDistance::MeshDistance(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  auto point = [&](int i) {
    const Vec3& p = mesh.vertices[i];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  impl_->triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    impl_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
}

MeshDistance::~MeshDistance() = default;

double MeshDistance::distance(const Vec3& p) const {
  return std::sqrt(impl_->tree.squared_distance(K::Point_3(p.x(), p.y(), p.z())));
}

}  // namespace clumpkit
