// The two-drone line's formation file (shape: line; config/formations/
// line_*.yaml, docs/formation.md, "Formation files"), read strictly: the
// law, the period, the gains, the reference and the drones (namespace,
// start, controller, delay, link), with what every shape's reader shares
// (formation_file.h). Unknown keys, one drone, a namespace twice, rho <= 0,
// sin^2 alpha + sin^2 beta > 1, a period that is not a whole number of drone
// steps are refused, naming the key, the value and what is accepted.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_file.h"
#include "aurora_control/formation/line/line_run.h"
#include "aurora_control/params/limits.h"

namespace aurora_control {

struct FormationDroneFile {
  std::string name_space;        // its ROS namespace (its drivers' topics)
  double start[3];               // [m]
  LawSettings<LineDrones> controller;  // its law and gains
  long delay = 0;                // its uplink delay [samples]
  LinkParams link;               // its link (docs/links.md; ideal unless given)
  PredictorFile predictor;       // its controller file's predictor (off for a mapping; docs/predictor.md)
};

struct FormationFile {
  FormationLaw law = FormationLaw::kPositionPriority;
  double period = 0.2;  // [s]
  FormationGains<double, 6> gains = FormationGains<double, 6>::of<LineFormation<double>>();
  FormationReference<double, LineFormation<double>> reference;
  std::vector<FormationDroneFile> drones;
};

inline const char* formationLawName(FormationLaw law) {
  return law == FormationLaw::kInverseKinematics ? "inverse_kinematics"
         : law == FormationLaw::kPositionPriority ? "position_priority"
                                                  : "shape_priority";
}

namespace formation_detail {

// reference: {path: fixed | lemniscate, duration, amplitude: [rx, ry],
// position: [x, y, z], shape: {rho, alpha, beta}}.
inline void readReference(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          FormationReference<double, LineFormation<double>>& ref) {
  r.onlyKeys(n, key, {"path", "duration", "amplitude", "position", "shape"});
  const std::string path = r.text(r.require(n, key, "path", "fixed, lemniscate"), r.key(key, "path"));
  if (path == "fixed") ref.path = FormationPath::kFixed;
  else if (path == "lemniscate") ref.path = FormationPath::kLemniscate;
  else r.fail(r.key(key, "path"), "= '" + path + "' is unknown: accepted fixed, lemniscate");
  ref.duration = r.numberIn(r.require(n, key, "duration", "seconds > 0"), r.key(key, "duration"), 0.0, 3600.0, "s", false);
  if (n["amplitude"]) {
    const std::vector<double> a = numbers(r, n["amplitude"], r.key(key, "amplitude"), 2);
    ref.amplitude[0] = a[0], ref.amplitude[1] = a[1];
  }
  const std::vector<double> p = numbers(r, r.require(n, key, "position", "[x, y, z] in m"), r.key(key, "position"), 3);
  const std::string shape_key = r.key(key, "shape");
  const YAML::Node s = r.require(n, key, "shape", "{rho, alpha, beta}");
  r.onlyKeys(s, shape_key, {"rho", "alpha", "beta"});
  const double rho = r.number(r.require(s, shape_key, "rho", "m > 0"), r.key(shape_key, "rho"));
  if (!(rho > 0)) r.fail(r.key(shape_key, "rho"), "= " + YamlReader::fmt(rho) + " is refused: accepted a distance > 0 m");
  const double alpha = r.number(r.require(s, shape_key, "alpha", "rad"), r.key(shape_key, "alpha"));
  const double beta = r.number(r.require(s, shape_key, "beta", "rad"), r.key(shape_key, "beta"));
  const double reach = std::sin(alpha) * std::sin(alpha) + std::sin(beta) * std::sin(beta);
  if (reach > 1.0) {
    r.fail(shape_key, "alpha = " + YamlReader::fmt(alpha) + ", beta = " + YamlReader::fmt(beta) + " are refused: sin^2 alpha + sin^2 beta = " +
                          YamlReader::fmt(reach) + " > 1 (no position of drone 2 has these angles); accepted sin^2 alpha + sin^2 beta <= 1");
  }
  const double Q[6] = {p[0], p[1], p[2], rho, alpha, beta};
  for (int i = 0; i < 6; ++i) ref.Q[i] = Q[i];
}

// drones[i]: {namespace, start: [x, y, z], controller: {name, gains...} or a
// controller file, delay, link: a link file}.
inline FormationDroneFile readDrone(const YamlReader& r, const YAML::Node& n, const std::string& key,
                                    const std::string& config_dir) {
  r.onlyKeys(n, key, {"namespace", "start", "controller", "delay", "link"});
  FormationDroneFile d;
  d.name_space =
      namespaceAt(r, r.require(n, key, "namespace", "a ROS namespace (drone1, ugv_2)"), r.key(key, "namespace"));
  const std::vector<double> s = numbers(r, r.require(n, key, "start", "[x, y, z] in m"), r.key(key, "start"), 3);
  for (int i = 0; i < 3; ++i) d.start[i] = s[i];
  const YAML::Node c = r.require(n, key, "controller", "a controller mapping {name, gains} or file (controllers/NAME.yaml)");
  d.controller = controllerAt<LineDrones>(r, c, r.key(key, "controller"), config_dir);
  d.predictor = predictorAt(r, c, r.key(key, "controller"), config_dir);
  long given = kDelayNotGiven;
  if (n["delay"]) {
    const double value = r.number(n["delay"], r.key(key, "delay"));
    const std::string refusal = delayRefusal(value, false, 0.0, given);
    if (!refusal.empty()) r.fail(r.key(key, "delay"), "= " + YamlReader::fmt(value) + " " + refusal);
  }
  if (n["link"]) d.link = linkFileAt(r, n["link"], r.key(key, "link"), config_dir);
  d.delay = delayInForce(given, d.link);  // a delay given replaces the link's uplink delay (docs/links.md)
  return d;
}

// Starts the line's variables are defined at (line_formation.h): no drone
// below the ground, drone 2 not level with drone 1.
inline void refuseSingularStart(const YamlReader& r, const std::vector<FormationDroneFile>& drones) {
  for (size_t i = 0; i < drones.size(); ++i) {
    refuseStartHeight(r, "formation.drones[" + std::to_string(i) + "].start", drones[i].start);
  }
  const double* a = drones[0].start;
  const double* b = drones[1].start;
  const double gap = std::fabs(b[2] - a[2]);
  if (gap < LineFormation<double>::kMinStartHeightGap) {
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    r.fail("formation.drones", "are refused: drone 1 (" + drones[0].name_space + ") starts at " + pointText(a) + " and drone 2 (" +
                                   drones[1].name_space + ") at " + pointText(b) + ", " + YamlReader::fmt(distance) +
                                   " m apart and " + YamlReader::fmt(gap) +
                                   " m apart in height: the line's variables are singular where the drones are level "
                                   "(eq. F4 divides by z2 - z1; at 0 m apart beta is undefined) and the layer would "
                                   "command NaN; accepted starts at least " +
                                   YamlReader::fmt(LineFormation<double>::kMinStartHeightGap) + " m apart in height");
  }
}

inline void readDrones(const YamlReader& r, const YAML::Node& n, const std::string& config_dir, FormationFile& f) {
  if (!n.IsSequence() || n.size() != 2) {
    r.fail("formation.drones", "must list the line's 2 drones (it lists " + std::to_string(n.IsSequence() ? n.size() : 0) + ")");
  }
  for (size_t i = 0; i < n.size(); ++i) {
    f.drones.push_back(readDrone(r, n[i], "formation.drones[" + std::to_string(i) + "]", config_dir));
  }
  if (f.drones[0].name_space == f.drones[1].name_space) {
    r.fail("formation.drones[1].namespace", "= '" + f.drones[1].name_space + "' is drone 1's too: accepted a namespace of its own");
  }
  refuseSingularStart(r, f.drones);
  if (f.drones[0].controller.law != f.drones[1].controller.law) {
    r.fail("formation.drones[1].controller.name", "differs from drone 1's: accepted the same law for every drone");
  }
}

}  // namespace formation_detail

// The two-drone line's file (shape: line), read from its document
// (formation_document.h); the shapes' list (shapes.h) hands each document to
// its shape's reader, so this one reads only a line.
inline FormationFile readFormationFile(const FormationDocument& d) {
  using namespace formation_detail;
  const YamlReader r = formationReader(d);
  if (d.shape.empty()) r.fail("formation.shape", "is missing: accepted 'shape: line' (the two-drone line this reader reads)");
  if (d.shape != "line") {
    r.fail("formation.shape", "= '" + d.shape + "' is not the two-drone line this reader reads (shapes.h chooses "
                              "a file's reader by its shape)");
  }
  const YAML::Node n = formationSection(r, d, {"shape", "law", "period", "gains", "reference", "drones"});
  FormationFile f;
  const std::string law = r.text(r.require(n, "formation", "law", "inverse_kinematics, position_priority, shape_priority"), "formation.law");
  bool known = false;
  for (FormationLaw l : {FormationLaw::kInverseKinematics, FormationLaw::kPositionPriority, FormationLaw::kShapePriority}) {
    if (law == formationLawName(l)) f.law = l, known = true;
  }
  if (!known) r.fail("formation.law", "= '" + law + "' is unknown: accepted inverse_kinematics, position_priority, shape_priority");
  if (n["period"]) f.period = r.numberIn(n["period"], "formation.period", 0.0, 60.0, "s", false);
  if (n["gains"]) readGains(r, n["gains"], "formation.gains", f.gains);
  readReference(r, r.require(n, "formation", "reference", "{path, duration, position, shape}"), "formation.reference", f.reference);
  readDrones(r, r.require(n, "formation", "drones", "the 2 drones"), d.config_dir, f);
  return f;
}

inline FormationFile readFormationFile(const std::string& path, const std::string& config_dir) {
  return readFormationFile(loadFormationDocument(path, config_dir));
}

// The two-drone line's entry in the shapes' list (shapes.h): AuRoRA's line
// of two AR.Drones, their vehicle file the flight's or the node's (the
// formation file names none).
struct LineShapeEntry {
  using Shape = LineFormation<double>;
  using File = FormationFile;
  static constexpr int kRobots = 2;
  static constexpr bool kNamesItsVehicles = false;
  using UnnamedVehicle = LineDrones::Vehicle;  // its drones (withUnnamedVehicle, shapes.h)
  static const char* name() { return "line"; }
  static std::string robotKey(const std::string& what) { return "formation.drones[i]." + what; }
  static std::string lawRefusal() { return "the line's law is its file's formation.law"; }
  static File read(const FormationDocument& d, const std::string&) { return readFormationFile(d); }
  // A sweep's: its run, its robots' law type (f(Law()); the drones' law,
  // chosen by the file), the shape its parameters are named by, its laws a
  // sweep may vary (formation_law; none: the file's formation.law).
  using SweepRun = LineRun;
  // The sweep's set of vehicle parameters (its file's, each vehicle's
  // nominal else): its drones are the set's of their vehicle.
  template <class VehicleSet>
  static SweepRun sweepRun(const File& f, const VehicleSet& vehicles) {
    return formationRun(f, vehicles.template of<LineDrones::Vehicle>());
  }
  static ShapeSweepFacts sweepFacts(const File& f) {
    ShapeSweepFacts facts;
    facts.duration = f.reference.duration;
    facts.controller = lawNameOf(f.drones[0].controller);
    return facts;
  }
  template <class F>
  static void withRobotLaw(const std::string& controller, F&& f) { withLawOfNamed<LineDrones>(controller, f); }
  using ParamShape = Shape;
  static constexpr int kSweepLaws = 0;
  static std::string sweepLawNames() { return ""; }
  static void fly(const File& file, const FormationFlightOptions& o);  // src/line/line_flight.cpp
  static std::unique_ptr<FormationCrew> crew(const File& file, const CrewRequest& q);  // src/line/line_crew.cpp
};

// Each drone's delay in force shorter than the run, as one drone's
// (limits.h, delayShorterThanRun); `keys[d]` names where drone d's came from.
inline void refuseFormationDelays(const LineRun& run, double Ts,
                                  const std::vector<std::string>& keys) {
  const long ticks = formationTicks(run.reference.duration, Ts);
  for (int d = 0; d < LineFormation<double>::kDrones; ++d) {
    if (!delayShorterThanRun(run.drone[d].delay, ticks)) {
      throw ConfigError(keys[d] + " = " + delayRunText(run.drone[d].delay, ticks, Ts));
    }
    const std::string late = latestPacketRefusal(run.drone[d].link, run.drone[d].delay, ticks, Ts);
    if (!late.empty()) throw ConfigError(keys[d] + " with drone " + std::to_string(d + 1) + "'s link: " + late);
  }
}

// The run of a formation file with the drones' vehicle `vehicle`, its
// period in whole drone steps (refused otherwise).
inline LineRun formationRun(const FormationFile& f, const LineDrones::Vehicle::Params<double>& vehicle) {
  LineRun run;
  run.law = f.law;
  run.gains = f.gains;
  run.reference = f.reference;
  run.schedule.period_ticks = wholeRobotSteps(f.period, vehicle.Ts);  // on the drones' steps (step_ticks 1)
  if (run.schedule.period_ticks == 0) {
    throw ConfigError("formation.period = " + YamlReader::fmt(f.period) + " s is refused: accepted a whole number of drone steps of " +
                      YamlReader::fmt(vehicle.Ts) + " s (0.2 s = 6 steps at 30 Hz)");
  }
  for (int d = 0; d < 2; ++d) {
    run.drone[d].plant = run.drone[d].model = vehicle;
    run.drone[d].gains = f.drones[d].controller.gains;
    run.drone[d].delay = f.drones[d].delay;
    run.drone[d].link = f.drones[d].link;
    for (int i = 0; i < 3; ++i) run.drone[d].start[i] = f.drones[d].start[i];
    f.drones[d].controller.withLawType([&](auto law) {
      run.drone[d].predictor = formationPredictor<decltype(law)>(f.drones[d].predictor, vehicle.Ts);
    });
  }
  refuseShortFormation(run.reference.duration, "formation.reference.duration");
  refuseFormationDelays(run, vehicle.Ts, {"formation.drones[0].delay", "formation.drones[1].delay"});
  return run;
}

}  // namespace aurora_control
