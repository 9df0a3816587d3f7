// The Bebop 2 compensator's controller file (config/controllers/
// bebop2_compensator.yaml, docs/bebop2.md, "The compensator"), read
// strictly: its 16 gains in four lists of x, y, z, yaw, and its rate,
// which must divide the vehicle's own (30 Hz: 30, 15, 10, 6, 5 ...).
#pragma once

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "aurora_control/law/bebop2_compensator.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

struct CompensatorFile {
  CompensatorGains<double> gains;  // period_steps set by compensatorPeriod
  double rate = 30.0;              // [Hz] the law's
  bool has_clamp = false;          // the file sets clamp_commands
  bool clamp = true;
};

// The name under 'controller:' of a controller file ("" when it has none):
// what chooses the vehicle a flight flies.
inline std::string controllerFileName(const std::string& path) {
  return aurora_common::yamlFileWord("controller file", path, "controller", "name");
}

// One gain list of a controller mapping: `<at>.<key>` (at: "controller" in
// a controller file), one number per axis of `axes` (e.g. "x, y, z, yaw"),
// each in [0, max].
struct GainList {
  const char* key;
  double* into;
};

inline void readGainLists(const YamlReader& r, const YAML::Node& c, const std::string& at,
                          std::initializer_list<GainList> lists, size_t n, const std::string& axes, double max) {
  const std::string text = "a list of " + std::to_string(n) + " numbers in [0, " + YamlReader::fmt(max) + "] (" +
                           axes + ")";
  for (const GainList& g : lists) {
    const std::string key = r.key(at, g.key);
    const std::vector<double> v = r.numbers(r.require(c, at, g.key, text), key, n, text);
    for (size_t i = 0; i < n; ++i) {
      g.into[i] = v[i];
      if (!(v[i] >= 0.0 && v[i] <= max)) r.fail(key, "must be " + text);
    }
  }
}

inline CompensatorFile readCompensatorFile(const std::string& path) {
  const YAML::Node root = loadYamlFile("controller file", path);
  const YamlReader r("controller file '" + path + "': ");
  r.onlyKeys(root, "", {"controller", "clamp_commands"});
  const YAML::Node c = root["controller"];
  r.onlyKeys(c, "controller", {"name", "ksp", "ksd", "kp", "kd", "rate"});
  CompensatorFile f;
  readGainLists(r, c, "controller", {{"ksp", f.gains.ksp}, {"ksd", f.gains.ksd}, {"kp", f.gains.kp}, {"kd", f.gains.kd}}, 4,
                "x, y, z, yaw", kCompensatorGainMax);
  f.rate = r.numberIn(r.require(c, "controller", "rate", "Hz, dividing the vehicle's rate (30 Hz: 30, 15, 10, 6, 5)"),
                      "controller.rate", 0.0, 1000.0, "Hz", false);
  if (root["clamp_commands"]) f.has_clamp = true, f.clamp = r.boolean(root["clamp_commands"], "clamp_commands");
  return f;
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

}  // namespace aurora_control
