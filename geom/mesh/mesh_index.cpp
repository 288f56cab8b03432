#include "geom/mesh/mesh_index.h"

#include "geom/errors.h"
#include "geom/mesh/embree_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace clumpkit {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;  // vertex region a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;  // edge ab
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);  // edge bc
  const double denom = 1.0 / (va + vb + vc);                     // face region
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct MeshIndex::Impl {
  std::unique_ptr<EmbreeScene> embree;
  Vec3 shift = Vec3::Zero();  // Embree works in float: coordinates relative to the box centre
  double x_start = 0.0;       // rays along x start here, outside the mesh
  double slack = 0.0;         // absolute float slack of the culling radius
  // The triangles around each vertex (CSR: ring[ring_start[v] .. ring_start[v + 1]]).
  std::vector<int> ring_start, ring;
};

namespace {

struct Query {
  const Mesh* mesh;
  Vec3 p;          // query point, world coordinates
  double best_d2;  // squared distance to the closest triangle so far
  double slack;
  int best = -1;  // that triangle
};

// Embree calls this for every triangle whose BVH box meets the query ball; shrinking the ball to
// the best distance so far prunes the rest. The ball is kept a little larger than the double
// distance, since Embree's boxes are of the float vertices.
bool closest_triangle(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<Query*>(args->userPtr);
  const auto& t = q->mesh->triangles[args->primID];
  const auto& v = q->mesh->vertices;
  const double d2 =
      (closest_point_on_triangle(q->p, v[t[0]], v[t[1]], v[t[2]]) - q->p).squaredNorm();
  if (d2 > q->best_d2 || (d2 == q->best_d2 && q->best >= 0 && int(args->primID) > q->best))
    return false;  // ties go to the lower index, whatever order the BVH visits them in
  q->best_d2 = d2;
  q->best = static_cast<int>(args->primID);
  args->query->radius = static_cast<float>(std::sqrt(d2) * (1.0 + 1e-6) + q->slack);
  return true;
}

}  // namespace

MeshIndex::MeshIndex(const Mesh& mesh) : mesh_(mesh), impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (mesh.triangles.empty()) throw InvalidInput("the mesh has no triangles");
  const auto bb = bounding_box(mesh);
  m.shift = 0.5 * (bb[0] + bb[1]);
  const double extent = (bb[1] - bb[0]).maxCoeff();
  m.x_start = bb[0].x() - 0.5 * extent - 1.0;
  // Float vertices are off by ~6e-8 of the coordinates' size: ten times that covers it.
  m.slack = 1e-6 * (extent + (bb[1] - m.shift).cwiseAbs().maxCoeff());
  m.embree = std::make_unique<EmbreeScene>(mesh, m.shift, true);
  m.ring_start.assign(mesh.vertices.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++m.ring_start[t[k] + 1];
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) m.ring_start[v + 1] += m.ring_start[v];
  m.ring.resize(m.ring_start.back());
  std::vector<int> fill(m.ring_start.begin(), m.ring_start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) m.ring[fill[mesh.triangles[t][k]]++] = static_cast<int>(t);
}

MeshIndex::~MeshIndex() = default;

double MeshIndex::distance(const Vec3& p) const {
  return nearest(p, std::numeric_limits<double>::infinity()).distance;
}

double MeshIndex::distance(const Vec3& p, double limit) const {
  return nearest(p, limit).distance;
}

double MeshIndex::distance_to_triangle(const Vec3& p, int t) const {
  const auto& tri = mesh_.triangles[t];
  const auto& v = mesh_.vertices;
  return (closest_point_on_triangle(p, v[tri[0]], v[tri[1]], v[tri[2]]) - p).norm();
}

MeshIndex::Nearest MeshIndex::nearest(const Vec3& p, double limit) const {
  const Impl& m = *impl_;
  Query q{&mesh_, p, limit * limit, m.slack};
  RTCPointQuery pq;
  const Vec3 o = p - m.shift;
  pq.x = static_cast<float>(o.x());
  pq.y = static_cast<float>(o.y());
  pq.z = static_cast<float>(o.z());
  pq.time = 0.0f;
  pq.radius = std::isfinite(limit) ? static_cast<float>(limit * (1.0 + 1e-6) + m.slack)
                                   : std::numeric_limits<float>::infinity();
  RTCPointQueryContext ctx;
  rtcInitPointQueryContext(&ctx);
  rtcPointQuery(m.embree->scene, &pq, &ctx, closest_triangle, &q);
  if (q.best < 0) return Nearest{limit, -1};
  return Nearest{std::sqrt(q.best_d2), q.best};
}

MeshIndex::Nearest MeshIndex::descend(const Vec3& p, Nearest start) const {
  const Impl& m = *impl_;
  if (start.triangle < 0) return start;
  // Each move strictly lowers (distance, index), so the walk ends; the guard only bounds it.
  // Each triangle is measured once a step, and the ring of a vertex the previous triangle had
  // is skipped: all of it was measured then and none beat where the walk now stands.
  std::array<int, 3> previous{-1, -1, -1};
  for (std::size_t guard = 0; guard < mesh_.triangles.size(); ++guard) {
    const Nearest here = start;
    const std::array<int, 3> corners = mesh_.triangles[here.triangle];
    for (int k = 0; k < 3; ++k) {
      const int v = corners[k];
      if (v == previous[0] || v == previous[1] || v == previous[2]) continue;
      for (int r = m.ring_start[v]; r < m.ring_start[v + 1]; ++r) {
        const int t = m.ring[r];
        if (t == start.triangle) continue;
        const auto& u = mesh_.triangles[t];
        bool measured = false;  // in the ring of an earlier corner
        for (int j = 0; j < k; ++j)
          measured |= u[0] == corners[j] || u[1] == corners[j] || u[2] == corners[j];
        if (measured) continue;
        const double d = distance_to_triangle(p, t);
        if (d < start.distance || (d == start.distance && t < start.triangle)) start = {d, t};
      }
    }
    if (start.triangle == here.triangle) break;
    previous = corners;
  }
  return start;
}

std::vector<MeshIndex::Crossing> MeshIndex::crossings_x(double y, double z) const {
  const Impl& m = *impl_;
  std::vector<Crossing> xs;
  const float ox = static_cast<float>(m.x_start - m.shift.x());
  const float origin[3] = {ox, static_cast<float>(y - m.shift.y()),
                           static_cast<float>(z - m.shift.z())};
  const float dir[3] = {1.0f, 0.0f, 0.0f};
  float tnear = 0.0f;
  for (int guard = 0; guard < 1000000; ++guard) {
    const RayHit hit = first_hit(m.embree->scene, origin, dir, tnear);
    if (hit.triangle < 0) break;
    xs.push_back(
        Crossing{m.shift.x() + static_cast<double>(ox) + static_cast<double>(hit.t), hit.triangle});
    tnear = step_past(hit.t);
  }
  return xs;
}

std::vector<MeshIndex::Crossing> MeshIndex::even_crossings_x(double y, double z,
                                                             double nudge) const {
  auto xs = crossings_x(y, z);
  for (int attempt = 1; xs.size() % 2 == 1 && attempt <= 3; ++attempt)
    xs = crossings_x(y + nudge * std::fmod(0.6180339887 * attempt, 1.0),
                     z + nudge * std::fmod(0.7548776662 * attempt, 1.0));
  return xs;
}

}  // namespace clumpkit
