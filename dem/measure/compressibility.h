// One-dimensional compressibility from an e–log σv curve: the compression index over a stress
// range and the yield stress at the knee (a bilinear fit in e–log σv).
#pragma once

#include <vector>

namespace clumpkit::dem {

/// The compression index Cc = −de/d(log10 σ): minus the slope of the least-squares line of the
/// void ratios e against log10 of the stresses σ (Pa) in [lo, hi]. NaN with fewer than 3 points
/// there. `e` and `sigma` have the same length.
double compression_index(const std::vector<double>& e, const std::vector<double>& sigma, double lo,
                         double hi);

/// The knee of e–log σv: two least-squares lines in (log10 σ, e), the first through the points
/// up to a break and the second through those after it (at least 3 each), the break chosen for
/// the least total squared error (ties: the first); the yield stress is σ where the lines
/// cross (10^x). Points with σ ≤ 0 are left out. NaN with fewer than 6 points or parallel lines.
/// A laboratory reads the same knee with Casagrande's construction; the bilinear fit needs no
/// judgement of the point of maximum curvature (Butterfield 1979 fits ln(1 + e) the same way).
double yield_stress(const std::vector<double>& e, const std::vector<double>& sigma);

}  // namespace clumpkit::dem
