#include "geom/fill/distance_field.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/mesh_index.h"
#include "geom/mesh/ray_inside.h"

#include <tbb/parallel_for.h>

#include <openvdb/openvdb.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>

namespace clumpkit {

namespace {
void init_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}
}  // namespace

double DistanceField::sample(const Vec3& p) const {
  const Vec3 g = (p - origin) / h;
  const int i0 = static_cast<int>(std::floor(g.x())), j0 = static_cast<int>(std::floor(g.y())),
            k0 = static_cast<int>(std::floor(g.z()));
  if (i0 < 0 || j0 < 0 || k0 < 0 || i0 + 1 >= dims[0] || j0 + 1 >= dims[1] || k0 + 1 >= dims[2])
    return -h;
  const double fx = g.x() - i0, fy = g.y() - j0, fz = g.z() - k0;
  double v = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * (dz ? fz : 1 - fz);
    v += w * at(i0 + dx, j0 + dy, k0 + dz);
  }
  return v;
}

double feature_distance(const DistanceField& f, const Mesh& mesh, const Vec3& p) {
  const Vec3 g = (p - f.origin) / f.h;
  const int i0 = static_cast<int>(std::lround(g.x())), j0 = static_cast<int>(std::lround(g.y())),
            k0 = static_cast<int>(std::lround(g.z()));
  double best = std::numeric_limits<double>::infinity();
  int seen[27];
  int n = 0;
  for (int k = std::max(0, k0 - 1); k <= std::min(f.dims[2] - 1, k0 + 1); ++k)
    for (int j = std::max(0, j0 - 1); j <= std::min(f.dims[1] - 1, j0 + 1); ++j)
      for (int i = std::max(0, i0 - 1); i <= std::min(f.dims[0] - 1, i0 + 1); ++i) {
        const int t = f.feature[f.index(i, j, k)];
        if (t < 0 || std::find(seen, seen + n, t) != seen + n) continue;
        seen[n++] = t;
        const auto& tri = mesh.triangles[t];
        const auto& v = mesh.vertices;
        best = std::min(best,
                        (closest_point_on_triangle(p, v[tri[0]], v[tri[1]], v[tri[2]]) - p).norm());
      }
  return n ? best : std::abs(f.sample(p));
}

namespace {

// Grid dimensions: voxel centres from about two voxels below the box to two above.
std::array<int, 3> field_dims(const std::array<Vec3, 2>& bb, double h) {
  std::array<int, 3> dims{};
  for (int k = 0; k < 3; ++k) {
    const double n = std::ceil((bb[1][k] - bb[0][k]) / h) + 5;
    if (!(n < 2e9))
      throw InvalidInput("distance field would have " + format_number(n) +
                         " voxels along one axis: use fewer --voxels or a larger voxel size");
    dims[k] = static_cast<int>(n);
  }
  return dims;
}

double product(const std::array<int, 3>& d) {
  return double(d[0]) * d[1] * d[2];
}

// The smallest voxel whose grid over the mesh's box holds at most `budget` voxels.
double budget_voxel(const Mesh& mesh, double h, double budget) {
  const auto bb = bounding_box(mesh);
  const double box = (bb[1] - bb[0]).prod();
  for (int k = 0; k < 100 && product(field_dims(bb, h)) > budget; ++k)
    h = std::max(1.05 * h, std::cbrt(box / budget));
  return h;
}

}  // namespace

