// Element tests on a DEM specimen in a servo-controlled cell (dem/lab/cell.h), along a loading
// path (LoadingPath below): isotropic, oedometer, triaxial, constant-p′ triaxial.
#pragma once

#include "dem/core/world.h"
#include "dem/lab/cell.h"
#include "dem/lab/servo.h"
#include "dem/measure/breakage.h"
#include "dem/run/stage_store.h"
#include "geom/range.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// The world options of an element test on `bodies` (SI): gravity off (the test's stresses are
/// far above the specimen's weight), spatial sorting every 1,000 steps (as LAMMPS), the Verlet
/// skin 0.2·r_min of the smallest sphere (a length of the specimen, so a scaled copy runs
/// alike) and the specimen's `contact` law. Throws InvalidInput for no bodies.
WorldOptions element_test_world_options(const std::vector<Body>& bodies,
                                        const ContactParams& contact);

/// The Verlet skin of a test on crushable particles: 0.75 of the median sphere radius. A bond
/// that breaks releases fragments at metres per second while the specimen creeps, and the skin
/// list is searched again once the fastest sphere has crossed half the skin: with 0.2·r_min the
/// rockfill oedometer searched every third step past its yield stress. A performance setting
/// only (results do not depend on the skin). Throws InvalidInput for no spheres.
double crushable_skin(const std::vector<Body>& bodies);

/// Inertial number I = ε̇·d·sqrt(ρ/p) of a test at `strain_rate` (1/s) and `confining` stress (Pa)
/// on `bodies`, d their mean volume-equivalent diameter and ρ their total mass over their total
/// volume: quasi-static below 1e-3, dense flow above 1e-2 (GDR MiDi 2004).
double inertial_number(const std::vector<Body>& bodies, double strain_rate, double confining);

/// The grains of an inertial number: their mean volume-equivalent diameter d (m) and their total
/// mass over their total volume ρ (kg/m³, with any density scaling the masses carry). A grain is
/// a body, or with `particles` (one entry per body, ElementTestSettings::particles) the bodies
/// of one particle together: a crushable specimen's particle, not its cells.
struct GrainScale {
  double diameter = 0, density = 0;
};
GrainScale grain_scale(const std::vector<Body>& bodies, const std::vector<int>& particles = {});

/// The strain rate ε̇ = I·sqrt(σ/ρ)/d (1/s) that gives inertial number I under stress σ (Pa).
double inertial_strain_rate(const GrainScale& grains, double inertial, double stress);

struct LoadingPath;
extern const LoadingPath kTriaxialPath;

/// The ranges of ElementTestSettings that run_element_test checks: the confining stress (Pa),
/// the strain rate (1/s) and the relative stress error of an equilibrium.
inline constexpr Range kConfiningStress = above(0);
inline constexpr Range kTestStrainRate = above(0);
inline constexpr Range kConsolidationTolerance = above(0);
/// The isotropic loading rate (Pa/s; 0: confining·strain_rate·20) and the servo walls' speed
/// limit as a strain rate (1/s; 0: the gain's).
inline constexpr Range kStressRate = at_least(0);
inline constexpr Range kServoStrainRate = at_least(0);
/// The inertial number an oedometer or triaxial holds (0: none, strain_rate throughout).
inline constexpr Range kHeldInertialNumber = at_least(0);
/// Where a triaxial ends (engineering axial strain): at 1 the platens would meet.
inline constexpr Range kMaxAxialStrain = open(0, 1);
/// The step limit of one oedometer hold (checked with hold stresses) and the steps between
/// curve rows.
inline constexpr Range kMaxHoldSteps = integers_from(100);
inline constexpr Range kRecordEvery = integers_from(1);
/// The last fraction of a triaxial curve averaged for the critical state (a test recipe's
/// critical_fraction; the test job reads the curve's rows past it).
inline constexpr Range kCriticalFraction = open_closed(0, 1);

