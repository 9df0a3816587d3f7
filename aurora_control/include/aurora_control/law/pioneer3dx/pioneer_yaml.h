// The Pioneer P3-DX's controller files (config/controllers/
// pioneer_kinematic.yaml, pioneer_dynamic.yaml; docs/pioneer3dx.md,
// "Controllers"), read strictly: each gain a list of two, on x, y for the
// kinematic part, on u, omega for the dynamic compensation. The laws run
// every model step (AuRoRA's Pioneer scripts): no rate of their own.
#pragma once

#include <string>

#include "aurora_control/law/gain_lists_yaml.h"
#include "aurora_control/law/pioneer3dx/pioneer_laws.h"

namespace aurora_control {

// Each law's gain lists: on x, y for the kinematic part, on u, omega for
// the dynamic compensation.
inline std::vector<GainGroup> gainGroups(PioneerKinematicGains<double>& g) {
  return {{{{"k1", g.k1}, {"k2", g.k2}}, {"x", "y"}}};
}
inline std::vector<GainGroup> gainGroups(PioneerDynamicGains<double>& g) {
  return {{{{"kc1", g.kc1}, {"kc2", g.kc2}}, {"x", "y"}}, {{{"kd1", g.kd1}, {"kd2", g.kd2}}, {"u", "omega"}}};
}

inline std::vector<std::pair<const char*, double*>> gainExtras(PioneerKinematicGains<double>&) { return {}; }
inline std::vector<std::pair<const char*, double*>> gainExtras(PioneerDynamicGains<double>& g) {
  return {{"accel_interval", &g.accel_interval}};
}

// The gain lists of each law under the mapping at key `at` ("controller"
// in a controller file, a robot's controller in a formation file).
inline void readPioneerGains(const YamlReader& r, const YAML::Node& c, const std::string& at,
                             PioneerKinematicGains<double>& g) {
  r.onlyKeys(c, at, {"name", "k1", "k2"});
  for (const GainGroup& group : gainGroups(g)) readGainLists(r, c, at, group, kPioneerGainMax);
}

inline void readPioneerGains(const YamlReader& r, const YAML::Node& c, const std::string& at,
                             PioneerDynamicGains<double>& g) {
  r.onlyKeys(c, at, {"name", "kc1", "kc2", "kd1", "kd2", "accel_interval"});
  for (const GainGroup& group : gainGroups(g)) readGainLists(r, c, at, group, kPioneerGainMax);
  g.accel_interval = 0.0;
  if (c["accel_interval"]) {
    g.accel_interval = r.numberIn(c["accel_interval"], r.key(at, "accel_interval"), 0.0, 10.0,
                                  "s (0: the vehicle's sample time)");
  }
}

// Each law's gains from a controller mapping (law_settings_yaml.h's
// readLawMapping): both run every model step, whatever the vehicle's Ts.
inline void readLawGains(const YamlReader& r, const YAML::Node& c, const std::string& key,
                         PioneerKinematicGains<double>& g, double /*Ts*/) {
  readPioneerGains(r, c, key, g);
}
inline void readLawGains(const YamlReader& r, const YAML::Node& c, const std::string& key,
                         PioneerDynamicGains<double>& g, double /*Ts*/) {
  readPioneerGains(r, c, key, g);
}

}  // namespace aurora_control
