// The throughput of the last `window` seconds, for a progress ETA. Early-stop
// runs finish faster later in a sweep (and a machine's load changes), so the
// rate since the start overestimates the time left; the recent rate does not.
#pragma once

#include <deque>
#include <utility>

namespace aurora_sweep {

class RecentRate {
 public:
  // done_at_start: items already done at t = 0 (a resumed run's chunks), so
  // they do not count as throughput.
  explicit RecentRate(double window = 10.0, long done_at_start = 0)
      : window_(window), samples_{{0.0, done_at_start}} {}

  // t [s] since the start, done: items finished by then. Returns items/s over
  // the last `window` seconds (over everything while less has passed).
  double add(double t, long done) {
    samples_.emplace_back(t, done);
    while (samples_.size() > 2 && samples_[1].first <= t - window_) samples_.pop_front();
    const auto& first = samples_.front();
    const double dt = t - first.first;
    return dt > 0 ? (done - first.second) / dt : 0.0;
  }

 private:
  double window_;
  std::deque<std::pair<double, long>> samples_;
};

}  // namespace aurora_sweep
