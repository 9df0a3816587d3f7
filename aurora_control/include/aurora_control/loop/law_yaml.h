// The controller files' schema (config/controllers/*.yaml, 'controller:'),
// read strictly for the node, replay and the sweep: the law's name, all of
// its gains (none may be missing), nothing else.
//   pd_saturated:   kp, kd in [kPdGainMin, kPdGainMax] = [0, 10]
//   underactuated:  k1_x, k2_x, ..., k1_psi, k2_psi in [0.001, 100] (limits.h)
#pragma once

#include <string>
#include <vector>

#include "aurora_control/law/other_laws.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

// The gains of `law` by configuration name, in the order Control lists them.
inline std::vector<std::string> lawGainNames(LawType law) {
  if (law == LawType::kPdSaturated) return {"kp", "kd"};
  std::vector<std::string> names;
  for (int i = 0; i < 2 * kAxes; ++i) names.push_back(underactuatedGainName(i));
  return names;
}

inline double& lawGain(ControllerSettings& set, int i) {
  if (set.law == LawType::kPdSaturated) return i == 0 ? set.gains.kp : set.gains.kd;
  return underactuatedGain(set.underactuated, i);
}

inline double lawGain(const ControllerSettings& set, int i) {
  if (set.law == LawType::kPdSaturated) return i == 0 ? set.gains.kp : set.gains.kd;
  return underactuatedGain(set.underactuated, i);
}

// Reads the mapping under `key` into settings.law and its gains.
inline void readLaw(const YamlReader& r, const YAML::Node& node, const std::string& key,
                    ControllerSettings& set) {
  if (!node || !node.IsMap()) r.fail(key, "is missing or not a mapping: load a controller file such as config/controllers/pd_saturated.yaml");
  const std::string name = r.text(r.require(node, key, "name", knownLawNames()), r.key(key, "name"));
  if (!lawFromName(name, set.law)) {
    r.fail(r.key(key, "name"), "= '" + name + "' is unknown: accepted controllers: " + knownLawNames() +
                                   " (by vehicle: " + lawVehicleNames() + ")");
  }
  std::vector<std::string> accepted{"name"};
  const std::vector<std::string> gains = lawGainNames(set.law);
  accepted.insert(accepted.end(), gains.begin(), gains.end());
  r.onlyKeys(node, key, accepted);
  const bool pd = set.law == LawType::kPdSaturated;
  const double lo = pd ? kPdGainMin : kUnderactuatedGainMin, hi = pd ? kPdGainMax : kUnderactuatedGainMax;
  for (size_t i = 0; i < gains.size(); ++i) {
    const YAML::Node v = r.require(node, key, gains[i], "a number in [" + YamlReader::fmt(lo) + ", " + YamlReader::fmt(hi) + "]");
    lawGain(set, static_cast<int>(i)) = r.numberIn(v, r.key(key, gains[i]), lo, hi, "");
  }
}

// A controller file (config/controllers/*.yaml): 'controller:' (the law and
// its gains) and an optional 'clamp_commands'. Read by replay, the flight tool
// and the tests that fly a file's law offline.
struct ControllerFile {
  ControllerSettings settings;  // law and gains
  bool has_clamp = false;       // the file sets clamp_commands
  bool clamp = true;
};

inline ControllerFile readControllerFile(const std::string& path) {
  const YAML::Node root = loadYamlFile("controller file", path);
  const YamlReader r("controller file '" + path + "': ");
  r.onlyKeys(root, "", {"controller", "clamp_commands", "predictor"});  // predictor: predictor_yaml.h
  ControllerFile f;
  readLaw(r, root["controller"], "controller", f.settings);
  if (root["clamp_commands"]) f.has_clamp = true, f.clamp = r.boolean(root["clamp_commands"], "clamp_commands");
  return f;
}

}  // namespace aurora_control