/// Parameters of run_element_test (SI).
struct ElementTestSettings {
  /// Which test: how the walls are driven while loading and when it ends (LoadingPath below).
  const LoadingPath* path = &kTriaxialPath;
  /// Consolidation stress, and the lateral stress of a triaxial (Pa), in kConfiningStress.
  double confining = 100e3;
  /// isotropic: stress at the end of loading; oedometer: axial stress at the end (Pa).
  double final_stress = 400e3;
  /// Axial strain rate of oedometer and triaxial (1/s), in kTestStrainRate.
  double strain_rate = 0.05;
  /// Isotropic loading rate (Pa/s), in kStressRate; 0: confining·strain_rate·20.
  double stress_rate = 0.0;
  /// Oedometer and triaxial, > 0: the platen speeds up with the stress so that the inertial
  /// number of the particles (grain_scale) at the last curve row's axial stress stays at this
  /// value, never slower than strain_rate. A test to stresses a decade and more above the
  /// confining one then spends its steps where the strain is, instead of loading at the rate the
  /// lowest stress allows. 0: strain_rate throughout. In kHeldInertialNumber.
  double inertial_number = 0.0;
  /// Oedometer: axial stresses (Pa, ascending, each above `confining` and at most
  /// `final_stress`) where the platen stops and its servo holds the stress (the bottom platen
  /// fixed) until equilibrium, the load increments of a laboratory oedometer: every 100 steps,
  /// the axial stress within consolidation_tolerance of the target and the unbalanced-force
  /// ratio at most consolidation_unbalanced, or max_hold_steps. The state at each hold's end
  /// carries no rate part of the stress (the platen is at rest). Empty: a continuous test.
  std::vector<double> hold_stresses;
  long long max_hold_steps = 200'000;  ///< a hold's step limit, in kMaxHoldSteps
  double max_axial_strain = 0.2;       ///< triaxial end, in kMaxAxialStrain
  double friction = -1;                ///< μ of the test (negative: the world's)
  /// μ during the consolidation (negative: the test's). 0 consolidates a frictionless packing
  /// to its densest state at the confining stress, whatever its preparation (a protocol that
  /// makes specimens of different sizes and laws comparable); the test's μ applies from the
  /// start of loading.
  double consolidation_friction = -1;
  /// Relative stress error at equilibrium, in kConsolidationTolerance.
  double consolidation_tolerance = 0.005;
  double consolidation_unbalanced = 1e-3;  ///< unbalanced-force ratio at equilibrium
  long long max_consolidation_steps = 3'000'000;
  ServoGain gain;  ///< max_speed 0: 10 × the platen speed, or height/1000 per 1,000 steps
  /// Speed limit of every servo-driven wall as a strain rate of the cell (1/s, in
  /// kServoStrainRate; 0: gain's). Set ÷ λ for specimens λ times larger, it keeps the
  /// consolidation's inertial number the same whatever the time step (the default limit is per
  /// step, and the step of a constant-kn specimen grows as λ^1.5).
  double servo_strain_rate = 0.0;
  int record_every = 200;  ///< steps between curve rows, in kRecordEvery
  /// A crushable specimen (bonded cells): its bodies as built (the reference poses: a fragment
  /// is sized from its cells there, so cells that only deform their bonds change no size), its
  /// grading then (fragment_pieces) and the sieves of Marsal's Bg. Empty: no breakage columns
  /// (rigid bodies). The world's bodies must keep their indices (sort_every 0).
  std::vector<Body> reference;
  /// The particle of each body: the smallest body index of the bodies its bonds join as built
  /// (dem::fragments of the intact specimen).
  std::vector<int> particles;
  std::vector<SievedPiece> initial_grading;
  std::vector<double> sieves;
  /// Bounds of the size classes (volume-equivalent diameters of the particles, m, ascending,
  /// kBreakageClasses + 1 of them) whose fractions of broken particles the rows carry.
  std::vector<double> class_bounds;
  BreakageLimits breakage_limits;
};

/// The first entry of `holds` (ElementTestSettings::hold_stresses) that does not rise above the
/// one before it (the first above `confining`) or lies above `final_stress`; −1 when all are in
/// order.
int first_hold_out_of_order(const std::vector<double>& holds, double confining,
                            double final_stress);

/// Size classes of a crushable specimen's particles whose broken fractions are tracked.
inline constexpr int kBreakageClasses = 4;

