// The Bebop 2 compensator's controller file (config/controllers/
// bebop2_compensator.yaml, docs/bebop2.md, "The compensator"), read
// strictly: its 16 gains in four lists of x, y, z, yaw, and its rate,
// which must divide the vehicle's own (30 Hz: 30, 15, 10, 6, 5 ...).
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "aurora_control/law/bebop2/bebop2_compensator.h"
#include "aurora_control/law/gain_lists_yaml.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

struct CompensatorFile {
  CompensatorGains<double> gains;  // period_steps set by compensatorPeriod
  double rate = 30.0;              // [Hz] the law's
};

// The compensator's 16 gains (docs/bebop2.md, eq. B2).
inline std::vector<GainGroup> gainGroups(CompensatorGains<double>& g) {
  return {{{{"ksp", g.ksp}, {"ksd", g.ksd}, {"kp", g.kp}, {"kd", g.kd}}, {"x", "y", "z", "yaw"}}};
}

// What a law's gains hold beyond its lists, by name: the compensator's
// period in model steps (from its rate).
inline std::vector<std::pair<const char*, double*>> gainExtras(CompensatorGains<double>& g) {
  return {{"period_steps", &g.period_steps}};
}

// A compensator mapping (a controller file's 'controller:', or the node's
// ~controller): its gains and its rate; only its keys.
inline void readCompensator(const YamlReader& r, const YAML::Node& c, const std::string& at, CompensatorFile& f) {
  r.onlyKeys(c, at, {"name", "ksp", "ksd", "kp", "kd", "rate"});
  for (const GainGroup& group : gainGroups(f.gains)) readGainLists(r, c, at, group, kCompensatorGainMax);
  f.rate = r.numberIn(r.require(c, at, "rate", "Hz, dividing the vehicle's rate (30 Hz: 30, 15, 10, 6, 5)"),
                      r.key(at, "rate"), 0.0, 1000.0, "Hz", false);
}

// The law's period in model steps of Ts: its rate must divide the
// vehicle's (1/Ts) into a whole number of steps. `given` names where the
// rate came from in a refusal (e.g. "--rate 7").
inline long compensatorPeriod(const std::string& given, double rate, double Ts) {
  const double steps = 1.0 / (rate * Ts);
  const long whole = std::lround(steps);
  if (whole < 1 || std::fabs(steps - double(whole)) > 1e-9 * steps) {
    std::string accepted;
    for (long n = 1; n <= 6; ++n) accepted += (n > 1 ? ", " : "") + YamlReader::fmt(1.0 / (double(n) * Ts));
    throw ConfigError(given + " Hz does not divide the vehicle's " + YamlReader::fmt(1.0 / Ts) +
                      " Hz into whole model steps: accepted " + accepted + ", ... Hz");
  }
  return whole;
}

// What a law with a rate of its own gives (other_laws.h, lawHasRate; a
// flight's --rate): its rate [Hz] in a controller mapping, its period set
// from a rate (`given` names where it came from in a refusal), and that
// period in model steps.
inline double mappingRate(const YAML::Node& c, const CompensatorGains<double>&) { return c["rate"].as<double>(); }
inline void setLawRate(CompensatorGains<double>& g, double rate, double Ts, const std::string& given) {
  g.period_steps = double(compensatorPeriod(given, rate, Ts));
}
inline long lawPeriodSteps(const CompensatorGains<double>& g) { return long(g.period_steps); }

// The compensator's gains from a controller mapping (a controller file's
// 'controller:', or the node's ~controller) for a vehicle of sample time Ts:
// its period from its rate (each law's readLawGains, which
// law_settings_yaml.h's readLawMapping calls).
inline void readLawGains(const YamlReader& r, const YAML::Node& c, const std::string& key, CompensatorGains<double>& g,
                         double Ts) {
  CompensatorFile f;
  readCompensator(r, c, key, f);
  g = f.gains;
  setLawRate(g, f.rate, Ts, r.context() + "'" + r.key(key, "rate") + "' = " + YamlReader::fmt(f.rate));
}

}  // namespace aurora_control
