// Shared by the real-drone tests: the fake driver's true positions over
// time, and the position at any time between two of them.
#pragma once

#include <algorithm>
#include <vector>

namespace aurora_tests {

struct TruthSample {
  double t;       // header stamp [s]
  double pos[3];  // [m, world frame]
};

// Position at time t (linear interpolation); false after the last sample.
inline bool positionAt(const std::vector<TruthSample>& s, double t, double out[3]) {
  for (size_t i = 1; i < s.size(); ++i) {
    if (s[i].t >= t) {
      const double a = (t - s[i - 1].t) / std::max(1e-9, s[i].t - s[i - 1].t);
      for (int k = 0; k < 3; ++k) out[k] = s[i - 1].pos[k] + a * (s[i].pos[k] - s[i - 1].pos[k]);
      return true;
    }
  }
  return false;
}

}  // namespace aurora_tests