// The voxel of the options before the sphere budget's (FieldOptions::count_voxel) is applied.
double distance_voxel_size(const Mesh& mesh, const FieldOptions& o) {
  if (o.voxel_size > 0.0) {
    if (!std::isfinite(o.voxel_size))
      throw InvalidInput("voxel size must be finite, got " + std::to_string(o.voxel_size));
    return o.voxel_size;
  }
  require(kFieldVoxels, o.voxels, "--voxels");
  if (o.vote_sign) {
    // A mesh with holes has no reliable volume, hence no inertia axes: use the box instead.
    const auto bb = bounding_box(mesh);
    return (bb[1] - bb[0]).minCoeff() / o.voxels;
  }
  const PrincipalFrame f = principal_frame(mesh);
  double h = f.extents[0] / o.voxels;
  // The default resolution's budget: a platy or elongated shape gets coarser voxels rather
  // than hundreds of times the work of a compact one (a 1:20 plate at 40 voxels across its
  // thickness is 26e6 voxels); compact shapes stay far below it.
  if (o.max_voxels > 0) h = budget_voxel(mesh, h, o.max_voxels);
  return h;
}

double field_voxel_size(const Mesh& mesh, const FieldOptions& o) {
  const double h = distance_voxel_size(mesh, o);
  if (!(o.count_voxel > 0.0) || !(o.count_voxel < h)) return h;
  if (!std::isfinite(o.count_voxel))
    throw InvalidInput("count voxel must be finite, got " + std::to_string(o.count_voxel));
  const double fine = std::max(o.count_voxel, h / std::cbrt(kCountVoxelGrowth));
  return std::min(h, budget_voxel(mesh, fine, o.max_voxels > 0 ? o.max_voxels : kDefaultMaxVoxels));
}

double field_voxel_count(const Mesh& mesh, const FieldOptions& options) {
  return product(field_dims(bounding_box(mesh), field_voxel_size(mesh, options)));
}

namespace {

double bytes_estimate(double voxels, std::size_t triangles) {
  return 64.0 * 1048576.0 + 19.0 * voxels + 200.0 * double(triangles);
}

}  // namespace

double fill_bytes_estimate(const Mesh& mesh, const FieldOptions& options) {
  return bytes_estimate(field_voxel_count(mesh, options), mesh.triangles.size());
}

DistanceField make_distance_field(const Mesh& mesh, const FieldOptions& options) {
  const MeshIndex index(mesh);
  return make_distance_field(index, options);
}