/// One row of the curve. Strains and stresses compression positive; strains from the start of
/// loading (the end of consolidation). `interior_axial_strain` is the axial strain of the
/// middle half of the height, between the quarter heights of the platens: 1 − exp(−Σ rate·dt)
/// over the loading's steps, rate = interior_axial_strain_rate (dem/measure/strain_rate.h) —
/// free of the platens' boundary layers as an on-sample gauge of a laboratory test is of the
/// bedding error.
struct CurveRow {
  long long step = 0;
  double axial_strain = 0, volumetric_strain = 0;
  double axial_stress = 0, lateral_stress = 0, p = 0, q = 0;
  double porosity = 0, coordination = 0, unbalanced = 0;
  double interior_axial_strain = 0;
  /// 0 while loading; 1 a row within a hold (ElementTestSettings::hold_stresses); 2 the row
  /// that ends a hold at equilibrium, 3 one that ends it at max_hold_steps.
  double held = 0;
  /// Breakage (ElementTestSettings::initial_grading given; else 0): bonds with every point
  /// failed, fragments (bodies joined by intact bonds), particles of the specimen
  /// (ElementTestSettings::particles) in more than one fragment, and the indices against the
  /// initial grading; the broken bonds by how they failed (dem::failure_mode).
  double bonds_broken = 0, fragments = 0, particles_broken = 0;
  double bonds_mode_i = 0, bonds_mode_ii = 0, bonds_mixed = 0;
  double hardin_br = 0, einav_b = 0, marsal_bg = 0;
  /// Fraction of each size class's particles that are broken (class_bounds; 0 for an empty
  /// class).
  std::array<double, kBreakageClasses> broken_by_class{};
};

/// The breakage columns of `row` for the world's bodies and bonds (settings as above).
void measure_breakage(const World& world, const ElementTestSettings& settings, CurveRow& row);

/// Where a test is: everything besides the world that its later steps depend on, so a test
/// stopped between two records (or consolidation checks) and saved with its world continues to
/// the same bytes.
struct ElementTestState {
  enum class Phase { start, consolidation, loading, done };
  Phase phase = Phase::start;
  long long consolidation_steps = 0;
  bool consolidated = false;  ///< equilibrium reached within max_consolidation_steps
  long long loading_steps = 0;
  double start_height = 0;          ///< cell height when the test began (m): the speed limit
  double height0 = 0, volume0 = 0;  ///< at the end of consolidation: the strains' origin
  double solid_volume = 0;          ///< Σ body volumes (m³)
  double test_friction = 0;         ///< μ of the loading
  double interior_strain = 0;       ///< Σ rate·dt of CurveRow::interior_axial_strain so far
  int next_hold = 0;                ///< the hold_stresses entry reached next (or being held)
  bool holding = false;             ///< the platen is holding hold_stresses[next_hold]
  long long hold_steps = 0;         ///< steps of the hold so far
  std::vector<CurveRow> curve;
};

/// What a path's controls read at a loading step.
struct LoadingStep {
  const World& world;
  const TestCell& cell;
  const ElementTestSettings& settings;
  const ElementTestState& state;
  double stress_rate;   ///< Pa/s of a stress ramp
  double dt;            ///< time step (s)
  double platen_speed;  ///< closing speed of a strain-driven platen (m/s)
};

/// How an element test's walls are driven while loading, and when the loading ends: one path per
/// test kind, defined in dem/lab/loading_paths.cpp. A new test kind is a new path there (and its
/// entry in the job's registry, io/pipeline/test_kinds.cpp); run_element_test reads nothing
/// else of the kind.
struct LoadingPath {
  const char* name;
  /// The top platen closes at the strain rate (sped up to hold an inertial number, when one is
  /// set); false: the walls follow a stress ramp at stress_rate.
  bool strain_driven;
  /// Ends at final_stress, which must then exceed the confining stress; false: at
  /// max_axial_strain, which must then be positive.
  bool ends_at_final_stress;
  /// Takes hold_stresses: the platen stops at each and its servo holds the stress.
  bool holds;
  /// The walls' controls of the next step.
  void (*controls)(const LoadingStep& at, Control& axial, Control& lateral);
  /// Whether the loading has reached its end at the recorded row (holds aside).
  bool (*done)(const ElementTestSettings& s, const CurveRow& row);
  /// How far the loading is at the row: 0 at the consolidated state, 1 at the end (unclamped).
  double (*progress)(const ElementTestSettings& s, const CurveRow& row);
  /// The planned duration of the loading (s), of which the step cap is four times.
  double (*duration)(const ElementTestSettings& s, double stress_rate);
};

