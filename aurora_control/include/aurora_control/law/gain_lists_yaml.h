// A law's gains as lists over axes in its controller file (`kp: [x, y, z,
// yaw]`), written once per law (its gainGroups) for the reader, for the
// names the node publishes (namedGains) and for replay (gainSlots): what
// the Bebop 2's and the Pioneer's readers share (docs/architecture.md,
// "Laws"). Host only.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

// One gain list of a controller mapping: `<at>.<key>` (at: "controller" in
// a controller file), one number per axis of its group.
struct GainList {
  const char* key;
  double* into;
};

// Gain lists over the same axes (e.g. x, y, z, yaw): a law's gains as its
// controller file gives them, written once per law (gainGroups) for the
// reader and for the names the node publishes (namedGains).
struct GainGroup {
  std::vector<GainList> lists;
  std::vector<std::string> axes;
};

inline std::string axesText(const std::vector<std::string>& axes) {
  std::string text;
  for (size_t i = 0; i < axes.size(); ++i) text += (i ? ", " : "") + axes[i];
  return text;
}

inline void readGainLists(const YamlReader& r, const YAML::Node& c, const std::string& at, const GainGroup& group,
                          double max) {
  const size_t n = group.axes.size();
  const std::string text = "a list of " + std::to_string(n) + " numbers in [0, " + YamlReader::fmt(max) + "] (" +
                           axesText(group.axes) + ")";
  for (const GainList& g : group.lists) {
    const std::string key = r.key(at, g.key);
    const std::vector<double> v = r.numbers(r.require(c, at, g.key, text), key, n, text);
    for (size_t i = 0; i < n; ++i) {
      g.into[i] = v[i];
      if (!(v[i] >= 0.0 && v[i] <= max)) r.fail(key, "must be " + text);
    }
  }
}

// Every gain of a law by name, `<key>_<axis>` (ksp_x ... kd_yaw) in its
// file's order, then its extras: the controller node's Control.gain_names
// and its log; replay reads them back (law_settings_yaml.h's setGainsNamed).
template <class Gains>
std::vector<std::pair<std::string, double*>> gainSlots(Gains& g) {
  std::vector<std::pair<std::string, double*>> out;
  for (const GainGroup& group : gainGroups(g)) {
    for (const GainList& list : group.lists) {
      for (size_t i = 0; i < group.axes.size(); ++i) out.emplace_back(std::string(list.key) + "_" + group.axes[i], list.into + i);
    }
  }
  for (const auto& extra : gainExtras(g)) out.emplace_back(extra.first, extra.second);
  return out;
}

template <class Gains>
std::vector<std::pair<std::string, double>> namedGains(Gains g) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& slot : gainSlots(g)) out.emplace_back(slot.first, *slot.second);
  return out;
}

}  // namespace aurora_control
