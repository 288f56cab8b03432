#include "io/export/yade.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"

#include <cmath>
#include <functional>

namespace clumpkit {

namespace {

/// specimen_bodies.txt: clumpkit's exact mass, pose and principal moments of each rock body.
void write_yade_bodies(std::ostream& o, const std::vector<SpecimenBody>& bodies) {
  o << "# clumpkit exact rock bodies (SI): body mass x y z qw qx qy qz I1 I2 I3 (principal\n"
       "# moments about the body axes; the quaternion rotates body axes into the world)\n";
  for (const SpecimenBody& b : bodies)
    if (b.kind == dem::BodyKind::rock)
      o << b.id << " " << format_number(b.mass) << " " << format_xyz(b.position) << " "
        << format_number(b.orientation.w()) << " " << format_number(b.orientation.x()) << " "
        << format_number(b.orientation.y()) << " " << format_number(b.orientation.z()) << " "
        << format_xyz(b.moments) << "\n";
}

/// bodies_map.csv: the Yade body id each specimen body will get.
void write_yade_body_map(std::ostream& o, const std::vector<SpecimenBody>& bodies) {
  // Yade numbers bodies as they are appended: each clump's members, then the clump; then the
  // soil spheres and walls. The script checks these ids as it builds.
  o << "# specimen.csv body id -> Yade body id (clump id for rock, sphere id for soil)\n"
    << csv_header("bodies_map", "body,yade_kind,yade_id", si_length()) << "\n";
  long next = 0;
  for (const SpecimenBody& b : bodies)
    if (b.kind == dem::BodyKind::rock) {
      next += static_cast<long>(b.spheres.size());
      o << b.id << ",clump," << next++ << "\n";
    }
  for (const SpecimenBody& b : bodies)
    if (b.kind == dem::BodyKind::soil) o << b.id << ",sphere," << next++ << "\n";
}

/// The part of run_clumpkit.py after its settings: it takes every value from them.
constexpr char kYadeScriptBody[] = R"py(
def material(density):
    return O.materials.append(FrictMat(young=KN / R_MEAN, poisson=KS / KN,
                                       frictionAngle=math.atan(MU), density=density))

rock, soil, wall = material(RHO_ROCK), material(RHO_SOIL), material(RHO_ROCK)

def rows(path):
    with open(path) as f:
        return [line.split() for line in f if line.strip() and not line.startswith("#")]

members = {}
for x, y, z, r, body in rows("clump_members.txt"):
    members.setdefault(int(body), []).append((Vector3(float(x), float(y), float(z)), float(r)))
exact = {int(r[0]): [float(v) for v in r[1:]] for r in rows("specimen_bodies.txt")}
expected = {int(r[0]): int(r[2]) for r in
            (line.split(",") for line in open("bodies_map.csv") if line[0].isdigit())}

def axis(m, k):
    return Vector3(m[0, k], m[1, k], m[2, k])

def matched_moments(ori, q, moments):
    """Our principal moments, each on the Yade axis nearest our principal axis."""
    ours, theirs = q.toRotationMatrix(), ori.toRotationMatrix()
    best, best_cos = None, -1.0
    for p in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        worst = min(abs(axis(theirs, k).dot(axis(ours, p[k]))) for k in range(3))
        if worst > best_cos:
            best, best_cos = p, worst
    return Vector3(*(moments[best[k]] for k in range(3))), math.degrees(math.acos(min(1.0, best_cos)))

clumps = {}
residuals = []
for body, spheres in members.items():
    cid, _ = O.bodies.appendClumped([utils.sphere(c, r, material=rock) for c, r in spheres],
                                    discretization=DISCRETIZATION)
    if cid != expected[body]:
        raise RuntimeError("bodies_map.csv: body %d expected Yade id %d, got %d"
                           % (body, expected[body], cid))
    clumps[body] = cid
    mass, x, y, z, qw, qx, qy, qz, i1, i2, i3 = exact[body]
    state = O.bodies[cid].state
    inertia, angle = matched_moments(state.ori, Quaternion(qw, qx, qy, qz), (i1, i2, i3))
    offset = state.pos - Vector3(x, y, z)
    residuals.append((body, cid, offset.norm(), angle))
    if EXACT:
        state.mass = mass
        state.inertia = inertia
soil_ids = {}
for x, y, z, r, body in rows("soil_spheres.txt"):
    sid = O.bodies.append(utils.sphere(Vector3(float(x), float(y), float(z)), float(r),
                                       material=soil))
    if sid != expected[int(body)]:
        raise RuntimeError("bodies_map.csv: body %s expected Yade id %d, got %d"
                           % (body, expected[int(body)], sid))
    soil_ids[int(body)] = sid
O.bodies.append(utils.wall((0, 0, 0), axis=2, sense=1, material=wall))
# A faceted cylinder whose flat facets touch the container's circle at their midlines.
SEGMENTS = 72
O.bodies.append(geom.facetCylinder((0, 0, HEIGHT / 2), CONTAINER_RADIUS / math.cos(math.pi / SEGMENTS),
                                   HEIGHT, segmentsNumber=SEGMENTS, wallMask=4, material=wall))

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(damping=LOCAL_DAMPING, gravity=(0, 0, -GRAVITY)),
]

with open("yade_residuals.txt", "w") as f:
    f.write("# body yade_id |Yade centroid - exact centroid| (m) largest angle between matched axes (deg)\n")
    for body, cid, offset, angle in residuals:
        f.write("%d %d %.17g %.17g\n" % (body, cid, offset, angle))

def report(step):
    with open("bodies.%d.txt" % step, "w") as f:
        f.write("# body yade_id mass I1 I2 I3 x y z (state.mass, state.inertia, state.pos)\n")
        for body, cid in sorted(clumps.items()):
            s = O.bodies[cid].state
            f.write("%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n" % (
                body, cid, s.mass, s.inertia[0], s.inertia[1], s.inertia[2],
                s.pos[0], s.pos[1], s.pos[2]))

report(0)
O.run(NSTEPS, True)
report(NSTEPS)
print("clumpkit: %d clumps, %d soil spheres, %d steps" % (len(clumps), len(soil_ids), NSTEPS))
)py";

