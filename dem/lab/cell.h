// The cell of the element tests: rigid frictionless walls around a cuboid or a vertical
// cylinder, its size and stresses, and one step of its stress or velocity control.
#pragma once

#include "dem/core/world.h"
#include "dem/lab/servo.h"
#include "dem/run/stage_store.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// The rigid frictionless walls that hold a test specimen. Cuboid: six planes, −x, +x, −y, +y
/// (lateral) then −z, +z (platens). Cylinder: one vertical cylinder (lateral) then the platens.
/// Segment: the sector 0 ≤ φ ≤ angle of a vertical cylinder about the z-axis — the cylinder,
/// then the radial planes through the axis at φ = 0 and φ = angle (lateral), then the platens;
/// the radial planes are planes of symmetry of a whole chamber: they never move, and the
/// lateral stress is the cylinder's.
struct TestCell {
  enum class Shape { cuboid, cylinder, segment };
  Shape shape = Shape::cuboid;
  double angle = 0.0;        ///< segment: its angle (radians, in (0, π])
  std::vector<int> lateral;  ///< lateral wall indices
  int bottom = -1, top = -1;
};

/// Adds the frictionless walls of a cuboid [lo, hi] or of a vertical cylinder of `radius` about
/// the z-axis between z_lo and z_hi.
TestCell add_cuboid_test_cell(World& world, const Vec3& lo, const Vec3& hi);
TestCell add_cylinder_test_cell(World& world, double radius, double z_lo, double z_hi);
/// The segment of `angle` radians (in (0, π]) of that cylinder.
TestCell add_segment_test_cell(World& world, double radius, double angle, double z_lo, double z_hi);

/// The fraction of a whole chamber that the cell holds: angle / 2π for a segment, else 1.
double cell_fraction(const TestCell& cell);

/// Current size of the cell: height between the platens (m), lateral extents (cuboid: x and y
/// lengths; cylinder: both the diameter), volume (m³).
double cell_height(const World& world, const TestCell& cell);
double cell_volume(const World& world, const TestCell& cell);

/// Axial stress (mean of the two platens) and lateral stress (mean over the lateral walls, each
/// over its current area), Pa, compression positive.
double axial_stress(const World& world, const TestCell& cell);
double lateral_stress(const World& world, const TestCell& cell);

/// How the platens or the lateral walls move during a stage.
/// top_stress (axial only): the top platen under stress control, the bottom one fixed — a
/// chamber whose base holds while a probe pushes into it from the top.
struct Control {
  enum class Mode { stress, velocity, fixed, top_stress };
  Mode mode = Mode::fixed;
  double stress = 0;  ///< stress mode: target (Pa)
  double speed = 0;   ///< velocity mode: closing speed of the top platen (m/s; bottom stays)
};

/// One step: walls under stress control get their servo speed, the top platen under velocity
/// control closes in at its speed, fixed walls stay; then the world steps `steps` times.
void drive_cell(World& world, const TestCell& cell, const Control& axial, const Control& lateral,
                const ServoGain& gain, int steps = 1);

/// How a consolidation ended.
enum class Consolidation { equilibrium, step_limit, stopped };

/// Isotropic consolidation of the specimen in `cell` to `stress` (Pa): every wall under servo
/// control, one step at a time; every 100 steps, equilibrium when both the axial and the lateral
/// stress are within `tolerance` (relative) of the target and the mean unbalanced-force ratio is
/// at most `unbalanced`. `steps` counts the steps taken (continued from its value, up to
/// `max_steps`); `stop` is asked every 1,000 steps and ends it early when true.
Consolidation consolidate_cell(World& world, const TestCell& cell, double stress, double tolerance,
                               double unbalanced, long long max_steps, const ServoGain& gain,
                               long long& steps, const std::function<bool()>& stop = {});

/// The servo gain of a test: `gain` with its speed limit set, when not given, to
/// servo_strain_rate × height (when positive), else the larger of a millionth of the height per
/// step and ten times the platen speed `strain_rate` × height.
ServoGain test_servo_gain(ServoGain gain, double servo_strain_rate, double strain_rate,
                          double height, double dt);

/// Every wall of the cell: the lateral ones, then the bottom and top platens (cuboid: −x, +x,
/// −y, +y, −z, +z).
std::vector<int> cell_walls(const TestCell& cell);

/// Current extents (m): cuboid x and y lengths and the height; cylinder the diameter twice and
/// the height.
Vec3 cell_lengths(const World& world, const TestCell& cell);

/// Cuboid: the stress on each axis (Pa, compression positive), the mean of the two opposite
/// walls' normal stresses, each over the current area of its face. Throws InvalidInput for a
/// cylinder (use axial_stress and lateral_stress).
Vec3 cell_axis_stress(const World& world, const TestCell& cell);

/// Love–Weber stress (dem/measure/stress.h) of the bodies whose centroid lies inside the cell,
/// over the cell's volume.
Mat3 cell_love_weber_stress(const World& world, const TestCell& cell);

/// The cell's walls into a stage record ("cell.shape", "cell.lateral", "cell.bottom", "cell.top"),
/// so a checkpointed run knows them again.
void put_cell(StageRecord& record, const TestCell& cell);

/// The cell of put_cell. Throws InvalidInput naming `where` for a missing or malformed entry.
TestCell read_cell(const StageRecord& record, const std::string& where);

/// The phase a test's stage record holds, an index in [0, phases). Throws InvalidInput "WHERE:
/// stage record phase: N is not a phase of the test" otherwise.
int record_phase(const StageRecord& record, const std::string& where, int phases);

/// A test's curve into its stage record (put_curve): per row its step, then the numbers
/// `fields(row)` points at (an array of double*).
template <class Row, class Fields>
void put_test_curve(StageRecord& record, std::vector<Row> curve, Fields fields) {
  std::vector<std::vector<double>> rows;
  for (Row& c : curve) {
    rows.push_back({double(c.step)});
    for (double* v : fields(c)) rows.back().push_back(*v);
  }
  put_curve(record, rows);
}

/// The curve of put_test_curve, rows of `columns` numbers (step first). Throws InvalidInput naming
/// `where` for a missing or malformed row.
template <class Row, class Fields>
std::vector<Row> read_test_curve(const StageRecord& record, std::size_t columns,
                                 const std::string& where, Fields fields) {
  std::vector<Row> curve;
  for (const std::vector<double>& v : record_curve(record, columns, where)) {
    Row c;
    c.step = static_cast<long long>(v[0]);
    auto at = fields(c);
    for (std::size_t f = 0; f + 1 < columns; ++f) *at[f] = v[f + 1];
    curve.push_back(c);
  }
  return curve;
}

}  // namespace clumpkit::dem
