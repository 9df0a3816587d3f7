// Live changes of the controller node's settings (dynamic_reconfigure),
// checked by the start-up rules, ROS-free: a value is taken as the user
// gave it (no clamp), and a refusal names the key, that value and what is
// accepted; the settings in force are then left as they were.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_control/params/yaml_reader.h"
#include "aurora_control/predictor/predictor_yaml.h"

namespace aurora_control {

struct LiveChange {
  std::string name;  // kp, kd, delay_samples, k1_x ... k2_psi, the link's, predictor (parameter_table.h)
  double value;
  std::string word;  // a word setting's value (predictor: off, resimulate, smith)
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

// The link value a live setting names (link.h's LinkValue, in the table's
// row order from kRowUplinkJitter), or -1.
inline int linkValueIndex(const std::string& name) {
  const ParameterSpec* row = rowOfLiveSetting(name);
  if (row == nullptr) return -1;
  const long i = row - &kParameterTable[kRowUplinkJitter];
  return i >= 0 && i < kLinkValueCount ? static_cast<int>(i) : -1;
}
inline bool isLinkSetting(const std::string& name) { return linkValueIndex(name) >= 0; }
// The link's live settings, comma separated (the table's names).
inline std::string linkSettingNames() {
  std::vector<std::string> names;
  for (int i = 0; i < kLinkValueCount; ++i) names.push_back(kParameterTable[kRowUplinkJitter + i].live);
  return joinKeys(names);
}
static_assert(kRowDownlinkBurst - kRowUplinkJitter + 1 == kLinkValueCount, "one table row per LinkValue, in order");

// The link with change c applied (setLinkValue: a jitter set on a link
// without a kind is uniform).
inline LinkParams withLinkChange(LinkParams l, const LiveChange& c) {
  setLinkValue(l, linkValueIndex(c.name), c.value);
  return l;
}

// A link value: the table's range, whole samples where it counts samples,
// the burst's bound on the loss, the latency within the history.
inline std::string linkProblem(const LoopSettings& now, const LiveChange& c) {
  const ParameterSpec& row = *rowOfLiveSetting(c.name);
  const std::string range = rangeProblem(c, row.min, row.max, row.unit[0] ? row.unit : std::string("a value"));
  if (!range.empty()) return range;
  if (row.kind == ParamKind::kWholeSamples && c.value != std::floor(c.value)) {
    return c.name + " = " + YamlReader::fmt(c.value) + " is refused: accepted whole samples";
  }
  const LinkParams next = withLinkChange(now.link, c);
  for (const LinkDirection* d : {&next.uplink, &next.downlink}) {
    const std::string chain = burstLossRefusal(*d);
    if (!chain.empty()) return c.name + " = " + YamlReader::fmt(c.value) + ": the loss " + YamlReader::fmt(d->loss) + " " + chain;
  }
  if (next.historyNeeded(now.delay) > kMaxDelaySamples) {
    return c.name + " = " + YamlReader::fmt(c.value) + " is refused: the delay plus the jitter would exceed the " +
           "history of " + std::to_string(kMaxDelaySamples) + " samples";
  }
  return "";
}

}  // namespace live_detail

// "" when `c` may be applied to `now`, else the refusal. `task_steps`: the
// task's steps (taskStepCount), which a delay must be shorter than.
// A change of what every law's loop has: the delay, the link, the
// predictor. False for another setting (a law's gain).
inline bool loopSettingProblem(const LoopSettings& now, const LiveChange& c, long task_steps, std::string& problem) {
  using namespace live_detail;
  if (c.name == "delay_samples") return problem = delayProblem(c, task_steps, now.Ts), true;
  if (isLinkSetting(c.name)) return problem = linkProblem(now, c), true;
  if (c.name != kParameterTable[kRowPredictorForm].live) return false;
  PredictorForm form;
  problem = predictorFormOf(c.word, form) ? "" : c.name + " = '" + c.word + "' is refused: " + acceptedPredictorForms();
  return true;
}

inline std::string checkLiveChange(const ControllerSettings& now, const LiveChange& c, long task_steps) {
  using namespace live_detail;
  std::string problem;
  if (loopSettingProblem(now, c, task_steps, problem)) return problem;
  const bool pd = gainIndex(LawType::kPdSaturated, c.name) >= 0;
  const bool ua = gainIndex(LawType::kUnderactuated, c.name) >= 0;
  if (!pd && !ua) {
    return "'" + c.name + "' is not a live setting: accepted delay_samples, " +
           joinKeys(lawGainNames(now.law)) + " (the " + lawName(now.law) + " law's gains), the link's " +
           linkSettingNames() + ", predictor";
  }
  const LawType law = pd ? LawType::kPdSaturated : LawType::kUnderactuated;
  if (law != now.law) {
    const int i = gainIndex(law, c.name);
    ControllerSettings other = now;
    other.law = law;
    if (c.value == lawGain(other, i)) return "";  // a dump of the whole server loaded back: no change
    return c.name + " = " + YamlReader::fmt(c.value) + " is refused: a gain of the " + lawName(law) +
           " law, but this node flies the " + lawName(now.law) + " law (accepted: " +
           joinKeys(lawGainNames(now.law)) + ", delay_samples, the link's " + linkSettingNames() + ")";
  }
  return pd ? rangeProblem(c, kPdGainMin, kPdGainMax, "a gain")
            : rangeProblem(c, kUnderactuatedGainMin, kUnderactuatedGainMax, "a gain");
}

// Applies a delay, link or predictor change checkLiveChange() accepted;
// false for a gain.
inline bool applyLoopChange(LoopSettings& set, const LiveChange& c) {
  if (c.name == "delay_samples") {
    set.delay = static_cast<long>(c.value);
    return true;
  }
  if (live_detail::isLinkSetting(c.name)) {
    set.link = live_detail::withLinkChange(set.link, c);
    return true;
  }
  if (c.name != kParameterTable[kRowPredictorForm].live) return false;
  predictorFormOf(c.word, set.predictor);  // checked by checkLiveChange
  return true;
}

// Applies a change checkLiveChange() accepted.
inline void applyLiveChange(ControllerSettings& set, const LiveChange& c) {
  if (applyLoopChange(set, c)) return;
  const int i = live_detail::gainIndex(set.law, c.name);
  if (i >= 0) lawGain(set, i) = c.value;  // the other law's unchanged gain: nothing to do
}

// Another vehicle's law (other_laws.h): its delay and link change live; its
// gains come from its controller file. The AR.Drone's gains the server shows
// (their defaults: ardroneGainsShown) load back unchanged.
template <class Law>
std::string checkLiveChange(const LawSettings<Law>& now, const LiveChange& c, long task_steps) {
  using namespace live_detail;
  std::string problem;
  if (loopSettingProblem(now, c, task_steps, problem)) return problem;
  const ControllerSettings shown;
  for (LawType law : {LawType::kPdSaturated, LawType::kUnderactuated}) {
    ControllerSettings as = shown;
    as.law = law;
    const int i = gainIndex(law, c.name);
    if (i >= 0 && c.value == lawGain(as, i)) return "";  // a dump of the whole server loaded back
  }
  return "'" + c.name + "' = " + YamlReader::fmt(c.value) + " is refused: this node flies the " + Law::name() +
         " law, whose gains come from its controller file (restart with another); live: delay_samples, the link's " +
         linkSettingNames() + ", predictor";
}

template <class Law>
void applyLiveChange(LawSettings<Law>& set, const LiveChange& c) {
  applyLoopChange(set, c);
}

}  // namespace aurora_control
