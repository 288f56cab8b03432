#include "io/reports/render.h"

#include "geom/errors.h"
#include "geom/mesh/embree_scene.h"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace clumpkit {

struct ClumpRenderer::Impl {
  Vec3 center = Vec3::Zero();  ///< the framed ball, also the scenes' float origin
  double radius = 1.0;
  std::unique_ptr<EmbreeScene> mesh;
  RTCScene spheres = nullptr;
  std::size_t sphere_count = 0;
  ~Impl() {
    if (spheres) rtcReleaseScene(spheres);
  }
};

namespace {

constexpr double kFrame = 1.04;  // the view's half width over the framed ball's radius

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  int id = -1;
  Vec3 normal = Vec3::Zero();
};

Hit intersect(RTCScene scene, const float o[3], const float d[3]) {
  const RayHit r = first_hit(scene, o, d, 0.0f);
  Hit h;
  if (r.triangle < 0) return h;
  h.t = r.t;
  h.id = r.triangle;
  h.normal = Vec3(r.normal[0], r.normal[1], r.normal[2]);
  const double n = h.normal.norm();
  h.normal = n > 0 ? Vec3(h.normal / n) : Vec3(Vec3::UnitZ());
  return h;
}

/// Sphere i's colour: hues a golden-ratio step apart, so neighbours rarely look alike.
Vec3 sphere_colour(int i) {
  const double hue = std::fmod(0.08 + 0.6180339887 * i, 1.0) * 6.0, s = 0.55, v = 0.95;
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const Vec3 rgb[6] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  return 255.0 * rgb[sector];
}

}  // namespace

