// What every shape's formation file reader shares (docs/formation.md,
// "Formation files"): files named relative to the config folder, lists of
// numbers, the layer's gains, a robot's controller, predictor, link and
// namespace, the start heights, the shortest duration the checks judge, and
// what a sweep records of a shape's file. Each shape's own reader
// (line/line_yaml.h, triangle/, uav_ugv/) reads its file with these.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/formation/formation_document.h"
#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/params/yaml_reader.h"
#include "aurora_control/predictor/predictor_yaml.h"

namespace aurora_control {

namespace formation_detail {

// A file a formation file names: absolute, or relative to the config folder.
inline std::string inConfig(const std::string& file, const std::string& config_dir) {
  return file.empty() || file[0] == '/' ? file : config_dir + "/" + file;
}

// A list of exactly n numbers.
inline std::vector<double> numbers(const YamlReader& r, const YAML::Node& n, const std::string& key, size_t count) {
  if (!n.IsSequence() || n.size() != count) r.fail(key, "must be a list of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (const auto& x : n) v.push_back(r.number(x, key));
  return v;
}

// The layer's gains at `key`: {k1: [N numbers], k2: [N numbers]}, either
// left out keeping the shape's defaults; each in the formation gains' range.
template <int N>
void readGains(const YamlReader& r, const YAML::Node& n, const std::string& key, FormationGains<double, N>& g) {
  r.onlyKeys(n, key, {"k1", "k2"});
  const char* names[2] = {"k1", "k2"};
  double* into[2] = {g.k1, g.k2};
  for (int j = 0; j < 2; ++j) {
    if (!n[names[j]]) continue;
    const std::vector<double> v = numbers(r, n[names[j]], r.key(key, names[j]), N);
    for (int i = 0; i < N; ++i) {
      if (!(v[i] >= kFormationGainMin && v[i] <= kFormationGainMax)) {  // formation_layer.h
        r.fail(r.key(key, names[j]), "= " + YamlReader::fmt(v[i]) + " (entry " + std::to_string(i + 1) +
                                         ") is refused: accepted gains in [" + YamlReader::fmt(kFormationGainMin) +
                                         ", " + YamlReader::fmt(kFormationGainMax) + "]");
      }
      into[j][i] = v[i];
    }
  }
}

// A robot's controller at `key`: a mapping {name, gains ...} or a
// controller file (controllers/NAME.yaml, in the config folder). A file's
// predictor block is read by predictorAt: formation robots fly it
// (formation_runner.h, dronePredictor).
// `Data`: the law family of the shape's robots (law_of.h).
template <class Data>
LawSettings<Data> controllerAt(const YamlReader& r, const YAML::Node& c, const std::string& key,
                               const std::string& config_dir) {
  if (c.IsScalar()) return readControllerFile<Data>(inConfig(r.text(c, key), config_dir));
  LawSettings<Data> set;
  readLawMapping(r, c, key, set);
  return set;
}

// The predictor of a robot's controller at `key` (off for a mapping).
inline PredictorFile predictorAt(const YamlReader& r, const YAML::Node& c, const std::string& key,
                                 const std::string& config_dir) {
  if (!c.IsScalar()) return PredictorFile{};
  return readControllerPredictor(inConfig(r.text(c, key), config_dir));
}

// A robot's link file at `key` (links/NAME.yaml, in the config folder).
inline LinkParams linkFileAt(const YamlReader& r, const YAML::Node& n, const std::string& key,
                             const std::string& config_dir) {
  return readLinkFile(inConfig(r.text(n, key), config_dir));
}

inline std::string pointText(const double p[3]) {
  return "[" + YamlReader::fmt(p[0]) + ", " + YamlReader::fmt(p[1]) + ", " + YamlReader::fmt(p[2]) + "]";
}

// A robot's ROS namespace at `key` (a name such as ardrone1 or bebop2: a
// letter, then letters, digits and '_'); the drivers' topics are under it.
inline std::string namespaceAt(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  const std::string name = r.text(n, key);
  bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) r.fail(key, "= '" + name + "' is not a namespace: accepted a letter, then letters, digits or '_' (drone1, ugv_2)");
  return name;
}

// Every shape's robots in namespaces of their own (their drivers' topics).
inline void refuseSharedNamespaces(const YamlReader& r, const std::string& key, const std::vector<std::string>& names) {
  for (size_t i = 0; i < names.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (names[i] == names[j]) {
        r.fail(key, "names '" + names[i] + "' for robots " + std::to_string(j + 1) + " and " + std::to_string(i + 1) +
                        ": accepted a namespace of its own for each robot");
      }
    }
  }
}

// The highest start a formation file takes [m] (the drones' waypoint
// ceiling, task_check.h's 100 m).
constexpr double kHighestStart = 100.0;

// The one start check of every shape (the line's drones, the UAV-UGV
// line's robots, the triangle's): z within [lo, hi] m, refused naming `key`
// and the start, with `accepted` saying what is (a ground robot: z = 0).
inline void refuseStartHeight(const YamlReader& r, const std::string& key, const double p[3], double lo = 0.0,
                              double hi = kHighestStart, const std::string& accepted = "") {
  if (p[2] >= lo && p[2] <= hi) return;
  r.fail(key, "= " + pointText(p) + " has z = " + YamlReader::fmt(p[2]) + " m" + (p[2] < 0.0 ? ", below the ground" : "") +
                  ": " + (accepted.empty() ? "accepted heights [" + YamlReader::fmt(lo) + ", " + YamlReader::fmt(hi) + "] m" : accepted));
}

}  // namespace formation_detail

// What a sweep of a shape's file records beside its run (aurora_sweep's
// file reader): how long it flies, the controller its records name (its
// robots' law where one law flies them all: the entry's withRobotLaw
// chooses by it), and why a sweep refuses the file ("" where it flies it).
struct ShapeSweepFacts {
  double duration = 0.0;  // [s]
  std::string controller;
  std::string refusal;
};

// A formation is judged from the checks' settling time on
// (formation_checks.h): a shorter one would be judged on nothing and pass,
// every error 0. Every shape's file (`key`: its duration's key) and a
// sweep's criteria (`settle`: its settle_time) refuse it by this rule.
inline std::string shortFormationRefusal(double duration, const std::string& key,
                                         double settle = FormationCriteria<double>::study().settle_time) {
  if (duration > settle) return "";
  return "'" + key + "' = " + YamlReader::fmt(duration) + " s is refused: the formation checks judge a flight from " +
         YamlReader::fmt(settle) + " s on (settle_time), so a shorter one would be judged on nothing; accepted durations > " +
         YamlReader::fmt(settle) + " s";
}
inline void refuseShortFormation(double duration, const std::string& key) {
  const std::string refusal = shortFormationRefusal(duration, key);
  if (!refusal.empty()) throw ConfigError(refusal);
}
// The same, said with the reader's file (the UAV-UGV line's and the triangle's `formation.duration`).
inline void refuseShortFormation(const YamlReader& r, double duration, const std::string& key) {
  const std::string refusal = shortFormationRefusal(duration, key);
  if (!refusal.empty()) r.failWith(refusal);
}

// A formation robot's predictor of file `f` flying law `Law` at sample time
// Ts: its model loaded as the law's vehicle, its horizon in samples; its
// command path is the run's (dronePredictor).
template <class Law>
PredictorRun<typename Law::Vehicle, double> formationPredictor(const PredictorFile& f, double Ts) {
  return predictorRun<Law>(f, Ts, 0, 0, false);
}

}  // namespace aurora_control
