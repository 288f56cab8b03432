// The cone penetration test: a specimen consolidated in its cell, then a cone probe pushed down
// its axis at constant speed with the cell's stresses held (CTGU 2017's chamber, boundary BC1).
#pragma once

#include "dem/lab/element_loading.h"
#include "geom/range.h"

#include <functional>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// The probe's shaft diameter (m), push speed (m/s) and push distance (m) a test takes.
inline constexpr Range kProbeDiameter = above(0);
inline constexpr Range kProbeVelocity = above(0);
inline constexpr Range kProbeDepth = above(0);
/// The cone's apex angle (degrees): 180 would be a flat end.
inline constexpr Range kProbeApex = open(0, 180);

/// The probe and its push (SI).
struct ProbeSettings {
  double diameter = 0.018;  ///< shaft diameter D_c (m)
  double apex_deg = 60.0;   ///< apex angle of the cone (degrees)
  double velocity = 0.02;   ///< push speed (m/s)
  double depth = 0.15;      ///< push distance below the specimen's top (m)
  double friction = -1.0;   ///< μ of probe–sphere contacts (negative: the test's)
};

/// The whole test: consolidation (as an element test's: confining, friction,
/// consolidation_friction, consolidation_tolerance, consolidation_unbalanced,
/// max_consolidation_steps, gain, servo_strain_rate, record_every), then the push.
struct CptSettings {
  ElementTestSettings cell;
  ProbeSettings probe;
};

/// One row of the CPT curve. Forces are those of the spheres on the probe, positive upwards (the
/// soil's resistance to the push), for the whole chamber (a segment's × 2π / angle); qc = tip force
/// / (π D_c² / 4); fs = sleeve force over the shaft's area below the specimen's top, 2π (D_c/2) L
/// (0 while L = 0).
struct CptRow {
  long long step = 0;
  double depth = 0;  ///< the apex's travel below the specimen's top at the push's start (m)
  double tip_force = 0, sleeve_force = 0;       ///< N
  double qc = 0, fs = 0;                        ///< Pa
  double axial_stress = 0, lateral_stress = 0;  ///< the cell's (Pa), held at the confining stress
};

/// Where a CPT is, so a test stopped between two records and saved with its world continues to
/// the same bytes.
struct CptState {
  enum class Phase { start, consolidation, push, done };
  Phase phase = Phase::start;
  long long consolidation_steps = 0;
  bool consolidated = false;
  long long push_steps = 0;
  double start_height = 0;  ///< cell height when the test began (m): the servo's speed limit
  double test_friction = 0;
  double apex0 = 0;  ///< the apex's height at the start of the push: the specimen's top (m)
  int probe = -1;    ///< the probe's wall index (added at the start of the push)
  bool reached_bottom = false;  ///< the push ended early: the apex came within D_c of the bottom
  std::vector<CptRow> curve;
};

/// What a CPT produced.
struct CptResult {
  long long consolidation_steps = 0;
  bool consolidated = false;
  bool reached_bottom = false;
  std::vector<CptRow> curve;
  bool stopped = false;
  bool resumed = false;
};

/// Throws InvalidInput "probe.FIELD must be ..., got V" for a probe that is none: a diameter,
/// velocity or depth not positive and finite, an apex angle outside (0, 180) degrees. The one
/// check of the probe's own values (recipes call it on their [probe] section, validate_cpt on
/// its settings).
void validate_probe(const ProbeSettings& probe);

/// Throws InvalidInput "probe.diameter D m is wider than half the cell (width W m)" unless
/// the probe's diameter is at most half the `width` of its chamber (a cylinder's diameter, a
/// cuboid's narrower side): the one rule of the probe's room, validate_cpt's and the LAMMPS
/// export's.
void check_probe_width(const ProbeSettings& probe, double width);

/// Throws InvalidInput where the specimen is zoned radially with a core of small particles of
/// radius `core_radius` (0: not zoned so) and the probe is wider than that core or the core is
/// under 4 probe diameters (CTGU 2017 sizes the core at 4 probe diameters, 75 mm for 18 mm, so
/// that the zone the cone disturbs stays in fine material). validate_cpt's check; the LAMMPS
/// export's too.
void check_probe_core(const ProbeSettings& probe, double core_radius);

/// Throws InvalidInput when a segment of `angle` radians about the vertical `axis` keeps the
/// bodies near it (the largest sphere within two probe diameters of the shaft) so far from the
/// axis that the probe reaches less than one of them past that gap: it would barely touch the
/// particles. validate_cpt's check for segments; the LAMMPS export's too.
void check_segment_reach(const std::vector<Body>& bodies, const Vec3& axis, double angle,
                         const ProbeSettings& probe);

/// Throws InvalidInput for a probe that cannot be pushed in `cell`: validate_probe's cases, a
/// probe wider than half the cell, one that a segment's walls keep off the particles, or, where
/// the specimen is zoned radially with a core of small particles of radius `core_radius` (0: not
/// zoned), a probe wider than that core or a core under 4 probe diameters (CTGU 2017 sizes the
/// core at 4 probe diameters, 75 mm for 18 mm, so that the zone the cone disturbs stays in fine
/// material).
void validate_cpt(const World& world, const TestCell& cell, const CptSettings& settings,
                  double core_radius = 0.0);

/// Consolidates the specimen isotropically to the confining stress (consolidate_cell), then adds
/// a probe on the cell's axis with its apex at the top platen and pushes it down at its speed,
/// the platens and the lateral walls under servo control at the confining stress, until the
/// apex has travelled `depth` (or comes within one probe diameter of the bottom platen). A row
/// every record_every steps. `stop` is asked as by run_element_test. Deterministic for any
/// thread count.
CptResult run_cpt(World& world, const TestCell& cell, const CptSettings& settings, CptState& state,
                  const std::function<bool()>& stop = {});

/// The CPT as the resumable stage "cpt" of control.store, as run_element_test's staged form: a
/// resumed test ends with the same curve, bit for bit, as one never stopped. `consolidated`, when
/// set, is called once with the specimen at the end of its consolidation (the probe added, not
/// yet moved), as run_element_test's.
CptResult run_cpt(
    CellSpecimen& specimen, const CptSettings& settings, const StageControl& control,
    const std::string& fingerprint,
    const std::function<void(const CellSpecimen&, const CptState&)>& consolidated = {});

/// What a checkpoint of the staged CPT keeps besides the world, and its reader (throws
/// InvalidInput naming `where` for a missing or malformed entry).
StageRecord cpt_record(const CptState& state, const TestCell& cell);
void read_cpt_record(const StageRecord& record, const std::string& where, CptState& state,
                     TestCell& cell);

}  // namespace clumpkit::dem