/// All walls follow a stress ramp from the confining stress to final_stress.
extern const LoadingPath kIsotropicPath;
/// The lateral walls fixed, the top platen driven to final_stress (holding at hold_stresses).
extern const LoadingPath kOedometerPath;
/// The lateral stress held at the confining stress, the top platen driven to max_axial_strain.
extern const LoadingPath kTriaxialPath;
/// The mean stress p′ = (σa + 2σr)/3 held at the confining stress while the top platen is
/// driven to max_axial_strain: the lateral servo's target is σr = (3p′ − σa)/2 from the axial
/// stress before each step (never below 0), the path of a stress-path cell's constant-p′ test.
extern const LoadingPath kConstantMeanStressPath;

/// What a test produced.
struct ElementTestResult {
  long long consolidation_steps = 0;
  bool consolidated = false;  ///< equilibrium reached within max_consolidation_steps
  std::vector<CurveRow> curve;
  double solid_volume = 0;  ///< Σ body volumes (m³)
  bool stopped = false;     ///< ended early by the stop callback
  bool resumed = false;     ///< continued from a stored checkpoint (the staged run)
};

/// Consolidates the specimen in `cell` isotropically to the confining stress (servo on every
/// wall, gravity as the world has it), then loads it along settings.path: isotropic — all walls
/// follow a stress ramp to final_stress; oedometer — lateral walls fixed, top platen at
/// strain_rate until final_stress, held at each of hold_stresses on the way; triaxial — lateral
/// stress held by servo, top platen at strain_rate to max_axial_strain; triaxial-p — the same
/// with the mean stress held instead of the lateral one. `stop` is asked every 1,000 consolidation
/// steps, at the consolidated state (state.phase loading, one curve row) and every record; it ends
/// the test early when true. Deterministic: the same world and settings give the same curve for any
/// thread count.
ElementTestResult run_element_test(World& world, const TestCell& cell,
                                   const ElementTestSettings& settings,
                                   const std::function<bool()>& stop = {});

/// The same, continuing from `state` (a fresh one starts the test) and leaving in it where the
/// test stopped: Phase::done at the end, else the phase to continue with the saved world.
ElementTestResult run_element_test(World& world, const TestCell& cell,
                                   const ElementTestSettings& settings, ElementTestState& state,
                                   const std::function<bool()>& stop = {});

/// A specimen in its test cell: the world (bodies, the cell's walls, options with the time step)
/// and the cell.
struct CellSpecimen {
  World world;
  TestCell cell;
};

/// The element test as the resumable stage "test" of control.store (dem/run/stage_store.h),
/// opened with `fingerprint` (of everything that decides the result): when the store holds a
/// running checkpoint of the stage, `specimen` is replaced by its world and cell and the test
/// continues from its state; else it starts on `specimen`. A checkpoint is saved every
/// control.checkpoint_every_seconds and when the interrupter, told "test" and the fraction done
/// (consolidation the first tenth), asks to stop; then Interrupted is thrown. `consolidated`,
/// when set, is called once at the consolidated state (not by a run resumed past it). A resumed
/// test ends with the same curve, bit for bit, as one never stopped.
ElementTestResult run_element_test(
    CellSpecimen& specimen, const ElementTestSettings& settings, const StageControl& control,
    const std::string& fingerprint,
    const std::function<void(const CellSpecimen&, const ElementTestState&)>& consolidated = {});

/// What a checkpoint of the staged test keeps besides the world: every field of `state` (numbers
/// exact), the cell's walls and the curve so far ("curve.000000", … : eleven numbers per row).
StageRecord element_test_record(const ElementTestState& state, const TestCell& cell);

/// The state and cell of element_test_record. Throws InvalidInput naming `where` for a missing
/// or malformed entry.
void read_element_test_record(const StageRecord& record, const std::string& where,
                              ElementTestState& state, TestCell& cell);

/// Tangent modulus dy/dx of the least-squares line through the rows whose `x_of` (stress) lies
/// in [lo, hi]: the bulk modulus (p against ε_v) or the constrained modulus (σ_a against ε_a).
/// NaN with fewer than 3 rows there.
double tangent_modulus(const std::vector<CurveRow>& curve, double (*stress)(const CurveRow&),
                       double (*strain)(const CurveRow&), double lo, double hi);

/// Mobilised friction angle (degrees) of a triaxial row: asin((σ_a − σ_r)/(σ_a + σ_r)).
double friction_angle(const CurveRow& row);

}  // namespace clumpkit::dem
