#include "geom/volume/union_of_balls.h"

#include "geom/errors.h"
#include "geom/sphere.h"
#include "geom/volume/ball_piece.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <utility>
#include <vector>

namespace clumpkit {
namespace {

using detail::ball_piece;
using detail::HalfSpace;
using detail::Piece;
using detail::Scratch;
constexpr int kChunk = 1 << 18;  // balls owned by one chunk of the power diagram

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb =
    CGAL::Triangulation_vertex_base_with_info_3<int, K,
                                                CGAL::Regular_triangulation_vertex_base_3<K>>;
using Cb = CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>,
                                                   CGAL::Discard_hidden_points>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using RegularTriangulation = CGAL::Regular_triangulation_3<K, Tds>;

// The interrupter of union_properties, asked by the chunks' threads one at a time with the
// fraction of the balls done; a stop asked once stops every chunk.
class Poll {
 public:
  Poll(const Interrupter& interrupter, std::size_t total)
      : interrupter_(interrupter), total_(total) {}
  void operator()(std::size_t done_now) {
    if (!interrupter_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ += done_now;
    if (stop_ || interrupted(interrupter_, "union", double(done_) / double(total_))) {
      stop_ = true;
      throw Interrupted("union_properties: interrupted");
    }
  }

 private:
  const Interrupter& interrupter_;
  const std::size_t total_;
  std::mutex mutex_;
  std::size_t done_ = 0;
  bool stop_ = false;
};

// A chunk's power-diagram neighbourhoods: the vertices of its regular triangulation, renumbered
// in the triangulation's own order, and the cells (or edges) around each owned vertex.
struct ChunkGraph {
  int own = 0;                // the owned balls are local[0 .. own)
  std::vector<int> local_of;  // the index into `local` of each vertex
  std::vector<Sphere> ball;   // the vertices' balls, in vertex order
  std::vector<int> index;     // and their indices into `balls`
  std::vector<std::array<int, 4>> cells;
  std::vector<std::pair<int, int>> edges;
  bool solid = false;            // dimension 3: neighbours from the cells, else the edges
  std::vector<std::size_t> row;  // row[id] .. row[id + 1]: the cells (or edges) of owned vertex id
  std::vector<int> incident;

  // Whether vertex id is one of the balls the chunk owns.
  bool is_owned(int id) const { return local_of[id] < own; }
  // The number of finite vertices.
  int vertices() const { return static_cast<int>(local_of.size()); }