/// run_clumpkit.py: the settings, then the script that builds, checks and settles the bodies.
void write_yade_script(std::ostream& o, const EngineSettings& settings, double r_mean, double dt,
                       double height) {
  const dem::ContactParams& c = settings.contact;
  o << "# clumpkit export for Yade (syntax of Yade 2023.02a, Debian 12 `yade`). Run headless:\n"
       "#   yade -n -x run_clumpkit.py [nsteps (1000)] [exact (1; 0: Yade's own masses)]\n"
       "# Clumps are built by appendClumped from clump_members.txt, so their reference point\n"
       "# and axes are Yade's (from the member spheres); clumpkit's exact mass and principal\n"
       "# moments (specimen_bodies.txt) are then forced on them. yade_residuals.txt says how\n"
       "# far Yade's centroid and axes are from the exact ones.\n"
       "import math\n"
       "import sys\n"
       "from yade import geom, utils\n\n"
    << "NSTEPS = int(sys.argv[1]) if len(sys.argv) > 1 else 1000\n"
    << "EXACT = int(sys.argv[2]) if len(sys.argv) > 2 else 1\n"
    << "KN, KS, MU = " << format_number(c.kn) << ", " << format_number(c.ks) << ", "
    << format_number(c.friction) << "\n"
    << "LOCAL_DAMPING = " << format_number(c.local_damping) << "\n"
    << "R_MEAN = " << format_number(r_mean) << "  # Ip2_FrictMat_FrictMat_FrictPhys: kn = E r\n"
    << "RHO_ROCK, RHO_SOIL = " << format_number(settings.rock_density) << ", "
    << format_number(settings.soil_density) << "\n"
    << "CONTAINER_RADIUS, HEIGHT = " << format_number(settings.container_radius) << ", "
    << format_number(height) << "\n"
    << "GRAVITY = " << format_number(settings.gravity) << "  # m/s², downwards\n"
    << "# Yade's clump centroid and axes come from a grid of step (smallest member radius) /\n"
       "# DISCRETIZATION (Clump::updateProperties; 0: the plain sphere sum, overlaps twice).\n"
       "DISCRETIZATION = 30\n"
    << "O.dt = " << format_number(dt) << "\n"
    << kYadeScriptBody;
}

}  // namespace

std::vector<std::string> write_yade_export(const std::vector<SpecimenBody>& bodies,
                                           const EngineSettings& settings, const std::string& dir) {
  if (bodies.empty()) throw InvalidInput("Yade export: the specimen has no bodies");
  const SpecimenExtents e = specimen_extents(bodies);
  std::vector<std::string> files;
  auto file = [&](const char* name, const std::function<void(std::ostream&)>& fill) {
    files.push_back(write_export_file(dir, name, fill));
  };
  double radius_sum = 0;
  std::size_t spheres = 0;
  for (const SpecimenBody& b : bodies)
    for (const Sphere& s : b.spheres) {
      radius_sum += s.radius;
      ++spheres;
    }

  file("clump_members.txt", [&](std::ostream& o) {
    o << "# clumpkit rock spheres (m), world frame: x y z r body (ymport.textClumps format)\n";
    for (const SpecimenBody& b : bodies)
      if (b.kind == dem::BodyKind::rock)
        for (const Sphere& s : b.spheres)
          o << format_xyz(s.center) << " " << format_number(s.radius) << " " << b.id << "\n";
  });
  file("soil_spheres.txt", [&](std::ostream& o) {
    o << "# clumpkit soil spheres (m), world frame: x y z r body\n";
    for (const SpecimenBody& b : bodies)
      if (b.kind == dem::BodyKind::soil)
        for (const Sphere& s : b.spheres)
          o << format_xyz(s.center) << " " << format_number(s.radius) << " " << b.id << "\n";
  });
  file("specimen_bodies.txt", [&](std::ostream& o) { write_yade_bodies(o, bodies); });
  file("bodies_map.csv", [&](std::ostream& o) { write_yade_body_map(o, bodies); });

  const double r_mean = radius_sum / static_cast<double>(spheres);
  const double dt = 0.2 * std::sqrt(e.m_min / settings.contact.kn);
  const double height = std::max(settings.container_height, e.top) + 2 * e.r_max;
  file("run_clumpkit.py",
       [&](std::ostream& o) { write_yade_script(o, settings, r_mean, dt, height); });
  return files;
}

}  // namespace clumpkit
