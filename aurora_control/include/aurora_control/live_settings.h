// Live changes of the controller node's settings (dynamic_reconfigure),
// checked by the start-up rules, ROS-free: a value is taken as the user
// gave it (no clamp), and a refusal names the key, that value and what is
// accepted; the settings in force are then left as they were.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "aurora_control/law_yaml.h"
#include "aurora_control/limits.h"
#include "aurora_control/yaml_reader.h"

namespace aurora_control {

struct LiveChange {
  std::string name;  // kp, kd, delay_samples, k1_x ... k2_psi
  double value;
};

namespace live_detail {

// The index of `name` among `law`'s gains, or -1.
inline int gainIndex(LawType law, const std::string& name) {
  const std::vector<std::string> names = lawGainNames(law);
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

inline std::string rangeProblem(const LiveChange& c, double lo, double hi, const std::string& what) {
  if (std::isfinite(c.value) && c.value >= lo && c.value <= hi) return "";
  return c.name + " = " + YamlReader::fmt(c.value) + " is refused: accepted " + what + " in [" +
         YamlReader::fmt(lo) + ", " + YamlReader::fmt(hi) + "]";
}

inline std::string delayProblem(const LiveChange& c, long task_steps, double Ts) {
  long d = 0;
  const std::string refusal = delayRefusal(c.value, false, Ts, d);
  if (!refusal.empty()) return c.name + " = " + YamlReader::fmt(c.value) + " " + refusal;
  return delayShorterThanRun(d, task_steps) ? "" : c.name + " = " + delayRunText(d, task_steps, Ts);
}

}  // namespace live_detail

// "" when `c` may be applied to `now`, else the refusal. `task_steps`: the
// task's steps (taskStepCount), which a delay must be shorter than.
inline std::string checkLiveChange(const ControllerSettings& now, const LiveChange& c, long task_steps) {
  using namespace live_detail;
  if (c.name == "delay_samples") return delayProblem(c, task_steps, now.Ts);
  const bool pd = gainIndex(LawType::kPdSaturated, c.name) >= 0;
  const bool ua = gainIndex(LawType::kUnderactuated, c.name) >= 0;
  if (!pd && !ua) {
    return "'" + c.name + "' is not a live setting: accepted delay_samples, " +
           joinKeys(lawGainNames(now.law)) + " (the " + lawName(now.law) + " law's gains)";
  }
  const LawType law = pd ? LawType::kPdSaturated : LawType::kUnderactuated;
  if (law != now.law) {
    const int i = gainIndex(law, c.name);
    ControllerSettings other = now;
    other.law = law;
    if (c.value == lawGain(other, i)) return "";  // a dump of the whole server loaded back: no change
    return c.name + " = " + YamlReader::fmt(c.value) + " is refused: a gain of the " + lawName(law) +
           " law, but this node flies the " + lawName(now.law) + " law (accepted: " +
           joinKeys(lawGainNames(now.law)) + ", delay_samples)";
  }
  return pd ? rangeProblem(c, kPdGainMin, kPdGainMax, "a gain")
            : rangeProblem(c, kUnderactuatedGainMin, kUnderactuatedGainMax, "a gain");
}

// Applies a change checkLiveChange() accepted.
inline void applyLiveChange(ControllerSettings& set, const LiveChange& c) {
  if (c.name == "delay_samples") {
    set.delay = static_cast<long>(c.value);
    return;
  }
  const int i = live_detail::gainIndex(set.law, c.name);
  if (i >= 0) lawGain(set, i) = c.value;  // the other law's unchanged gain: nothing to do
}

}  // namespace aurora_control