ClumpRenderer::ClumpRenderer(const Mesh& mesh, const Clump& clump)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if (mesh.triangles.empty() && clump.spheres.empty())
    throw InvalidInput("nothing to render: no triangles and no spheres");
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (const Sphere& s : clump.spheres) {
    lo = lo.cwiseMin(s.center - Vec3::Constant(s.radius));
    hi = hi.cwiseMax(s.center + Vec3::Constant(s.radius));
  }
  m.center = 0.5 * (lo + hi);
  m.radius = 0.0;
  for (const Vec3& v : mesh.vertices) m.radius = std::max(m.radius, (v - m.center).norm());
  for (const Sphere& s : clump.spheres)
    m.radius = std::max(m.radius, (s.center - m.center).norm() + s.radius);
  if (!(m.radius > 0.0) || !std::isfinite(m.radius))
    throw InvalidInput("nothing to render: the mesh and spheres have no extent");
  m.mesh = std::make_unique<EmbreeScene>(mesh, m.center, false);
  m.spheres = rtcNewScene(m.mesh->device);
  m.sphere_count = clump.spheres.size();
  if (!clump.spheres.empty()) {
    RTCGeometry g = rtcNewGeometry(m.mesh->device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), clump.spheres.size()));
    for (std::size_t i = 0; i < clump.spheres.size(); ++i) {
      const Vec3 c = clump.spheres[i].center - m.center;
      for (int k = 0; k < 3; ++k) v[4 * i + k] = static_cast<float>(c[k]);
      v[4 * i + 3] = static_cast<float>(clump.spheres[i].radius);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(m.spheres, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(m.spheres);
}

ClumpRenderer::~ClumpRenderer() = default;

double ClumpRenderer::frame_width() const {
  return 2.0 * kFrame * impl_->radius;
}

RgbImage ClumpRenderer::render(const Vec3& direction, const Vec3& up, int pixels) const {
  const Impl& m = *impl_;
  if (pixels <= 0)
    throw InvalidInput("render: pixels " + std::to_string(pixels) + " (must be > 0)");
  const Vec3 d = direction.normalized();
  const Vec3 side = d.cross(up);
  if (!(side.norm() > 1e-9 * up.norm()) || !d.allFinite())
    throw InvalidInput("render: the view direction is zero or parallel to up");
  const Vec3 right = side.normalized();
  const Vec3 v_up = right.cross(d);
  // Light from the viewer's upper left; rays start a diameter in front of the framed ball.
  const Vec3 light = (-d + 0.6 * v_up - 0.5 * right).normalized();
  const double half = kFrame * m.radius, back = 2.0 * m.radius;
  const std::size_t n = std::size_t(pixels) * pixels;
  std::vector<Vec3> colour(n);
  std::vector<Vec3> mesh_normal(n, Vec3::Zero());  // zero: no mesh on this pixel
  const float dir[3] = {float(d.x()), float(d.y()), float(d.z())};
  tbb::parallel_for(0, pixels, [&](int py) {
    for (int px = 0; px < pixels; ++px) {
      const double u = (2.0 * (px + 0.5) / pixels - 1.0) * half;
      const double v = (1.0 - 2.0 * (py + 0.5) / pixels) * half;
      const std::size_t q = std::size_t(py) * pixels + px;
      // Everything lies in the framed ball: a ray outside its disc hits nothing.
      if (u * u + v * v > m.radius * m.radius) {
        colour[q] = Vec3::Constant(255.0);
        continue;
      }
      const Vec3 o = u * right + v * v_up - back * d;
      const float org[3] = {float(o.x()), float(o.y()), float(o.z())};
      const Hit s = m.sphere_count > 0 ? intersect(m.spheres, org, dir) : Hit{};
      const Hit t = intersect(m.mesh->scene, org, dir);
      Vec3 c(255, 255, 255);
      if (s.id >= 0) {
        const Vec3 nrm = s.normal.dot(d) > 0 ? Vec3(-s.normal) : s.normal;
        const double lambert = std::max(0.0, nrm.dot(light));
        const Vec3 reflect = 2.0 * nrm.dot(light) * nrm - light;
        const double spec = 0.3 * std::pow(std::max(0.0, reflect.dot(-d)), 24.0);
        const double depth = std::clamp((s.t - m.radius) / (2.0 * m.radius), 0.0, 1.0);
        c = (sphere_colour(s.id) * (0.3 + 0.7 * lambert) + Vec3::Constant(255.0 * spec)) *
            (1.0 - 0.45 * depth);
      }
      if (t.id >= 0) {
        mesh_normal[q] = t.normal.dot(d) > 0 ? Vec3(-t.normal) : t.normal;
        // In front of the spheres (or of nothing) the mesh is a translucent veil; a sphere in
        // front of it pokes out of the surface, and is tinted red so overshoot shows.
        if (t.t < s.t) {
          const Vec3 shade = Vec3(175, 190, 215) * (0.6 + 0.4 * std::abs(t.normal.dot(light)));
          c = 0.62 * c + 0.38 * shade;
        } else if (s.id >= 0) {
          c = 0.45 * c + 0.55 * Vec3(235, 30, 30);
        }
      }
      colour[q] = c.cwiseMin(255.0);
    }
  });
  // Lines: the silhouette (a mesh pixel with a background pixel within two) dark, creases (the
  // face normal turns by more than ~20° to the next pixel) a lighter grey, so faces read.
  RgbImage out;
  out.width = out.height = pixels;
  out.pixels.resize(3 * n);
  auto has_mesh = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < pixels && y < pixels &&
           mesh_normal[std::size_t(y) * pixels + x].squaredNorm() > 0;
  };
  tbb::parallel_for(0, pixels, [&](int py) {
    for (int px = 0; px < pixels; ++px) {
      const std::size_t q = std::size_t(py) * pixels + px;
      Vec3 c = colour[q];
      if (has_mesh(px, py)) {
        bool edge = false, crease = false;
        for (int k = 1; k <= 2 && !edge; ++k)
          edge = !has_mesh(px - k, py) || !has_mesh(px + k, py) || !has_mesh(px, py - k) ||
                 !has_mesh(px, py + k);
        if (!edge)
          crease = mesh_normal[q].dot(mesh_normal[q + 1]) < 0.94 ||
                   mesh_normal[q].dot(mesh_normal[q + pixels]) < 0.94;
        if (edge)
          c = Vec3(55, 60, 70);
        else if (crease)
          c = 0.45 * c + 0.55 * Vec3(90, 100, 120);
      }
      for (int k = 0; k < 3; ++k)
        out.pixels[3 * q + k] =
            static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0, 255.0)));
    }
  });
  return out;
}

}  // namespace clumpkit
