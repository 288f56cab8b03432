#include "geom/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace clumpkit {

double signed_volume(const Mesh& mesh) {
  double v = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    v += a.dot(b.cross(c));
  }
  return v / 6.0;
}

double surface_area(const Mesh& mesh) {
  double s = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    s += (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return 0.5 * s;
}

namespace {

// Volume integrals of 1, x, and x xᵀ over the solid, from signed tetrahedra (o, a, b, c).
// For a tetrahedron with one vertex at the origin and volume V:
//   ∫x dV = V (a+b+c)/4,  ∫x xᵀ dV = V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a+b+c.
struct Moments {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
};

Moments moments_about(const Mesh& mesh, const Vec3& origin) {
  Moments m;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin;
    const Vec3 b = mesh.vertices[t[1]] - origin;
    const Vec3 c = mesh.vertices[t[2]] - origin;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vec3 s = a + b + c;
    m.volume += v;
    m.first += v * s / 4.0;
    // The upper triangle only (the same sums, term for term), mirrored below at the end.
    const double w = v / 20.0;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        m.second(i, j) += w * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) m.second(i, j) = m.second(j, i);
  return m;
}

Vec3 box_centre(const Mesh& mesh) {
  const auto bb = bounding_box(mesh);
  return 0.5 * (bb[0] + bb[1]);
}

}  // namespace

Vec3 solid_centroid(const Mesh& mesh) {
  // Integrate about the box centre to limit cancellation for meshes far from the origin.
  const Vec3 o = box_centre(mesh);
  const Moments m = moments_about(mesh, o);
  return o + m.first / m.volume;
}

Mat3 solid_inertia(const Mesh& mesh) {
  return solid_inertia(mesh, solid_centroid(mesh));
}

