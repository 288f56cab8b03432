#include "geom/mesh/shells.h"

#include "geom/errors.h"

#include "geom/mesh/cgal_surface.h"

#include <CGAL/Polygon_mesh_processing/intersection.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace clumpkit {

namespace {

using cgal_surface::SurfaceMesh;

int find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

std::array<Vec3, 2> box_of(const Mesh& mesh, const Shell& s) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (int t : s.triangles)
    for (int v : mesh.triangles[t]) {
      lo = lo.cwiseMin(mesh.vertices[v]);
      hi = hi.cwiseMax(mesh.vertices[v]);
    }
  return {lo, hi};
}

bool boxes_overlap(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b) {
  return (a[0].array() <= b[1].array()).all() && (b[0].array() <= a[1].array()).all();
}

}  // namespace

double winding_number(const Mesh& mesh, const std::vector<int>& triangles, const Vec3& p) {
  double sum = 0;
  for (int t : triangles) {
    const Vec3 a = mesh.vertices[mesh.triangles[t][0]] - p;
    const Vec3 b = mesh.vertices[mesh.triangles[t][1]] - p;
    const Vec3 c = mesh.vertices[mesh.triangles[t][2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2.0 * std::atan2(a.dot(b.cross(c)),
                            la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return sum / (4.0 * M_PI);
}

namespace {

// Vertices joined by the triangles' edges (union-find, roots by find()).
std::vector<int> joined_vertices(const Mesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[find(parent, t[k])] = find(parent, t[0]);
  return parent;
}

// The number of shells, without listing their triangles: a scan is one shell.
std::size_t count_shells(const Mesh& mesh) {
  std::vector<int> parent = joined_vertices(mesh);
  std::vector<char> seen(parent.size(), 0);
  std::size_t count = 0;
  for (const auto& t : mesh.triangles) {
    char& s = seen[std::size_t(find(parent, t[0]))];
    count += s == 0;
    s = 1;
  }
  return count;
}

}  // namespace

std::vector<Shell> mesh_shells(const Mesh& mesh) {
  const int nv = static_cast<int>(mesh.vertices.size());
  std::vector<int> parent = joined_vertices(mesh);
  std::vector<int> shell_of_root(nv, -1);
  std::vector<Shell> shells;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    int& s = shell_of_root[find(parent, mesh.triangles[t][0])];
    if (s < 0) {
      s = static_cast<int>(shells.size());
      shells.emplace_back();
    }
    shells[s].triangles.push_back(t);
  }
  if (shells.size() < 2) {
    for (Shell& s : shells) s.volume = signed_volume(mesh);
    return shells;
  }
  std::vector<std::array<Vec3, 2>> boxes;
  for (Shell& s : shells) {
    for (int t : s.triangles) {
      const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
      const Vec3& b = mesh.vertices[mesh.triangles[t][1]];
      const Vec3& c = mesh.vertices[mesh.triangles[t][2]];
      s.volume += a.dot(b.cross(c)) / 6.0;
    }
    boxes.push_back(box_of(mesh, s));
  }
  for (std::size_t i = 0; i < shells.size(); ++i) {
    const Vec3& p = mesh.vertices[mesh.triangles[shells[i].triangles.front()][0]];
    for (std::size_t j = 0; j < shells.size(); ++j) {
      if (j == i || !boxes_overlap({p, p}, boxes[j])) continue;
      if (std::abs(winding_number(mesh, shells[j].triangles, p)) < 0.5) continue;
      ++shells[i].depth;
      if (shells[i].parent < 0 ||
          std::abs(shells[j].volume) < std::abs(shells[shells[i].parent].volume))
        shells[i].parent = static_cast<int>(j);
    }
  }
  return shells;
}

bool orient_shells(Mesh& mesh, std::size_t* count) {
  const std::size_t n = count_shells(mesh);
  if (count) *count = n;
  if (n < 2) return false;
  std::vector<Shell> shells = mesh_shells(mesh);
  const auto name = [&](std::size_t i) {
    return "shell " + std::to_string(i + 1) + " of " + std::to_string(shells.size());
  };
  // Crossing or touching surfaces first: nesting means nothing for them.
  std::vector<std::array<Vec3, 2>> boxes;
  for (const Shell& s : shells) boxes.push_back(box_of(mesh, s));
  std::vector<SurfaceMesh> surfaces;
  for (const Shell& s : shells)
    surfaces.push_back(cgal_surface::to_surface_mesh(mesh, &s.triangles));
  const auto cross = [&](std::size_t i, std::size_t j) {
    try {
      return CGAL::Polygon_mesh_processing::do_intersect(surfaces[i], surfaces[j]);
    } catch (const std::exception& e) {  // CGAL's precondition and assertion exceptions
      throw InvalidInput(name(i) + " and shell " + std::to_string(j + 1) +
                         " could not be tested for crossing: " + e.what());
    }
  };
  // Shells that meet only at corners they have at one position (lobes touching along an edge or
  // at a vertex, split apart on reading) overlap nowhere: their volumes add.
  const auto only_touch = [&](std::size_t i, std::size_t j) {
    std::vector<int> both = shells[i].triangles;
    both.insert(both.end(), shells[j].triangles.begin(), shells[j].triangles.end());
    const SurfaceMesh pair = cgal_surface::to_surface_mesh(mesh, &both);
    const std::size_t first_of_j = shells[i].triangles.size();
    for (const auto& [f, g] : cgal_surface::crossing_faces(pair))
      if ((f.idx() < first_of_j) != (g.idx() < first_of_j)) return false;
    return true;
  };
  for (std::size_t i = 0; i < shells.size(); ++i)
    for (std::size_t j = i + 1; j < shells.size(); ++j)
      if (boxes_overlap(boxes[i], boxes[j]) && cross(i, j) && !only_touch(i, j))
        throw InvalidInput(name(i) + " and shell " + std::to_string(j + 1) +
                           " cross or touch each other, so their overlap would count twice; "
                           "unite them into one closed surface first");
  bool flipped = false;
  for (std::size_t i = 0; i < shells.size(); ++i) {
    Shell& s = shells[i];
    const bool outward = s.depth % 2 == 0;
    if (s.depth == 0 && s.volume < 0) {
      for (int t : s.triangles) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      flipped = true;
      continue;
    }
    if ((s.volume > 0) != outward)
      throw InvalidInput(name(i) + " lies inside shell " + std::to_string(s.parent + 1) +
                         " and faces the same way (" +
                         (outward ? "inward, a void in a void" : "outward, a solid in a solid") +
                         "); flip it to make it " + (outward ? "an island" : "a void") +
                         ", or remove it");
  }
  return flipped;
}

}  // namespace clumpkit
