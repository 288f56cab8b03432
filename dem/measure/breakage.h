// Grading and breakage of a crushable assembly: sieving the fragments by their intermediate
// dimension, and the breakage indices of Hardin (1985), Einav (2007) and Marsal (1967).
#pragma once

#include <vector>

namespace clumpkit::dem {

/// A fragment for sieving: its solid volume (any unit; only fractions are used) and its
/// intermediate dimension I (m). It passes a square sieve of opening s when I < s (the smallest
/// dimension S ≤ I fits through an opening at least I wide, turned so; the long one need not).
struct SievedPiece {
  double volume = 0.0;
  double size = 0.0;
};

/// Sieve openings from `largest` down by the factor `ratio` while above `smallest`, ascending
/// (e.g. √2: the half-ϕ steps of a laboratory series). Throws InvalidInput unless 0 < smallest
/// < largest and ratio > 1.
std::vector<double> sieve_series(double smallest, double largest, double ratio);

/// The grading curve: per sieve (ascending) the fraction of the pieces' volume passing it (size
/// below the opening). Throws InvalidInput for no pieces, a piece of volume ≤ 0, a size < 0 or
/// a value that is not finite.
std::vector<double> passing(const std::vector<SievedPiece>& pieces,
                            const std::vector<double>& sieves);

/// The sizes that bound the breakage indices (m).
struct BreakageLimits {
  /// Hardin's (1985) silt limit: no breakage potential below the No. 200 sieve (0.074 mm); also
  /// Einav's smallest size d_m, the lower end of the areas in the semi-log grading plot.
  double silt = 7.4e-5;
  /// Dimension of Einav's ultimate (fractal) grading F_u(d) = (d/d_M)^(3 − D) (Einav 2007 after
  /// Sammis et al. 1987 and Coop et al. 2004: D ≈ 2.5).
  double fractal_dimension = 2.5;
};

/// Hardin's (1985) relative breakage Br = B_t/B_p0: the breakage potential of a grading, B_p =
/// ∫ log10(d/silt) dF over the sizes above the silt limit (the area between the grading curve,
/// the line F = 1 and the silt sieve in the semi-log plot), here summed over the pieces
/// themselves (the curve of infinitely many sieves: no sieve set enters); B_t = B_p0 − B_p. 0
/// for an unbroken assembly, 1 when all is silt. Throws InvalidInput as `passing` does, or for
/// an initial grading without potential (nothing above the silt limit).
double hardin_breakage(const std::vector<SievedPiece>& initial,
                       const std::vector<SievedPiece>& current, const BreakageLimits& limits = {});

/// Einav's (2007) relative breakage B: the area between the current and the initial grading
/// over that between the ultimate and the initial one, B = ∫(F − F0) / ∫(F_u − F0), both in the
/// semi-log plot between the silt limit d_m and d_M, the largest initial piece. A current
/// grading F = (1 − B)·F0 + B·F_u (Einav's assumption) gives B back for any measure of the
/// area. Exact for the pieces (step curves). Throws as hardin_breakage.
double einav_breakage(const std::vector<SievedPiece>& initial,
                      const std::vector<SievedPiece>& current, const BreakageLimits& limits = {});

/// Marsal's (1967) breakage factor Bg: the sum of the positive drops of the fraction retained
/// between consecutive sieves (and above the largest, below the smallest), initial minus
/// current, as a fraction of the volume (Marsal's percent / 100). Depends on the sieve set, as
/// Marsal's does. Throws as `passing`.
double marsal_breakage(const std::vector<SievedPiece>& initial,
                       const std::vector<SievedPiece>& current, const std::vector<double>& sieves);

}  // namespace clumpkit::dem