  // Lists, for each owned vertex, the items (cells or edges) it is a vertex of: counted, then
  // placed.
  template <class Items, class VerticesOf>
  void place(const Items& items, VerticesOf&& vertices_of) {
    const int nv = vertices();
    row.assign(nv + 1, 0);
    for (const auto& item : items)
      for (const int v : vertices_of(item))
        if (is_owned(v)) ++row[v + 1];
    for (int id = 0; id < nv; ++id) row[id + 1] += row[id];
    incident.resize(row[nv]);
    std::vector<std::size_t> next(row.begin(), row.end() - 1);
    for (std::size_t c = 0; c < items.size(); ++c)
      for (const int v : vertices_of(items[c]))
        if (is_owned(v)) incident[next[v]++] = static_cast<int>(c);
  }
};

// Regular triangulation of the weighted centres (weight r²) of the balls `local` (indices into
// `balls`); info = index into `local`.
void triangulate(const std::vector<Sphere>& s, const std::vector<int>& balls,
                 const std::vector<int>& local, RegularTriangulation& rt) {
  const int n = static_cast<int>(local.size());
  std::vector<std::pair<K::Weighted_point_3, int>> points;
  points.reserve(n);
  for (int k = 0; k < n; ++k) {
    const Sphere& b = s[balls[local[k]]];
    points.emplace_back(K::Weighted_point_3(K::Point_3(b.center.x(), b.center.y(), b.center.z()),
                                            b.radius * b.radius),
                        k);
  }
  rt.insert(points.begin(), points.end());
  std::vector<std::pair<K::Weighted_point_3, int>>().swap(points);
}

// The neighbourhoods of the chunk's `owned` balls (the first of `local`) from its regular
// triangulation `rt`, which is cleared.
ChunkGraph chunk_graph(RegularTriangulation& rt, const std::vector<Sphere>& s,
                       const std::vector<int>& balls, const std::vector<int>& local,
                       std::size_t owned) {
  ChunkGraph g;
  // Power-diagram neighbours of the owned balls = edges of the regular triangulation (any
  // dimension 0–3). The vertices are renumbered in the triangulation's own order (spatially
  // sorted on insertion), and the owned balls are visited in that order: their cells and
  // neighbours then lie close together in memory (visited in slab order, two loads in three missed
  // the cache). `local_of[id]` is the index into `local` of vertex `id`.
  g.own = static_cast<int>(owned);
  g.local_of.reserve(local.size());
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) {
    g.local_of.push_back(v->info());
    v->info() = static_cast<int>(g.local_of.size()) - 1;
  }
  const int nv = g.vertices();
  g.ball.resize(nv);
  g.index.resize(nv);
  for (int id = 0; id < nv; ++id) {
    g.index[id] = local[g.local_of[id]];
    g.ball[id] = s[balls[g.index[id]]];
  }
  // Neighbours from the cells (dimension 3) or the edges (lower dimensions): the cells' vertices
  // are read once into a flat array and each owned vertex gets the list of its cells (counted,
  // then placed); its neighbours are the other vertices of those cells, each kept once (a
  // stamp per vertex). One sort of every edge of the chunk cost more than the triangulation. In
  // dimension 3 every finite edge lies on a finite cell, and the six edges of each cell are much
  // faster to collect than CGAL's edge iterator.
  g.solid = rt.dimension() == 3;
  if (g.solid) {
    g.cells.reserve(rt.number_of_finite_cells());
    for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c)
      g.cells.push_back(
          {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  } else {
    for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e) {
      const int a = e->first->vertex(e->second)->info();
      const int b = e->first->vertex(e->third)->info();
      g.edges.emplace_back(a, b);
    }
  }
  rt.clear();
  if (g.solid)
    g.place(g.cells, [](const std::array<int, 4>& c) { return c; });
  else
    g.place(g.edges, [](const std::pair<int, int>& e) {
      return std::array<int, 2>{e.first, e.second};
    });
  return g;
}

// The half-spaces of owned vertex id's power cell, one per neighbour in index order; `seen` is
// the stamp per vertex, `neighbours` a work array.
void power_planes(const ChunkGraph& g, int id, std::vector<int>& seen,
                  std::vector<std::pair<int, int>>& neighbours, std::vector<HalfSpace>& planes) {
  // Each neighbour once, in index order (the half-spaces' order, so a ball's piece does not
  // depend on the chunking).
  neighbours.clear();
  seen[id] = id;
  auto add = [&](int b) {
    if (seen[b] != id) neighbours.push_back({g.index[b], b});
    seen[b] = id;
  };
  for (std::size_t r = g.row[id]; r < g.row[id + 1]; ++r) {
    if (g.solid)
      for (const int b : g.cells[g.incident[r]]) add(b);
    else
      add(g.edges[g.incident[r]].first), add(g.edges[g.incident[r]].second);
  }
  std::sort(neighbours.begin(), neighbours.end());
  const Sphere& bi = g.ball[id];
  planes.clear();
  for (const auto& [j, b] : neighbours) {
    const Sphere& bj = g.ball[b];
    const Vec3 dv = bj.center - bi.center;
    const double d2 = dv.squaredNorm();
    const double dist = std::sqrt(d2);
    planes.push_back(
        {dv / dist, (d2 + (bi.radius - bj.radius) * (bi.radius + bj.radius)) / (2.0 * dist)});
  }
}

// The pieces of the balls owned by one chunk (`owned`, indices into `balls`), from the regular
// triangulation of `local` (owned first, then the halo; indices into `balls`). Pieces of other
// balls are not touched.
void chunk_pieces(const std::vector<Sphere>& s, const std::vector<int>& balls,
                  const std::vector<int>& local, std::size_t owned, std::vector<Piece>& pieces,
                  Poll& poll) {
  RegularTriangulation rt;
  triangulate(s, balls, local, rt);
  poll(0);
  const ChunkGraph g = chunk_graph(rt, s, balls, local, owned);
  const int nv = g.vertices();

  // Owned balls that are no vertex are hidden: their pieces are empty.
  std::vector<char> is_vertex(owned, 0);
  for (int id = 0; id < nv; ++id)
    if (g.is_owned(id)) is_vertex[g.local_of[id]] = 1;
  for (std::size_t k = 0; k < owned; ++k)
    if (!is_vertex[k]) pieces[local[k]].empty = true;

  Scratch scratch;
  std::vector<int> seen(nv, -1);
  std::vector<std::pair<int, int>> neighbours;  // (index into `balls`, vertex id)
  std::vector<HalfSpace> planes;
  constexpr std::size_t kPollEvery = 1 << 12;
  std::size_t since_poll = owned - std::count(is_vertex.begin(), is_vertex.end(), char(1));
  for (int id = 0; id < nv; ++id) {
    if (!g.is_owned(id)) continue;
    if (++since_poll >= kPollEvery) poll(std::exchange(since_poll, 0));
    power_planes(g, id, seen, neighbours, planes);
    pieces[g.index[id]] = ball_piece(g.ball[id].radius, planes, scratch);
  }
  poll(since_poll);
}

}  // namespace

UnionProperties union_properties(const Clump& clump, const Interrupter& interrupter) {
  return union_properties_in_chunks(clump, kChunk, interrupter);
}

UnionProperties union_properties_in_chunks(const Clump& clump, int chunk,
                                           const Interrupter& interrupter) {
  if (chunk < 1) throw InvalidInput("union_properties: chunk size must be positive");
  validate(clump);
  const std::vector<Sphere>& s = clump.spheres;
  const std::vector<int> balls = distinct_balls(s);
  const int n = static_cast<int>(balls.size());

  // The power diagram in chunks: slabs of consecutive balls along the longest axis of the centres'
  // box, each triangulated with a halo of every ball within 2·r_max of the slab. Exact: a ball
  // j restricts the piece B_i ∩ PowerCell_i only where pow_j < pow_i ≤ 0, i.e. inside B_j ∩ B_i,
  // so the balls that overlap B_i (all in its slab's halo) give the same piece as all balls, and
  // a half-space of a ball that is a power neighbour only in the halo's diagram leaves the piece
  // (and the clipping of its other faces) unchanged. Chunks run in parallel, each with a
  // triangulation a fraction of the size, which bounds the memory.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double r_max = 0.0;
  for (const int b : balls) {
    lo = lo.cwiseMin(s[b].center);
    hi = hi.cwiseMax(s[b].center);
    r_max = std::max(r_max, s[b].radius);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int k) { return s[balls[k]].center[axis]; };
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
    return key(a) < key(b) || (key(a) == key(b) && a < b);  // a total order: one result
  });
  const int chunks = std::max(1, (n + chunk - 1) / chunk);
  std::vector<Piece> pieces(n);
  Poll poll(interrupter, static_cast<std::size_t>(n));
  tbb::parallel_for(tbb::blocked_range<int>(0, chunks, 1), [&](const tbb::blocked_range<int>& r) {
    for (int c = r.begin(); c != r.end(); ++c) {
      const int first = static_cast<int>(static_cast<long long>(n) * c / chunks);
      const int last = static_cast<int>(static_cast<long long>(n) * (c + 1) / chunks);
      // The halo: sorted neighbours on either side within 2·r_max (with a margin for rounding).
      const double margin = 2.0 * r_max * (1.0 + 1e-9) + 1e-12 * (hi - lo).norm();
      const double from = key(order[first]) - margin, to = key(order[last - 1]) + margin;
      std::vector<int> local(order.begin() + first, order.begin() + last);
      for (int k = first - 1; k >= 0 && key(order[k]) >= from; --k) local.push_back(order[k]);
      for (int k = last; k < n && key(order[k]) <= to; ++k) local.push_back(order[k]);
      chunk_pieces(s, balls, local, static_cast<std::size_t>(last - first), pieces, poll);
    }
  });

  // Sum in index order (deterministic), then shift the second moments to the centroid.
  UnionProperties out;
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  int contributing = 0;
  for (int k = 0; k < n; ++k) {
    const Piece& p = pieces[k];
    if (p.empty) continue;
    const double r = s[balls[k]].radius;
    if (p.volume > 1e-13 * (4.0 / 3.0 * kPi * r * r * r)) ++contributing;
    volume += p.volume;
    first += p.volume * s[balls[k]].center + p.first;
    out.area += p.area;
  }
  if (!(volume > 0.0) || !std::isfinite(volume) || !first.allFinite())
    throw NumericError("union_properties: union volume is not positive and finite");
  const Vec3 g = first / volume;
  Mat3 second = Mat3::Zero();
  for (int k = 0; k < n; ++k) {
    const Piece& p = pieces[k];
    if (p.empty) continue;
    const Vec3 dc = s[balls[k]].center - g;
    second += p.volume * dc * dc.transpose() + dc * p.first.transpose() + p.first * dc.transpose() +
              p.second;
  }
  out.mass.volume = volume;
  out.mass.centroid = g;
  out.mass.inertia = second.trace() * Mat3::Identity() - second;
  out.hidden = static_cast<int>(s.size()) - contributing;
  return out;
}

double union_bytes_estimate(const Clump& clump) {
  // 64 MiB for the program, 200 bytes per ball for the input, order and pieces, and 1,100 per
  // ball in each triangulation alive at once (a chunk with its halo, one per thread).
  const double n = double(clump.spheres.size());
  const double chunk = 1.35 * double(kChunk);
  const double at_once =
      std::min(std::ceil(n / double(kChunk)), double(tbb::this_task_arena::max_concurrency()));
  return 64.0 * 1048576.0 + 200.0 * n + 1100.0 * std::min(n, chunk * std::max(1.0, at_once));
}

double whole_triangulation_bytes_estimate(const Clump& clump) {
  return 64.0 * 1048576.0 + 1500.0 * double(clump.spheres.size());
}

}  // namespace clumpkit
