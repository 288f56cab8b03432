#include "geom/fill/distance_field.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/ray_inside.h"

#include <tbb/parallel_for.h>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <cmath>
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

double field_voxel_size(const Mesh& mesh, const FieldOptions& o) {
  if (o.voxel_size > 0.0) {
    if (!std::isfinite(o.voxel_size))
      throw InvalidInput("voxel size must be finite, got " + std::to_string(o.voxel_size));
    return o.voxel_size;
  }
  if (o.voxels < 4 || o.voxels > 2000)
    throw InvalidInput("--voxels must be in [4, 2000], got " + std::to_string(o.voxels));
  if (o.vote_sign) {
    // A mesh with holes has no reliable volume, hence no inertia axes: use the box instead.
    const auto bb = bounding_box(mesh);
    return (bb[1] - bb[0]).minCoeff() / o.voxels;
  }
  const PrincipalFrame f = principal_frame(mesh);
  return f.extents[0] / o.voxels;
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

}  // namespace

double field_voxel_count(const Mesh& mesh, const FieldOptions& options) {
  return product(field_dims(bounding_box(mesh), field_voxel_size(mesh, options)));
}

double fill_bytes_estimate(const Mesh& mesh, const FieldOptions& options) {
  return 64.0 * 1048576.0 + 16.0 * field_voxel_count(mesh, options) +
         450.0 * double(mesh.triangles.size());
}

DistanceField make_distance_field(const Mesh& mesh, const FieldOptions& options) {
  init_openvdb();
  const double h = field_voxel_size(mesh, options);
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
    const double need = fill_bytes_estimate(mesh, options);
    if (!(need <= options.max_bytes))
      throw InvalidInput("fill would need an estimated " + format_number(need / 1073741824.0, 3) +
                         " GiB (" + format_number(total) + " voxels of size " + format_number(h) +
                         ", " + std::to_string(mesh.triangles.size()) +
                         " triangles), more than --max-memory " +
                         format_number(options.max_bytes / 1073741824.0, 3) +
                         " GiB: use fewer --voxels or a larger voxel size");
  }
  f.origin = lo;

  // OpenVDB index space: voxel (i, j, k) centre at h (i, j, k) relative to lo. Points are shifted
  // to lo before the conversion to float so that far-from-origin meshes keep their precision.
  auto xform = openvdb::math::Transform::createLinearTransform(h);
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  for (const auto& p : mesh.vertices) {
    const Vec3 q = p - lo;
    points.emplace_back(float(q.x()), float(q.y()), float(q.z()));
  }
  std::vector<openvdb::Vec3I> tris;
  tris.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) tris.emplace_back(t[0], t[1], t[2]);
  const std::vector<openvdb::Vec4I> quads;
  const auto grid = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
      *xform, points, tris, quads, 1.0f, std::numeric_limits<float>::max());

  f.d.assign(static_cast<std::size_t>(total), static_cast<float>(-3.0 * h));
  const auto acc = grid->getConstAccessor();
  for (int k = 0; k < f.dims[2]; ++k)
    for (int j = 0; j < f.dims[1]; ++j)
      for (int i = 0; i < f.dims[0]; ++i) {
        const openvdb::Coord c(i, j, k);
        float v;
        if (acc.probeValue(c, v)) {
          f.d[f.index(i, j, k)] = -v;  // OpenVDB: negative inside
        } else {
          // Inactive: background; OpenVDB marks the filled interior with active voxels, so an
          // inactive voxel is outside unless its background sign says inside.
          f.d[f.index(i, j, k)] = -acc.getValue(c);
        }
      }
  if (options.vote_sign) {
    // OpenVDB's sign assumes a closed surface; the magnitudes (distances to the nearest
    // triangle) stay right, so only the sign is re-decided, voxel by voxel.
    const RayInside rays(mesh);
    tbb::parallel_for(0, f.dims[2], [&](int k) {
      for (int j = 0; j < f.dims[1]; ++j)
        for (int i = 0; i < f.dims[0]; ++i) {
          float& v = f.d[f.index(i, j, k)];
          v = rays.inside(f.position(i, j, k)) ? std::abs(v) : -std::abs(v);
        }
    });
  }
  return f;
}

}  // namespace clumpkit
