// The crushing peak of a single-particle compression curve (Hu et al. 2023 §3.2 after Huillca
// et al. 2021): the largest force before a load drop of at least 35 % with the particle split or
// collapsed; strength σ = Fp/D² (eq. 13).
#pragma once

#include "geom/range.h"

#include <cstddef>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// The load drop, as a fraction of the running peak, that marks failure (PeakRule::drop).
inline constexpr Range kPeakDrop = open(0, 1);

/// The rule's numbers.
struct PeakRule {
  double drop = 0.35;  ///< the load drop that marks failure, as a fraction of the running peak
  /// Collapse without a split: the force stays below (1 − drop) of the running peak over this
  /// much further platen travel, as a fraction of the particle's diameter. A corner crushed under
  /// a platen unloads and reloads within about 2 % of D (a 27.5 mm particle fell from 2.06 to
  /// 0.31 kN, stayed low for 0.57 mm, then carried 7 kN), so 2 % made such a corner a collapse
  /// whenever the reload came a step late; 5 % does not.
  double collapse_travel = 0.05;
  /// Travel counts toward a collapse only while the force is at least this fraction of the
  /// running peak: below it the platens are not loading the particle but brushing a chip.
  double contact = 0.1;
};

/// One sample of a crushing test: platen travel (m), force (N), whether the particle's bonded
/// cells had already come apart (crush.h: no piece holds 90 % of the mass), and whether it was
/// still whole (every cell joined by intact bonds: nothing has broken off).
struct CrushSample {
  double travel = 0.0;
  double force = 0.0;
  bool split = false;
  /// A whole particle whose force falls and stays low has tipped over or slid between the
  /// platens (an elongated one stood on its end does at friction 0.3): that is not a collapse.
  bool whole = false;
};

struct CrushPeak {
  bool found = false;
  std::size_t index = 0;     ///< sample of the peak force
  double force = 0.0;        ///< Fp (N)
  double travel = 0.0;       ///< platen travel at the peak (m)
  std::size_t detected = 0;  ///< sample where the rule was met
  std::string by;            ///< "split" or "collapse" ("" when not found)
};

/// Scans the samples in order with the running maximum F* (its first sample on ties): the peak is
/// F* at the first sample where F ≤ (1 − drop)·F* and the particle is split ("split"), or where F
/// has stayed ≤ (1 − drop)·F* over collapse_travel·D of travel with F ≥ contact·F* and the
/// particle is not whole ("collapse": a whole particle tipped over rather than collapsed;
/// the travel of a platen gone free, or pushing a loose chip aside, after the touching corner
/// cell broke off is not counted, or that chip would pass for the particle's failure). A drop that
/// recovers above (1 − drop)·F* before either is not a failure; a later, higher maximum replaces
/// F*. Throws InvalidInput for a rule outside (0, 1) / (0, 1] / [0, 1 − drop), or D not positive.
CrushPeak crushing_peak(const std::vector<CrushSample>& samples, double diameter,
                        const PeakRule& rule = {});

}  // namespace clumpkit::dem
