#include "dem/lab/cell.h"

#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "geom/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace clumpkit::dem {

namespace {

int add_frictionless(World& world, Wall wall) {
  wall.friction = 0.0;
  return world.add_wall(wall);
}

// Lateral extents: cuboid x and y lengths; cylinder and segment the diameter twice.
std::array<double, 2> lateral_extents(const World& world, const TestCell& cell) {
  if (cell.shape != TestCell::Shape::cuboid) {
    const double d = 2.0 * world.walls()[cell.lateral[0]].radius;
    return {d, d};
  }
  return {world.walls()[cell.lateral[1]].point.x() - world.walls()[cell.lateral[0]].point.x(),
          world.walls()[cell.lateral[3]].point.y() - world.walls()[cell.lateral[2]].point.y()};
}

double axial_area(const World& world, const TestCell& cell) {
  if (cell.shape != TestCell::Shape::cuboid) {
    const double r = world.walls()[cell.lateral[0]].radius;
    return cell_fraction(cell) * kPi * r * r;
  }
  const auto e = lateral_extents(world, cell);
  return e[0] * e[1];
}

// Area of lateral wall k of the cell.
double lateral_area(const World& world, const TestCell& cell, std::size_t k) {
  const double h = cell_height(world, cell);
  if (cell.shape == TestCell::Shape::cylinder)
    return 2.0 * kPi * world.walls()[cell.lateral[0]].radius * h;
  if (cell.shape == TestCell::Shape::segment)  // the arc θ R h, or a radial plane R h
    return (k == 0 ? cell.angle : 1.0) * world.walls()[cell.lateral[0]].radius * h;
  const auto e = lateral_extents(world, cell);
  return (k < 2 ? e[1] : e[0]) * h;  // x walls span y, y walls span x
}

void servo(World& world, int wall, double area, double target, const ServoGain& gain) {
  set_wall_speed(world, wall,
                 servo_speed(wall_stress(world, wall, area), target, area,
                             wall_contact_stiffness(world, wall), world.options().timestep, gain));
}

// The cell's extents about its centre: its walls strain the specimen homogeneously, so the
// world's lists measure the spheres' motion relative to that strain (World::set_cell_frame).
void frame_cell(World& world, const TestCell& cell) {
  const auto e = lateral_extents(world, cell);
  const std::vector<Wall>& w = world.walls();
  const double z0 = w[cell.bottom].point.z(), z1 = w[cell.top].point.z();
  const Vec3 centre =
      cell.shape == TestCell::Shape::cuboid
          ? Vec3(0.5 * (w[cell.lateral[0]].point.x() + w[cell.lateral[1]].point.x()),
                 0.5 * (w[cell.lateral[2]].point.y() + w[cell.lateral[3]].point.y()),
                 0.5 * (z0 + z1))
          : Vec3(w[cell.lateral[0]].point.x(), w[cell.lateral[0]].point.y(), 0.5 * (z0 + z1));
  world.set_cell_frame(centre, Vec3(e[0], e[1], z1 - z0));
}

}  // namespace

TestCell add_cuboid_test_cell(World& world, const Vec3& lo, const Vec3& hi) {
  if (!((hi - lo).minCoeff() > 0.0) || !(hi - lo).allFinite())
    throw InvalidInput("test cell: the box must have positive, finite edges");
  TestCell c;
  c.shape = TestCell::Shape::cuboid;
  for (int a = 0; a < 2; ++a) {
    c.lateral.push_back(add_frictionless(world, Wall::plane(lo, Vec3::Unit(a))));
    c.lateral.push_back(add_frictionless(world, Wall::plane(hi, -Vec3::Unit(a))));
  }
  c.bottom = add_frictionless(world, Wall::plane(lo, Vec3::UnitZ()));
  c.top = add_frictionless(world, Wall::plane(hi, -Vec3::UnitZ()));
  return c;
}

TestCell add_cylinder_test_cell(World& world, double radius, double z_lo, double z_hi) {
  if (!(radius > 0.0) || !(z_hi > z_lo) || !std::isfinite(radius) || !std::isfinite(z_hi - z_lo))
    throw InvalidInput("test cell: the cylinder must have a positive radius and height");
  TestCell c;
  c.shape = TestCell::Shape::cylinder;
  c.lateral.push_back(add_frictionless(world, Wall::cylinder(0.0, 0.0, radius)));
  c.bottom = add_frictionless(world, Wall::plane(Vec3(0, 0, z_lo), Vec3::UnitZ()));
  c.top = add_frictionless(world, Wall::plane(Vec3(0, 0, z_hi), -Vec3::UnitZ()));
  return c;
}

