#include "geom/descriptors/farthest_pair.h"

#include <algorithm>
#include <numeric>

namespace clumpkit {

namespace {

constexpr std::size_t kLeaf = 32;

struct Node {
  Vec3 lo, hi;
  std::size_t begin = 0, end = 0;  // range of `order`
  int left = -1, right = -1;       // children; -1 for a leaf
};

struct Tree {
  const std::vector<Vec3>& pts;
  std::vector<std::size_t> order;
  std::vector<Node> nodes;

  int build(std::size_t begin, std::size_t end) {
    Node node;
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = pts[order[begin]];
    for (std::size_t k = begin + 1; k < end; ++k) {
      node.lo = node.lo.cwiseMin(pts[order[k]]);
      node.hi = node.hi.cwiseMax(pts[order[k]]);
    }
    const int id = int(nodes.size());
    nodes.push_back(node);
    if (end - begin > kLeaf) {
      int axis;
      (node.hi - node.lo).maxCoeff(&axis);
      const std::size_t mid = begin + (end - begin) / 2;
      // Ties broken by index, so the tree (and nothing else: the answer never depends on it)
      // is the same on every machine.
      std::nth_element(order.begin() + long(begin), order.begin() + long(mid),
                       order.begin() + long(end), [&](std::size_t a, std::size_t b) {
                         return pts[a][axis] < pts[b][axis] ||
                                (pts[a][axis] == pts[b][axis] && a < b);
                       });
      const int left = build(begin, mid);
      const int right = build(mid, end);
      nodes[std::size_t(id)].left = left;
      nodes[std::size_t(id)].right = right;
    }
    return id;
  }
};

// Largest squared distance between two boxes: an upper bound of every pair they hold. The box
// corners are coordinates of the points and rounding is monotone, so it bounds the computed
// distances as well up to the order of the three additions (the margin below covers that).
double max_squared_distance(const Node& a, const Node& b) {
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max(a.hi[k] - b.lo[k], b.hi[k] - a.lo[k]);
    s += d * d;
  }
  return s;
}

struct Search {
  const Tree& tree;
  FarthestPair best;

  void offer(std::size_t a, std::size_t b) {
    const std::size_t i = std::min(a, b), j = std::max(a, b);
    const double d2 = (tree.pts[j] - tree.pts[i]).squaredNorm();
    if (d2 > best.squared_distance ||
        (d2 == best.squared_distance && (i < best.i || (i == best.i && j < best.j))))
      best = {i, j, d2};
  }

  void visit(int ia, int ib) {
    const Node& a = tree.nodes[std::size_t(ia)];
    const Node& b = tree.nodes[std::size_t(ib)];
    if (max_squared_distance(a, b) * (1.0 + 1e-9) < best.squared_distance) return;
    const bool a_leaf = a.left < 0, b_leaf = b.left < 0;
    if (a_leaf && b_leaf) {
      for (std::size_t p = a.begin; p < a.end; ++p)
        for (std::size_t q = ia == ib ? p + 1 : b.begin; q < b.end; ++q)
          offer(tree.order[p], tree.order[q]);
    } else if (ia == ib) {
      visit(a.left, a.left);
      visit(a.left, a.right);
      visit(a.right, a.right);
    } else if (b_leaf || (!a_leaf && a.end - a.begin >= b.end - b.begin)) {
      visit(a.left, ib);
      visit(a.right, ib);
    } else {
      visit(ia, b.left);
      visit(ia, b.right);
    }
  }
};

}  // namespace

FarthestPair farthest_pair(const std::vector<Vec3>& pts) {
  const std::size_t n = pts.size();
  if (n < 2) return {};
  Tree tree{pts, std::vector<std::size_t>(n), {}};
  std::iota(tree.order.begin(), tree.order.end(), std::size_t(0));
  tree.nodes.reserve(4 * (n / kLeaf + 1));
  tree.build(0, n);
  Search search{tree, {}};
  search.best = {0, 1, (pts[1] - pts[0]).squaredNorm()};
  // A good first bound prunes most boxes: walk to the farthest point a few times (each step
  // cannot shorten the pair).
  std::size_t from = 0;
  for (int round = 0; round < 4; ++round) {
    std::size_t far = from;
    double far_d2 = -1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double d2 = (pts[k] - pts[from]).squaredNorm();
      if (d2 > far_d2) far_d2 = d2, far = k;
    }
    if (far != from) search.offer(from, far);
    from = far;
  }
  search.visit(0, 0);
  if (!(search.best.squared_distance > 0.0)) return {};  // as the double loop: no pair is farther
  return search.best;
}

}  // namespace clumpkit