Mat3 solid_inertia(const Mesh& mesh, const Vec3& c) {
  const Moments m = moments_about(mesh, c);
  // Inertia from the covariance: I = tr(C) δ - C.
  return m.second.trace() * Mat3::Identity() - m.second;
}

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck r;
  const int nv = static_cast<int>(mesh.vertices.size());
  // Every directed edge filed under its lower vertex (compressed rows) as one key: the higher
  // vertex and the direction in the lowest bit, so each edge's uses are adjacent once a row is
  // sorted and are counted in one pass. Rows hold a handful of keys: sorting them is cheaper
  // than one sort of a scan's 4·10⁶ edges (and a tree map took seconds). Indices are below 2³¹.
  const auto bb =
      mesh.vertices.empty() ? std::array<Vec3, 2>{Vec3::Zero(), Vec3::Zero()} : bounding_box(mesh);
  const double scale = (bb[1] - bb[0]).norm();
  std::vector<int> row(std::size_t(nv) + 1, 0);
  auto valid = [&](const std::array<int, 3>& t) {
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= nv) return false;
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
  };
  for (const auto& t : mesh.triangles) {
    if (!valid(t)) {
      r.degenerate = true;
      continue;
    }
    const Vec3& a = mesh.vertices[t[0]];
    const double area2 = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
    if (!(area2 > 1e-14 * scale * scale)) r.degenerate = true;
    for (int k = 0; k < 3; ++k) ++row[std::size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
  }
  for (int v = 0; v < nv; ++v) row[v + 1] += row[v];
  std::vector<std::uint32_t> keys(static_cast<std::size_t>(row[nv]));
  {
    std::vector<int> next(row.begin(), row.end() - 1);
    for (const auto& t : mesh.triangles) {
      if (!valid(t)) continue;
      for (int k = 0; k < 3; ++k) {
        const int from = t[k], to = t[(k + 1) % 3];
        keys[next[std::min(from, to)]++] =
            (std::uint32_t(std::max(from, to)) << 1) | std::uint32_t(from > to);
      }
    }
  }
  bool oriented = true;
  for (int v = 0; v < nv; ++v) {
    const auto first = keys.begin() + row[v], last = keys.begin() + row[v + 1];
    std::sort(first, last);
    for (auto q = first; q != last;) {
      int uses[2] = {0, 0};  // low-to-high, high-to-low
      const std::uint32_t edge = *q >> 1;
      for (; q != last && *q >> 1 == edge; ++q) ++uses[*q & 1];
      if (uses[0] > 1 || uses[1] > 1) oriented = false;  // a directed edge used twice
      const int total = uses[0] + uses[1];
      if (total == 1) {
        ++r.boundary_edges;
        oriented = false;
      } else if (total > 2) {
        ++r.nonmanifold_edges;
      } else if (uses[0] == 0 || uses[1] == 0) {
        oriented = false;  // the two uses run in the same direction
      }
    }
  }
  // Vertex manifoldness: the triangles around each vertex must form a single fan.
  bool vertex_manifold = true;
  if (r.nonmanifold_edges == 0 && !mesh.triangles.empty()) {
    // Stars in compressed rows: the faces of vertex v are star[first[v] .. first[v + 1]).
    std::vector<int> first(nv + 1, 0);
    for (const auto& t : mesh.triangles)
      for (int v : t)
        if (v >= 0 && v < nv) ++first[v + 1];
    for (int v = 0; v < nv; ++v) first[v + 1] += first[v];
    std::vector<int> star(first[nv]), fill(first.begin(), first.end() - 1);
    for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
      for (int v : mesh.triangles[f])
        if (v >= 0 && v < nv) star[fill[v]++] = f;
    std::vector<int> parent;
    std::vector<std::pair<int, int>> ends;  // (other endpoint, star index)
    for (int v = 0; v < nv && vertex_manifold; ++v) {
      const int m = first[v + 1] - first[v];
      if (m == 0) continue;
      // Union-find over the faces of the star, joined when they share an edge through v.
      parent.resize(m);
      for (int i = 0; i < m; ++i) parent[i] = i;
      auto find = [&](int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      ends.clear();
      for (int i = 0; i < m; ++i)
        for (int w : mesh.triangles[star[first[v] + i]])
          if (w != v) ends.emplace_back(w, i);
      if (m <= 16) {  // a scan's valence is about 6: pairs are cheaper than a sort
        for (std::size_t e = 1; e < ends.size(); ++e)
          for (std::size_t f = 0; f < e; ++f)
            if (ends[e].first == ends[f].first) parent[find(ends[e].second)] = find(ends[f].second);
      } else {
        std::sort(ends.begin(), ends.end());
        for (std::size_t e = 1; e < ends.size(); ++e)
          if (ends[e].first == ends[e - 1].first)
            parent[find(ends[e].second)] = find(ends[e - 1].second);
      }
      const int root = find(0);
      for (int i = 1; i < m; ++i)
        if (find(i) != root) vertex_manifold = false;
    }
  }
  r.closed = r.boundary_edges == 0 && !mesh.triangles.empty();
  r.manifold = r.nonmanifold_edges == 0 && vertex_manifold;
  r.oriented = oriented && r.manifold;
  r.volume = signed_volume(mesh);
  return r;
}

void flip_orientation(Mesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

void append_mesh(Mesh& mesh, const Mesh& other) {
  const int n = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) mesh.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
}

std::vector<int> lexicographic_rank(const std::vector<Vec3>& points) {
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec3& p = points[a];
    const Vec3& q = points[b];
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  });
  std::vector<int> rank(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = static_cast<int>(i);
  return rank;
}

void canonicalize(Mesh& mesh) {
  const std::vector<int> rank = lexicographic_rank(mesh.vertices);
  std::vector<Vec3> vertices(mesh.vertices.size());
  for (std::size_t i = 0; i < rank.size(); ++i) vertices[rank[i]] = mesh.vertices[i];
  for (auto& t : mesh.triangles) {
    for (int& k : t) k = rank[k];
    // Rotate (keeps orientation) so the smallest index comes first.
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  mesh.vertices = std::move(vertices);
}

void transform(Mesh& mesh, const Mat3& rotation, const Vec3& translation) {
  for (auto& p : mesh.vertices) p = rotation * p + translation;
}

std::array<Vec3, 2> bounding_box(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const auto& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

std::vector<EdgeUse> edge_uses(const Mesh& mesh) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<std::size_t> start(nv + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<EdgeUse> uses(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      uses[next[std::min(a, b)]++] = {(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b),
                                      static_cast<int>(f)};
    }
  auto less = [](const EdgeUse& x, const EdgeUse& y) {
    return x.key < y.key || (x.key == y.key && x.face < y.face);
  };
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(uses.begin() + start[v], uses.begin() + start[v + 1], less);
  return uses;
}

}  // namespace clumpkit