TestCell add_segment_test_cell(World& world, double radius, double angle, double z_lo,
                               double z_hi) {
  if (!(angle > 0.0 && angle <= kPi))
    throw InvalidInput("test cell: a segment's angle must be in (0, 180] degrees, got " +
                       std::to_string(angle * 180.0 / kPi));
  TestCell c = add_cylinder_test_cell(world, radius, z_lo, z_hi);
  c.shape = TestCell::Shape::segment;
  c.angle = angle;
  // The radial planes after the cylinder, then the platens again last (cell_walls' order is
  // lateral, bottom, top; the indices say which is which).
  c.lateral.push_back(add_frictionless(world, Wall::plane(Vec3::Zero(), Vec3::UnitY())));
  c.lateral.push_back(add_frictionless(
      world, Wall::plane(Vec3::Zero(), Vec3(std::sin(angle), -std::cos(angle), 0.0))));
  return c;
}

double cell_fraction(const TestCell& cell) {
  return cell.shape == TestCell::Shape::segment ? cell.angle / (2.0 * kPi) : 1.0;
}

double cell_height(const World& world, const TestCell& cell) {
  return world.walls()[cell.top].point.z() - world.walls()[cell.bottom].point.z();
}

double cell_volume(const World& world, const TestCell& cell) {
  return axial_area(world, cell) * cell_height(world, cell);
}

double axial_stress(const World& world, const TestCell& cell) {
  const double a = axial_area(world, cell);
  return 0.5 * (wall_stress(world, cell.bottom, a) + wall_stress(world, cell.top, a));
}

double lateral_stress(const World& world, const TestCell& cell) {
  if (cell.shape == TestCell::Shape::segment)  // the planes of symmetry carry the hoop stress
    return wall_stress(world, cell.lateral[0], lateral_area(world, cell, 0));
  double s = 0;
  for (std::size_t k = 0; k < cell.lateral.size(); ++k)
    s += wall_stress(world, cell.lateral[k], lateral_area(world, cell, k));
  return s / static_cast<double>(cell.lateral.size());
}

void drive_cell(World& world, const TestCell& cell, const Control& axial, const Control& lateral,
                const ServoGain& gain, int steps) {
  using Mode = Control::Mode;
  const double a = axial_area(world, cell);
  switch (axial.mode) {
    case Mode::stress:
      servo(world, cell.bottom, a, axial.stress, gain);
      servo(world, cell.top, a, axial.stress, gain);
      break;
    case Mode::velocity:
      set_wall_speed(world, cell.bottom, 0.0);
      set_wall_speed(world, cell.top, axial.speed);
      break;
    case Mode::top_stress:
      set_wall_speed(world, cell.bottom, 0.0);
      servo(world, cell.top, a, axial.stress, gain);
      break;
    case Mode::fixed:
      set_wall_speed(world, cell.bottom, 0.0);
      set_wall_speed(world, cell.top, 0.0);
      break;
  }
  for (std::size_t k = 0; k < cell.lateral.size(); ++k) {
    if (cell.shape == TestCell::Shape::segment && k > 0)  // planes of symmetry: fixed
      set_wall_speed(world, cell.lateral[k], 0.0);
    else if (lateral.mode == Mode::stress)
      servo(world, cell.lateral[k], lateral_area(world, cell, k), lateral.stress, gain);
    else if (lateral.mode == Mode::fixed)
      set_wall_speed(world, cell.lateral[k], 0.0);
    else
      throw InvalidInput("test cell: lateral walls are stress-controlled or fixed");
  }
  frame_cell(world, cell);
  world.step(steps);
}

Consolidation consolidate_cell(World& world, const TestCell& cell, double stress, double tolerance,
                               double unbalanced, long long max_steps, const ServoGain& gain,
                               long long& steps, const std::function<bool()>& stop) {
  const Control confine{Control::Mode::stress, stress, 0.0};
  constexpr int kCheck = 100;
  while (steps < max_steps) {
    drive_cell(world, cell, confine, confine, gain, 1);
    if (++steps % kCheck != 0) continue;
    const double ea = std::abs(axial_stress(world, cell) / stress - 1.0);
    const double el = std::abs(lateral_stress(world, cell) / stress - 1.0);
    if (ea <= tolerance && el <= tolerance && mean_unbalanced_force_ratio(world) <= unbalanced)
      return Consolidation::equilibrium;
    if (stop && steps % (kCheck * 10) == 0 && stop()) return Consolidation::stopped;
  }
  return Consolidation::step_limit;
}

ServoGain test_servo_gain(ServoGain gain, double servo_strain_rate, double strain_rate,
                          double height, double dt) {
  // Default speed limit: a millionth of the height per step, or ten times the platen's speed.
  if (servo_strain_rate > 0.0)
    gain.max_speed = servo_strain_rate * height;
  else if (!(gain.max_speed > 0.0))
    gain.max_speed = std::max(1e-6 * height / dt, 10.0 * strain_rate * height);
  return gain;
}

std::vector<int> cell_walls(const TestCell& cell) {
  std::vector<int> w = cell.lateral;
  w.push_back(cell.bottom);
  w.push_back(cell.top);
  return w;
}

Vec3 cell_lengths(const World& world, const TestCell& cell) {
  const auto e = lateral_extents(world, cell);
  return Vec3(e[0], e[1], cell_height(world, cell));
}

