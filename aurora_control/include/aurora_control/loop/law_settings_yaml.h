// Every law's settings from its controller mapping (a controller file's
// 'controller:', or the node's ~controller where the launch loads it), and
// its gains by name: the controller node's and replay's one reader for the
// AR.Drone's two laws (law_yaml.h) and the other vehicles' (other_laws.h).
// ROS-free.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aurora_control/law/compensator_yaml.h"  // each law's controller-file reader, one line each
#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/law/pioneer_yaml.h"
#include "aurora_control/loop/delayed_controller.h"

namespace aurora_control {

// The mapping at `key` into `set` (set.vehicle and set.Ts already set: the
// compensator's rate must divide the vehicle's).
inline void readLawMapping(const YamlReader& r, const YAML::Node& c, const std::string& key, ControllerSettings& set) {
  readLaw(r, c, key, set);
}

// Every other law: the reader its controller-file header gives
// (readLawGains(reader, mapping, key, gains, Ts), found by its gains' type).
template <class Law>
void readLawMapping(const YamlReader& r, const YAML::Node& c, const std::string& key, LawSettings<Law>& set) {
  readLawGains(r, c, key, set.gains, set.Ts);
}

// The law's name and its gains in force by name (Control.gain_names).
inline const char* lawNameOf(const ControllerSettings& set) { return lawName(set.law); }
template <class Law>
const char* lawNameOf(const LawSettings<Law>&) {
  return Law::name();
}

inline std::vector<std::pair<std::string, double>> gainsInForce(const ControllerSettings& set) {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<std::string> names = lawGainNames(set.law);
  for (size_t i = 0; i < names.size(); ++i) out.emplace_back(names[i], lawGain(set, int(i)));
  return out;
}
template <class Law>
std::vector<std::pair<std::string, double>> gainsInForce(const LawSettings<Law>& set) {
  return namedGains(set.gains);
}

// The AR.Drone gains a node shows on its reconfigure server: its own, or
// (flying another vehicle's law) the defaults, which it never reads.
inline const ControllerSettings& ardroneGainsShown(const ControllerSettings& set) { return set; }
template <class Law>
ControllerSettings ardroneGainsShown(const LawSettings<Law>&) {
  return ControllerSettings();
}

}  // namespace aurora_control