namespace {

// Inside/outside of every voxel centre from the surface crossings of the grid's rows along x:
// one ray per row instead of one per voxel, so the cost is rows × log(triangles). A row whose
// crossings are odd in number grazed the surface (an edge, a tangent point, a face's plane): it
// is cast again a hair off the voxel centres, which decides those centres the same way unless
// they lie within 1e-4 voxel of the surface, and if still odd its voxels are decided by a 7-ray
// vote each. The two voxels either side of a crossing get the crossed triangle
// in `hint` (when given): its distance bounds their nearest-triangle search.
std::vector<std::uint8_t> inside_by_rows(const MeshIndex& index, const DistanceField& f,
                                         std::vector<std::int32_t>* hint) {
  std::vector<std::uint8_t> in(static_cast<std::size_t>(product(f.dims)), 0);
  // Rows still odd after three nudges (one running in a face's plane) are decided voxel by
  // voxel by a 7-ray vote afterwards; one flag per row, so no thread writes another's.
  std::vector<std::uint8_t> odd(std::size_t(f.dims[1]) * f.dims[2], 0);
  tbb::parallel_for(0, f.dims[2], [&](int k) {
    for (int j = 0; j < f.dims[1]; ++j) {
      const Vec3 c = f.position(0, j, k);
      const auto xs = index.even_crossings_x(c.y(), c.z(), 1e-4 * f.h);
      if (xs.size() % 2 == 1) {
        odd[std::size_t(k) * f.dims[1] + j] = 1;
        continue;
      }
      for (std::size_t q = 0; q < xs.size(); q += 2) {
        const int i0 = std::max(0, int(std::ceil((xs[q].x - f.origin.x()) / f.h)));
        const int i1 = std::min(f.dims[0] - 1, int(std::floor((xs[q + 1].x - f.origin.x()) / f.h)));
        for (int i = i0; i <= i1; ++i) in[f.index(i, j, k)] = 1;
      }
      if (hint)
        for (const auto& x : xs) {
          const int i = int(std::floor((x.x - f.origin.x()) / f.h));
          if (i >= 0 && i < f.dims[0]) (*hint)[f.index(i, j, k)] = x.triangle;
          if (i + 1 >= 0 && i + 1 < f.dims[0]) (*hint)[f.index(i + 1, j, k)] = x.triangle;
        }
    }
  });
  if (std::find(odd.begin(), odd.end(), 1) != odd.end()) {
    const RayInside rays(index.mesh());
    tbb::parallel_for(0, f.dims[2], [&](int k) {
      for (int j = 0; j < f.dims[1]; ++j)
        if (odd[std::size_t(k) * f.dims[1] + j])
          for (int i = 0; i < f.dims[0]; ++i)
            in[f.index(i, j, k)] = rays.inside(f.position(i, j, k));
    });
  }
  return in;
}

// Layers of the band around the surface voxels.
constexpr int kBand = 2;

// The field's lattice at voxel h (origin, dims), with its distance and feature arrays allocated
// when `distances`; throws before allocating when it is too large or over options.max_bytes.
DistanceField empty_field(const Mesh& mesh, const FieldOptions& options, double h, bool distances) {
  init_openvdb();
  const auto bb = bounding_box(mesh);
  DistanceField f;
  f.h = h;
  // Voxel centres on the lattice origin + h·(i, j, k), about two voxels beyond the box on each
  // side. The half-voxel offset keeps axis-aligned faces (boxes!) off the voxel centres, where
  // a centre at distance 0 would drop a whole layer of cells from the interior count.
  const Vec3 lo = bb[0] - 1.5 * h * Vec3::Ones();
  f.dims = field_dims(bb, h);
  const double total = product(f.dims);
  if (total > 2e9)
    throw InvalidInput("distance field would have " + format_number(total) +
                       " voxels (limit 2e9): use fewer --voxels or a larger voxel size");
  if (options.max_bytes > 0) {
    // From the size found above: the voxel size of a shape with two equal moments takes a 2-D
    // hull of every vertex (principal_frame), a tenth of a second on a scan.
    const double need = bytes_estimate(total, mesh.triangles.size());
    if (!(need <= options.max_bytes))
      throw InvalidInput("fill would need an estimated " + format_number(need / 1073741824.0, 3) +
                         " GiB (" + format_number(total) + " voxels of size " + format_number(h) +
                         ", " + std::to_string(mesh.triangles.size()) +
                         " triangles), more than --max-memory " +
                         format_number(options.max_bytes / 1073741824.0, 3) +
                         " GiB: use fewer --voxels or a larger voxel size");
  }
  f.origin = lo;

  if (distances) {
    f.d.assign(static_cast<std::size_t>(total), 0.0f);
    f.feature.assign(static_cast<std::size_t>(total), -1);
  }

  return f;
}

// 1. The inside flag of every voxel: ray parity along the rows (their hints left in
// f.feature until the surface voxels are found), or, for a mesh that is not closed, a vote of 7
// rays per voxel.
std::vector<std::uint8_t> inside_voxels(const MeshIndex& index, DistanceField& f,
                                        const FieldOptions& options) {
  const Mesh& mesh = index.mesh();
  std::vector<std::uint8_t> in;
  if (options.vote_sign) {
    in.assign(static_cast<std::size_t>(product(f.dims)), 0);
    const RayInside rays(mesh);
    tbb::parallel_for(0, f.dims[2], [&](int k) {
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) in[f.index(i, j, k)] = rays.inside(f.position(i, j, k));
    });
  } else {
    // f.feature, when kept, holds the rows' hints until step 2.
    in = inside_by_rows(index, f, f.feature.empty() ? nullptr : &f.feature);
  }

  return in;
}

