// Accepted ranges shared by every entry point (controller node, replay, the
// flight tool, the sweep, the live settings), from the one parameter table
// (parameter_table.h), so that they agree.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include "aurora_control/params/parameter_table.h"

namespace aurora_control {

// Feedback delay [samples of Ts]: 0 to 2047 (68 s at 30 Hz). Histories hold
// kDelayHistory states so the largest delay still finds its sample.
constexpr long kMaxDelaySamples = static_cast<long>(kParameterTable[kRowDelaySamples].max);
constexpr int kDelayHistory = static_cast<int>(kMaxDelaySamples) + 1;

// The history capacities the loops are compiled for: the smallest that holds
// `max_delay` (a short history keeps a batch of lanes in cache). Calls
// f(std::integral_constant<int, capacity>()); every runner and sweep backend
// picks its capacity here (the SIMD engine's rings take it at run time);
// the CUDA backend compiles the two tiers below the full history.
constexpr int kShortHistory = 64, kMediumHistory = 512;
constexpr int historyCapacity(long max_delay) {
  return max_delay < kShortHistory ? kShortHistory : max_delay < kMediumHistory ? kMediumHistory : kDelayHistory;
}
template <class F>
void withHistoryCapacity(long max_delay, F&& f) {
  switch (historyCapacity(max_delay)) {
    case kShortHistory: return f(std::integral_constant<int, kShortHistory>());
    case kMediumHistory: return f(std::integral_constant<int, kMediumHistory>());
    default: return f(std::integral_constant<int, kDelayHistory>());
  }
}

// A delay must be shorter than the run: the delay rule sends the current
// state while k <= d, so with d at least the run's iteration count the
// delayed state never reaches the controller and the run equals one without
// delay. Every entry point (sweep, node, replay) refuses it with this text.
inline bool delayShorterThanRun(long delay, long iterations) { return delay < iterations; }
// `iterations`: the run's steps 0..iterations-1 (the node, replay and
// flight: taskStepCount; the sweep: studyIterationCount).
inline std::string delayRunText(long delay, long iterations, double Ts) {
  char run[96];
  std::snprintf(run, sizeof run, " steps (t = 0 to %.4g s at Ts = %.4g s)", (iterations - 1) * Ts, Ts);
  return std::to_string(delay) + " samples is not shorter than the run's " + std::to_string(iterations) +
         run + ": the delayed state would never reach the controller, the run would equal one without "
         "delay; accepted delays up to " + std::to_string(iterations - 1) + " samples for this task";
}

inline std::string delayRangeText() { return "integer samples in [0, " + std::to_string(kMaxDelaySamples) + "]"; }

// The one delay parse of every entry point (docs/architecture.md, "The
// parameter table"): `value` in whole samples, or in seconds (in_seconds),
// rounded once to whole samples of Ts; either way then within [0,
// kMaxDelaySamples]. Sets `samples` and returns "", or returns the refusal,
// to follow "KEY = VALUE " (the task's length is checked after, with
// delayShorterThanRun).
inline std::string delayRefusal(double value, bool in_seconds, double Ts, long& samples) {
  const double max = double(kMaxDelaySamples);
  if (in_seconds) {
    char range[64];
    std::snprintf(range, sizeof range, "[0, %g] s (%ld samples of Ts = %g s)", max * Ts, kMaxDelaySamples, Ts);
    if (!std::isfinite(value) || value < 0 || std::lround(value / Ts) > kMaxDelaySamples) {
      return "is refused: accepted range " + std::string(range);
    }
    samples = std::lround(value / Ts);
    return "";
  }
  if (!std::isfinite(value) || value < 0 || value != std::floor(value) || value > max) {
    return "is refused: accepted " + delayRangeText();
  }
  samples = static_cast<long>(value);
  return "";
}

}  // namespace aurora_control
