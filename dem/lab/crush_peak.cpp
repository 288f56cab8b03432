#include "dem/lab/crush_peak.h"

#include "geom/errors.h"
#include "geom/format.h"

namespace clumpkit::dem {

CrushPeak crushing_peak(const std::vector<CrushSample>& samples, double diameter,
                        const PeakRule& rule) {
  require(kPeakDrop, rule.drop, "crushing peak: drop");
  if (!(rule.collapse_travel > 0.0 && rule.collapse_travel <= 1.0))
    throw InvalidInput("crushing peak: collapse travel must be in (0, 1], got " +
                       format_number(rule.collapse_travel));
  if (!(rule.contact >= 0.0 && rule.contact < 1.0 - rule.drop))
    throw InvalidInput("crushing peak: contact must be in [0, 1 − drop), got " +
                       format_number(rule.contact));
  if (!(diameter > 0.0))
    throw InvalidInput("crushing peak: diameter must be positive, got " + format_number(diameter));
  CrushPeak p;
  std::size_t best = 0;
  bool low = false;  // below (1 − drop)·F* since sample `low_from`
  std::size_t low_from = 0;
  double free_travel = 0.0;  // travel since then with the platens not loading the particle
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const CrushSample& s = samples[i];
    if (s.force > samples[best].force) best = i;
    const bool below =
        s.force <= (1.0 - rule.drop) * samples[best].force && samples[best].force > 0;
    if (!below) {
      low = false;
      continue;
    }
    if (!low) {
      low = true;
      low_from = i;
      free_travel = 0.0;
    } else if (!(s.force >= rule.contact * samples[best].force)) {
      free_travel += s.travel - samples[i - 1].travel;
    }
    const bool collapsed = !s.whole && s.travel - samples[low_from].travel - free_travel >=
                                           rule.collapse_travel * diameter;
    if (s.split || collapsed) {
      p.found = true;
      p.index = best;
      p.force = samples[best].force;
      p.travel = samples[best].travel;
      p.detected = i;
      p.by = s.split ? "split" : "collapse";
      return p;
    }
  }
  return p;
}

}  // namespace clumpkit::dem