// 2. The surface voxels (layer 0 of the returned layers, 255 elsewhere).
std::vector<std::uint8_t> surface_voxels(const MeshIndex& index, DistanceField& f,
                                         const std::vector<std::uint8_t>& in) {
  const Mesh& mesh = index.mesh();
  const double h = f.h;
  // each bounded as tightly as is known for certain, since the bound decides how many triangles
  // it visits: by h (the segment to that neighbour crosses the surface) and by the distance to
  // any triangle already known near it (the rows' hints, the voxels before it in its z slab; the
  // slabs run in parallel, and the result, the nearest triangle with ties to the lower index,
  // does not depend on the bound).
  // Triangles smaller than a voxel (by the mean edge, √(2·area/n) for a mesh of n triangles):
  // then a voxel's nearest triangle may be none of its neighbours', and walks over the surface
  // are worth their cost.
  const bool small_triangles = std::sqrt(2.0 * surface_area(mesh) / mesh.triangles.size()) < h;
  std::vector<std::uint8_t> layer(f.d.size(), 255);
  auto differs = [&](int i, int j, int k) {
    const std::uint8_t v = in[f.index(i, j, k)];
    return (i > 0 && in[f.index(i - 1, j, k)] != v) ||
           (i + 1 < f.dims[0] && in[f.index(i + 1, j, k)] != v) ||
           (j > 0 && in[f.index(i, j - 1, k)] != v) ||
           (j + 1 < f.dims[1] && in[f.index(i, j + 1, k)] != v) ||
           (k > 0 && in[f.index(i, j, k - 1)] != v) ||
           (k + 1 < f.dims[2] && in[f.index(i, j, k + 1)] != v);
  };
  tbb::parallel_for(0, f.dims[2], [&](int k) {
    for (int j = 0; j < f.dims[1]; ++j)
      for (int i = 0; i < f.dims[0]; ++i) {
        const std::int64_t q = f.index(i, j, k);
        if (!differs(i, j, k)) {
          f.feature[q] = -1;
          continue;
        }
        layer[q] = 0;
        const Vec3 p = f.position(i, j, k);
        MeshIndex::Nearest known{1.01 * h, -1};
        for (int b = std::max(0, j - 1); b <= std::min(f.dims[1] - 1, j + 1); ++b)
          for (int a = std::max(0, i - 1); a <= std::min(f.dims[0] - 1, i + 1); ++a) {
            const int t = f.feature[f.index(a, b, k)];
            if (t < 0) continue;
            const double d = index.distance_to_triangle(p, t);
            if (d < known.distance) known = {d, t};
          }
        // Where triangles are small, a descent from the best known one tightens the bound to
        // about the answer, so the search visits a handful of triangles instead of a voxel's
        // worth.
        if (known.triangle >= 0 && small_triangles) known = index.descend(p, known);
        auto n = index.nearest(p, known.distance * (1.0 + 1e-9) + 1e-12 * h);
        if (n.triangle < 0) n = index.nearest(p, std::numeric_limits<double>::infinity());
        f.feature[q] = n.triangle;
        f.d[q] = static_cast<float>(in[q] ? n.distance : -n.distance);
      }
  });

  return layer;
}

// The nearest of the triangles that the 26 neighbours of voxel (i, j, k) keep, among those
// neighbours `use` accepts: a feature transform, exact wherever the voxel's nearest triangle
// is one of them (all but where features compete), a few dozen point–triangle distances.
template <class Use>
MeshIndex::Nearest nearest_of_neighbours(const MeshIndex& index, const DistanceField& f, int i,
                                         int j, int k, Use&& use) {
  const Vec3 p = f.position(i, j, k);
  MeshIndex::Nearest best{std::numeric_limits<double>::infinity(), -1};
  // Neighbours mostly share a few triangles: each is measured once (the answer, the nearest
  // with ties to the lower index, does not depend on the order).
  int seen[27];
  int n_seen = 0;
  for (int c = std::max(0, k - 1); c <= std::min(f.dims[2] - 1, k + 1); ++c)
    for (int b = std::max(0, j - 1); b <= std::min(f.dims[1] - 1, j + 1); ++b)
      for (int a = std::max(0, i - 1); a <= std::min(f.dims[0] - 1, i + 1); ++a) {
        const std::int64_t n = f.index(a, b, c);
        const int t = f.feature[n];
        if (t < 0 || std::find(seen, seen + n_seen, t) != seen + n_seen || !use(n)) continue;
        seen[n_seen++] = t;
        const double d = index.distance_to_triangle(p, t);
        if (d < best.distance || (d == best.distance && t < best.triangle)) best = {d, t};
      }
  if (best.triangle < 0) best = index.nearest(p, std::numeric_limits<double>::infinity());
  return best;
}

