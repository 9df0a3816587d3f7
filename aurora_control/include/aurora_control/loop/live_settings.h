// Live changes of the controller node's settings (dynamic_reconfigure),
// checked by the start-up rules, ROS-free: a value is taken as the user
// gave it (no clamp), and a refusal names the key, that value and what is
// accepted; the settings in force are then left as they were.
#pragma once

#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "aurora_control/loop/controller_parameters.h"
#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_control/params/yaml_reader.h"
#include "aurora_control/predictor/predictor_yaml.h"

namespace aurora_control {

struct LiveChange {
  std::string name;  // a live law's gain, delay_samples, the link's, predictor (controller_parameters.h)
  double value;
  std::string word;  // a word setting's value (predictor: off, resimulate, smith)
};

namespace live_detail {

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

namespace live_detail {

// The row of Law named `name`, or -1.
template <class Law>
int rowIndex(const std::string& name) {
  for (int i = 0; i < Law::kGainCount; ++i) {
    if (name == Law::gainRow(i).name) return i;
  }
  return -1;
}

template <class Law>
std::vector<std::string> rowNames() {
  std::vector<std::string> names;
  for (int i = 0; i < Law::kGainCount; ++i) names.push_back(Law::gainRow(i).name);
  return names;
}

// The gains the server shows for live law Live: this loop's, where Live is
// of its family; else Live's preset.
template <class Live, class Data>
typename Live::template Gains<double> shownGains(std::true_type, const LawSettings<Data>& set) {
  return set.gains;
}
template <class Live, class Data>
typename Live::template Gains<double> shownGains(std::false_type, const LawSettings<Data>&) {
  return presetGains<typename Live::Data>();
}

// A law whose gains change live: its own gain in its row's range; a gain
// of another law of its family the server shows, unchanged (a dump of the
// whole server loaded back), or refused; any other name refused.
template <class Data, class Law>
std::string liveGainProblem(const LawSettings<Data>& now, Law, const LiveChange& c) {
  const int own = rowIndex<Law>(c.name);
  if (own >= 0) return rangeProblem(c, Law::gainRow(own).min, Law::gainRow(own).max, "a gain");
  std::string problem = "'" + c.name + "' is not a live setting: accepted delay_samples, " + joinKeys(rowNames<Law>()) +
                        " (the " + Law::name() + " law's gains), the link's " + linkSettingNames() + ", predictor";
  auto gains = now.gains;
  forEachLawOf<Data>([&](auto other) {
    using Other = decltype(other);
    const double* gain = gainsAreRows<Other>() ? gainNamed(other, gains, c.name) : nullptr;
    if (gain == nullptr) return;
    if (c.value == *gain) problem = "";
    else problem = c.name + " = " + YamlReader::fmt(c.value) + " is refused: a gain of the " + Other::name() +
                   " law, but this node flies the " + Law::name() + " law (accepted: " + joinKeys(rowNames<Law>()) +
                   ", delay_samples, the link's " + linkSettingNames() + ")";
  });
  return problem;
}

// A law whose gains come from its controller file: only the values the
// server shows for the live laws' gains (each law's preset gains) load
// back, unchanged.
template <class Law>
std::string fixedGainProblem(Law, const LiveChange& c) {
  bool shown = false;
  forEachLiveGainLaw([&](auto live) {
    auto preset = presetGains<typename decltype(live)::Data>();
    const double* gain = gainNamed(live, preset, c.name);
    shown = shown || (gain != nullptr && c.value == *gain);
  });
  if (shown) return "";
  return "'" + c.name + "' = " + YamlReader::fmt(c.value) + " is refused: this node flies the " + Law::name() +
         " law, whose gains come from its controller file (restart with another); live: delay_samples, the link's " +
         linkSettingNames() + ", predictor";
}

}  // namespace live_detail

// "" when `c` may be applied to `now`, else the refusal: the delay, the
// link and the predictor for every law; the gains of a law whose gains are
// its rows (the AR.Drone's two), in their rows' ranges.
template <class Data>
std::string checkLiveChange(const LawSettings<Data>& now, const LiveChange& c, long task_steps) {
  using namespace live_detail;
  std::string problem;
  if (loopSettingProblem(now, c, task_steps, problem)) return problem;
  now.withLawType([&](auto law) {
    problem = gainsAreRows<decltype(law)>() ? liveGainProblem(now, law, c) : fixedGainProblem(law, c);
  });
  return problem;
}

// Applies a change checkLiveChange() accepted (another law's unchanged
// gain: nothing to do).
template <class Data>
void applyLiveChange(LawSettings<Data>& set, const LiveChange& c) {
  if (applyLoopChange(set, c)) return;
  set.withLawType([&](auto law) {
    double* gain = gainsAreRows<decltype(law)>() ? gainNamed(law, set.gains, c.name) : nullptr;
    if (gain != nullptr) *gain = c.value;
  });
}

// What the reconfigure server shows of the live laws' gains, by name: the
// gains of this loop's family as set, every other live law's preset.
template <class Data>
std::vector<std::pair<std::string, double>> liveGainsShown(const LawSettings<Data>& set) {
  std::vector<std::pair<std::string, double>> out;
  forEachLiveGainLaw([&](auto live) {
    using Live = decltype(live);
    auto g = live_detail::shownGains<Live>(std::is_same<typename Live::Data, Data>(), set);
    for (const auto& slot : lawGainSlots(live, g)) out.emplace_back(slot.first, *slot.second);
  });
  return out;
}

}  // namespace aurora_control