Vec3 cell_axis_stress(const World& world, const TestCell& cell) {
  if (cell.shape != TestCell::Shape::cuboid)
    throw InvalidInput("test cell: stress per axis needs a cuboid cell");
  const Vec3 l = cell_lengths(world, cell);
  Vec3 s;
  for (int a = 0; a < 2; ++a) {
    const double area = l[1 - a] * l[2];  // x walls span y and z, y walls x and z
    s[a] = 0.5 * (wall_stress(world, cell.lateral[2 * a], area) +
                  wall_stress(world, cell.lateral[2 * a + 1], area));
  }
  s[2] = axial_stress(world, cell);
  return s;
}

Mat3 cell_love_weber_stress(const World& world, const TestCell& cell) {
  const double z_lo = world.walls()[cell.bottom].point.z(),
               z_hi = world.walls()[cell.top].point.z();
  if (cell.shape != TestCell::Shape::cuboid) {
    const Wall& side = world.walls()[cell.lateral[0]];
    const bool segment = cell.shape == TestCell::Shape::segment;
    const Vec3 n1 = segment ? world.walls()[cell.lateral[1]].normal : Vec3::Zero();
    const Vec3 n2 = segment ? world.walls()[cell.lateral[2]].normal : Vec3::Zero();
    return love_weber_stress(
        world,
        [&](const Vec3& x) {
          const double dx = x.x() - side.point.x(), dy = x.y() - side.point.y();
          const bool wedge =
              !segment || (n1.x() * dx + n1.y() * dy >= 0.0 && n2.x() * dx + n2.y() * dy >= 0.0);
          return wedge && dx * dx + dy * dy <= side.radius * side.radius && x.z() >= z_lo &&
                 x.z() <= z_hi;
        },
        cell_volume(world, cell));
  }
  const Vec3 lo(world.walls()[cell.lateral[0]].point.x(), world.walls()[cell.lateral[2]].point.y(),
                z_lo);
  const Vec3 hi(world.walls()[cell.lateral[1]].point.x(), world.walls()[cell.lateral[3]].point.y(),
                z_hi);
  return love_weber_stress(
      world,
      [&](const Vec3& x) {
        return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
      },
      (hi - lo).prod());
}

void put_cell(StageRecord& record, const TestCell& cell) {
  record["cell.shape"] = cell.shape == TestCell::Shape::cuboid     ? "cuboid"
                         : cell.shape == TestCell::Shape::cylinder ? "cylinder"
                                                                   : "segment";
  if (cell.shape == TestCell::Shape::segment) put_number(record, "cell.angle", cell.angle);
  std::string lateral;
  for (int w : cell.lateral) lateral += (lateral.empty() ? "" : ",") + std::to_string(w);
  record["cell.lateral"] = lateral;
  record["cell.bottom"] = std::to_string(cell.bottom);
  record["cell.top"] = std::to_string(cell.top);
}

TestCell read_cell(const StageRecord& record, const std::string& where) {
  TestCell cell;
  const auto shape = record.find("cell.shape");
  if (shape == record.end() ||
      (shape->second != "cuboid" && shape->second != "cylinder" && shape->second != "segment"))
    throw InvalidInput(where + ": stage record cell.shape missing or not cuboid/cylinder/segment");
  cell.shape = shape->second == "cuboid"     ? TestCell::Shape::cuboid
               : shape->second == "cylinder" ? TestCell::Shape::cylinder
                                             : TestCell::Shape::segment;
  if (cell.shape == TestCell::Shape::segment) {
    cell.angle = record_number(record, "cell.angle", where);
    if (!(cell.angle > 0.0 && cell.angle <= kPi))
      throw InvalidInput(where + ": stage record cell.angle: not in (0, pi]");
  }
  for (double w : record_list(record, "cell.lateral", where)) {
    if (!(w >= 0 && w < 2147483647.0) || w != std::floor(w))
      throw InvalidInput(where + ": stage record cell.lateral: " + std::to_string(w) +
                         " is not a wall index");
    cell.lateral.push_back(static_cast<int>(w));
  }
  cell.bottom = static_cast<int>(record_integer(record, "cell.bottom", where));
  cell.top = static_cast<int>(record_integer(record, "cell.top", where));
  const std::size_t lateral_walls = cell.shape == TestCell::Shape::cuboid     ? 4
                                    : cell.shape == TestCell::Shape::cylinder ? 1
                                                                              : 3;
  if (cell.lateral.size() != lateral_walls || cell.bottom < 0 || cell.top < 0)
    throw InvalidInput(where + ": stage record cell: " + shape->second + " with " +
                       std::to_string(cell.lateral.size()) + " lateral walls, bottom " +
                       std::to_string(cell.bottom) + ", top " + std::to_string(cell.top));
  return cell;
}

int record_phase(const StageRecord& record, const std::string& where, int phases) {
  const long long phase = record_integer(record, "phase", where);
  if (phase < 0 || phase >= phases)
    throw InvalidInput(where + ": stage record phase: " + std::to_string(phase) +
                       " is not a phase of the test");
  return static_cast<int>(phase);
}

}  // namespace clumpkit::dem