// The band: kBand layers around the surface voxels, each from the layer before; voxels left out
// of it and outside get −(kBand + 1)·h.
void band_voxels(const MeshIndex& index, DistanceField& f, const std::vector<std::uint8_t>& in,
                 std::vector<std::uint8_t>& layer) {
  const double h = f.h;
  for (int L = 1; L <= kBand; ++L) {
    tbb::parallel_for(0, f.dims[2], [&](int k) {
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) {
          const std::int64_t q = f.index(i, j, k);
          if (layer[q] != 255) continue;
          bool next = false;
          for (int c = std::max(0, k - 1); c <= std::min(f.dims[2] - 1, k + 1) && !next; ++c)
            for (int b = std::max(0, j - 1); b <= std::min(f.dims[1] - 1, j + 1) && !next; ++b)
              for (int a = std::max(0, i - 1); a <= std::min(f.dims[0] - 1, i + 1); ++a)
                if (layer[f.index(a, b, c)] == L - 1) {
                  next = true;
                  break;
                }
          if (next) layer[q] = static_cast<std::uint8_t>(100 + L);  // marked, not yet done
        }
    });
    tbb::parallel_for(0, f.dims[2], [&](int k) {
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) {
          const std::int64_t q = f.index(i, j, k);
          if (layer[q] != 100 + L) continue;
          const auto n = nearest_of_neighbours(index, f, i, j, k,
                                               [&](std::int64_t m) { return layer[m] < L; });
          f.feature[q] = n.triangle;
          f.d[q] = static_cast<float>(in[q] ? n.distance : -n.distance);
        }
    });
    for (auto& v : layer)
      if (v == 100 + L) v = static_cast<std::uint8_t>(L);
  }
  // From here `layer[q] != 255` means voxel q has its feature: the band now, deep voxels later.
  for (std::size_t q = 0; q < layer.size(); ++q)
    if (layer[q] == 255 && !in[q]) f.d[q] = static_cast<float>(-(kBand + 1) * h);  // outside, far
}

