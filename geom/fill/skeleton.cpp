#include "geom/fill/skeleton.h"

#include <cmath>

namespace clumpkit {

std::vector<MedialCandidate> medial_candidates(const DistanceField& f, double ridge,
                                               double min_radius) {
  std::vector<MedialCandidate> out;
  const double inv_len[4] = {0.0, 1.0, 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)};
  for (int k = 1; k + 1 < f.dims[2]; ++k)
    for (int j = 1; j + 1 < f.dims[1]; ++j)
      for (int i = 1; i + 1 < f.dims[0]; ++i) {
        const double dp = f.at(i, j, k);
        if (dp <= 0.0 || dp < min_radius) continue;
        double slope = -1e300;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int n = std::abs(dx) + std::abs(dy) + std::abs(dz);
              if (n == 0) continue;
              const double s = (f.at(i + dx, j + dy, k + dz) - dp) * inv_len[n] / f.h;
              slope = std::max(slope, s);
            }
        if (slope < ridge) out.push_back(MedialCandidate{i, j, k, f.position(i, j, k), dp});
      }
  return out;
}

}  // namespace clumpkit