// 3. The interior beyond the band.
void interior_voxels(const MeshIndex& index, DistanceField& f, const std::vector<std::uint8_t>& in,
                     std::vector<std::uint8_t>& layer) {
  const Mesh& mesh = index.mesh();
  const double h = f.h;
  // 3. The interior beyond the band. OpenVDB fast sweeping (first-order Eikonal, Zhao 2005)
  // from the band inwards gives every deep voxel an approximate depth (within about a voxel);
  // in that order, shallow first, each voxel then takes the nearest of the triangles its 26
  // neighbours keep (they are shallower, so they have theirs): a feature transform whose values
  // are exact distances to real triangles.
  init_openvdb();
  auto sdf = openvdb::FloatGrid::create(static_cast<float>((kBand + 1) * h));
  sdf->setTransform(openvdb::math::Transform::createLinearTransform(h));
  sdf->setGridClass(openvdb::GRID_LEVEL_SET);
  auto mask = openvdb::MaskGrid::create();
  mask->setTransform(sdf->transformPtr());
  std::vector<std::int64_t> deep;
  {
    auto acc = sdf->getAccessor();
    auto macc = mask->getAccessor();
    for (int k = 0; k < f.dims[2]; ++k)
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) {
          const std::int64_t q = f.index(i, j, k);
          if (layer[q] != 255) {
            acc.setValueOn(openvdb::Coord(i, j, k), -f.d[q]);  // OpenVDB: negative inside
          } else if (in[q]) {
            macc.setValueOn(openvdb::Coord(i, j, k));
            deep.push_back(q);
          }
        }
  }
  if (deep.empty()) return;
  // Inactive voxels inside the band take −background, so the sweep knows their side.
  openvdb::tools::signedFloodFill(sdf->tree());
  const auto swept = openvdb::tools::maskSdf(*sdf, *mask);
  {
    const auto acc = swept->getConstAccessor();
    const std::int64_t nx = f.dims[0], nxy = nx * f.dims[1];
    for (const std::int64_t q : deep) {
      const float v =
          -acc.getValue(openvdb::Coord(int(q % nx), int(q / nx % f.dims[1]), int(q / nxy)));
      f.d[q] = std::isfinite(v) ? v : std::numeric_limits<float>::max();
    }
  }
  std::stable_sort(deep.begin(), deep.end(),
                   [&](std::int64_t a, std::int64_t b) { return f.d[a] < f.d[b]; });
  const std::int64_t nx = f.dims[0], nxy = nx * f.dims[1];
  for (const std::int64_t q : deep) {
    const int i = int(q % nx), j = int(q / nx % f.dims[1]), k = int(q / nxy);
    auto n =
        nearest_of_neighbours(index, f, i, j, k, [&](std::int64_t m) { return layer[m] != 255; });
    // Where triangles are smaller than a voxel the nearest one may be none of the neighbours'
    // (their features run up to a third of a voxel high): a descent over the surface from the
    // best of them finds it. Larger triangles are seen by the neighbours already.
    if (n.triangle >= 0) {
      const auto& t = mesh.triangles[n.triangle];
      const auto& v = mesh.vertices;
      const double edge =
          std::max({(v[t[1]] - v[t[0]]).squaredNorm(), (v[t[2]] - v[t[1]]).squaredNorm(),
                    (v[t[0]] - v[t[2]]).squaredNorm()});
      if (edge < h * h) n = index.descend(f.position(i, j, k), n);
    }
    f.feature[q] = n.triangle;
    f.d[q] = static_cast<float>(n.distance);
    layer[q] = 0;
  }
}

}  // namespace

DistanceField make_distance_field(const MeshIndex& index, const FieldOptions& options) {
  DistanceField f =
      empty_field(index.mesh(), options, distance_voxel_size(index.mesh(), options), true);
  const std::vector<std::uint8_t> in = inside_voxels(index, f, options);
  std::vector<std::uint8_t> layer = surface_voxels(index, f, in);
  band_voxels(index, f, in, layer);
  interior_voxels(index, f, in, layer);
  return f;
}

DistanceField make_finer_field(const MeshIndex& index, const DistanceField& coarse,
                               const FieldOptions& options) {
  DistanceField f =
      empty_field(index.mesh(), options, field_voxel_size(index.mesh(), options), false);
  const std::vector<std::uint8_t> in = inside_voxels(index, f, options);
  f.d.assign(in.size(), static_cast<float>(-f.h));
  // A voxel on the surface itself stays inside (a value above 0), as its sign says.
  tbb::parallel_for(0, f.dims[2], [&](int k) {
    for (int j = 0; j < f.dims[1]; ++j)
      for (int i = 0; i < f.dims[0]; ++i) {
        const std::int64_t q = f.index(i, j, k);
        if (in[q])
          f.d[q] = std::max(
              std::numeric_limits<float>::min(),
              static_cast<float>(feature_distance(coarse, index.mesh(), f.position(i, j, k))));
      }
  });
  return f;
}

}  // namespace clumpkit
