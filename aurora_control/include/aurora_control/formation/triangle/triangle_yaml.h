// A triangle formation file (config/formations/triangle_*.yaml;
// docs/formation.md, "The triangle"), read strictly:
//
//   formation:
//     shape: triangle
//     law: N                      # N, PSO, SPO, OSP, S-PO
//     period: 0.05                # s: the layer's
//     duration: 50                # s
//     gains: {k1: [9], k2: [9]}   # optional: AuRoRA's class gains (3, 1)
//     reference: carrousel        # AuRoRA's Carrossel (the one so far)
//     robots:
//       starts: [[x, y, z], [x, y, z], [x, y, z]]   # m
//       namespaces: [ardrone1, ardrone2, ardrone3]   # optional: the robots' ROS namespaces (these by default)
//       vehicle: vehicles/ardrone2.yaml             # absent: kinematic robots (at their references)
//       controller: controllers/underactuated.yaml  # or an underactuated mapping
//       links: [links/A.yaml, links/B.yaml, links/C.yaml]   # optional, flying robots: one per drone
//
// Refused naming the key: an unknown law, key or reference, a period that
// the drones' step and a base tick of at most 12 parts cannot both divide.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_file.h"
#include "aurora_control/formation/triangle/triangle_run.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_control {

// The triangle's laws by AuRoRA's names.
inline const char* triangleLawName(TriangleLaw law) {
  static const char* const names[] = {"N", "PSO", "SPO", "OSP", "S-PO"};
  return names[static_cast<int>(law)];
}

// The triangle's laws, in their index order.
constexpr TriangleLaw kTriangleLaws[] = {TriangleLaw::kN, TriangleLaw::kPSO, TriangleLaw::kSPO, TriangleLaw::kOSP,
                                         TriangleLaw::kSdashPO};

// Their names, comma separated ("N, PSO, SPO, OSP, S-PO").
inline std::string triangleLawNames() {
  std::string names;
  for (TriangleLaw l : kTriangleLaws) names += (names.empty() ? "" : ", ") + std::string(triangleLawName(l));
  return names;
}

// `name` as a law, or a refusal naming `key` and the accepted names.
inline TriangleLaw triangleLawOf(const std::string& name, const std::string& key) {
  for (TriangleLaw l : kTriangleLaws) {
    if (name == triangleLawName(l)) return l;
  }
  throw ConfigError(key + " = '" + name + "' is not a triangle law: accepted " + triangleLawNames());
}

namespace triangle_yaml_detail {

// The base tick: period = p tick and Ts = q tick with q <= 12, and q <= p
// (one layer before a drone step at most: LayerSchedule).
inline void baseTick(const YamlReader& r, double period, double Ts, TriangleSetup& s) {
  if (period < Ts * (1.0 - 1e-9)) {
    r.fail("formation.period", "= " + YamlReader::fmt(period) + " s is refused: below the drones' step " +
                                   YamlReader::fmt(Ts) + " s (the layer runs at most once per step)");
  }
  for (long q = 1; q <= 12; ++q) {
    const long p = std::lround(double(q) * period / Ts);
    if (p >= 1 && std::fabs(double(p) * Ts / double(q) - period) <= 1e-9 * period) {
      s.layer_ticks = p, s.drone_ticks = q;
      return;
    }
  }
  r.fail("formation.period", "= " + YamlReader::fmt(period) + " s and the drones' step " + YamlReader::fmt(Ts) +
                                 " s have no common tick of Ts / 12 or longer: accepted periods of p Ts / q, q <= 12");
}

// A start where the variables' Jacobian is singular is refused (docs/
// formation.md, eq. T3, T4): two robots at one place or all three on a line
// (the shape's rows), or a median m = 2 p1 - p2 - p3 with no component off
// one axis (phi, theta or psi is 0 / 0).
inline void refuseSingularStart(const YamlReader& r, const double X[9]) {
  const std::string key = "formation.robots.starts";
  double u[3], v[3], c[3], m[3];
  for (int i = 0; i < 3; ++i) u[i] = X[3 + i] - X[i], v[i] = X[6 + i] - X[i];
  triangle_detail::cross(u, v, c);
  const double area = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double scale = triangle_detail::distance(X, X + 3) * triangle_detail::distance(X, X + 6);
  if (!(area > 1e-9 * scale) || !(scale > 0.0)) {
    r.fail(key, "puts the robots on one line (or two at one place): the triangle's angle beta and its shape rows are "
                "singular there; accepted three robots that span a triangle");
  }
  triangle_detail::median(X, m);
  const char* axis[3] = {"x", "y", "z"};
  const char* angle[3] = {"phi", "theta", "psi"};
  for (int i = 0; i < 3; ++i) {
    const double a = m[(i + 1) % 3], b = m[(i + 2) % 3];
    if (a * a + b * b == 0.0) {
      r.fail(key, std::string("puts robot 1's median m = 2 p1 - p2 - p3 along ") + axis[i] + ": " + angle[i] +
                      " is 0 / 0 there (its row of the Jacobian is singular); move a robot off that axis");
    }
  }
}

// The drones' optional `links`: three link files (links/ideal.yaml for
// none), each drone's uplink delay its delay unless --delay gives one.
inline void readLinks(const YamlReader& r, const YAML::Node& n, const std::string& key, const std::string& config_dir,
                      TriangleSetup& s) {
  if (!n["links"]) return;
  if (!n["links"].IsSequence() || n["links"].size() != 3) {
    r.fail(r.key(key, "links"), "must list 3 link files, one per drone (links/ideal.yaml for none)");
  }
  for (int d = 0; d < 3; ++d) {
    const std::string at = r.key(key, "links") + "[" + std::to_string(d) + "]";
    s.link[d] = formation_detail::linkFileAt(r, n["links"][d], at, config_dir);
    s.delay[d] = delayInForce(kDelayNotGiven, s.link[d]);
  }
}

inline void readRobots(const YamlReader& r, const YAML::Node& n, const std::string& config_dir, TriangleSetup& s) {
  const std::string key = "formation.robots";
  r.onlyKeys(n, key, {"starts", "namespaces", "vehicle", "controller", "links"});
  if (n["namespaces"]) {
    const std::string at = r.key(key, "namespaces");
    if (!n["namespaces"].IsSequence() || n["namespaces"].size() != 3) r.fail(at, "must list 3 namespaces, one per robot");
    for (int d = 0; d < 3; ++d) s.name_space[d] = formation_detail::namespaceAt(r, n["namespaces"][d], at + "[" + std::to_string(d) + "]");
    formation_detail::refuseSharedNamespaces(r, at, {s.name_space[0], s.name_space[1], s.name_space[2]});
  }
  const YAML::Node starts = r.require(n, key, "starts", "three [x, y, z] in m");
  if (!starts.IsSequence() || starts.size() != 3) r.fail(r.key(key, "starts"), "must list 3 robots' [x, y, z] in m");
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> p = formation_detail::numbers(r, starts[d], r.key(key, "starts") + "[" + std::to_string(d) + "]", 3);
    for (int i = 0; i < 3; ++i) s.start[3 * d + i] = p[i];
    formation_detail::refuseStartHeight(r, r.key(key, "starts") + "[" + std::to_string(d) + "]", &s.start[3 * d]);
  }
  refuseSingularStart(r, s.start);
  s.kinematic = !n["vehicle"];
  if (s.kinematic) {
    if (n["controller"]) r.fail(r.key(key, "controller"), "is refused without a vehicle: kinematic robots have no law");
    if (n["links"]) r.fail(r.key(key, "links"), "is refused without a vehicle: kinematic robots send no commands");
    return;
  }
  readLinks(r, n, key, config_dir, s);
  s.drone_file = formation_detail::inConfig(r.text(n["vehicle"], r.key(key, "vehicle")), config_dir);
  s.drone = aurora_sim::loadVehicleFile<TriangleDrone>(s.drone_file, "the triangle's drones");
  const std::string law = TriangleDroneLaw::name();
  const YAML::Node c = r.require(n, key, "controller", "an " + law + " mapping or controllers/" + law + ".yaml");
  const auto set = formation_detail::controllerAt<TriangleDrones>(r, c, r.key(key, "controller"), config_dir);
  if (set.law != familyIndex<TriangleDroneLaw>()) r.fail(r.key(key, "controller"), "is refused: the drones fly the " + law + " law");
  s.drone_gains = set.gains;
  s.predictor = formationPredictor<TriangleDroneLaw>(formation_detail::predictorAt(r, c, r.key(key, "controller"), config_dir),
                                                     s.drone.Ts);
}

}  // namespace triangle_yaml_detail

// The file's setup; `law` (not empty: flight's --law) replaces the file's.
inline TriangleSetup readTriangleFile(const FormationDocument& d, const std::string& law = "") {
  const YamlReader r = formationReader(d);
  const std::string& config_dir = d.config_dir;
  const YAML::Node n = formation_detail::formationSection(
      r, d, {"shape", "law", "period", "duration", "gains", "reference", "robots"});
  TriangleSetup s;
  const std::string file_law = r.text(r.require(n, "formation", "law", triangleLawNames()), "formation.law");
  try {
    s.law = law.empty() ? triangleLawOf(file_law, "'formation.law'") : triangleLawOf(law, "--law");
  } catch (const ConfigError& e) {
    r.failWith(e.what());
  }
  s.period = r.numberIn(r.require(n, "formation", "period", "s"), "formation.period", 0.0, 10.0, "s", false);
  s.duration = r.numberIn(r.require(n, "formation", "duration", "s"), "formation.duration", 0.0, 3600.0, "s", false);
  refuseShortFormation(r, s.duration, "formation.duration");
  if (n["gains"]) formation_detail::readGains(r, n["gains"], "formation.gains", s.gains);
  const std::string reference = r.text(r.require(n, "formation", "reference", "carrousel"), "formation.reference");
  if (reference != "carrousel") r.fail("formation.reference", "= '" + reference + "' is unknown: accepted carrousel");
  triangle_yaml_detail::readRobots(r, r.require(n, "formation", "robots", "starts (and vehicle, controller)"),
                                   config_dir, s);
  if (!s.kinematic) triangle_yaml_detail::baseTick(r, s.period, s.drone.Ts, s);
  return s;
}

inline TriangleSetup readTriangleFile(const std::string& path, const std::string& config_dir,
                                      const std::string& law = "") {
  return readTriangleFile(loadFormationDocument(path, config_dir), law);
}

// What makes a triangle's robots fly, which refusals of kinematic robots
// where vehicles are needed point to (config/formations/triangle_*.yaml).
inline std::string flyingTriangleKeys() {
  return std::string("formation.robots.vehicle: vehicles/") + TriangleDrone::name() +
         ".yaml, formation.robots.controller: controllers/" + TriangleDroneLaw::name() + ".yaml";
}

// AuRoRA's triangle's entry in the shapes' list (shapes.h): three robots,
// its own laws (flight's --law chooses one).
struct TriangleShapeEntry {
  using Shape = Triangle;
  using File = TriangleSetup;
  static constexpr int kRobots = 3;
  static constexpr bool kNamesItsVehicles = true;
  static const char* name() { return "triangle"; }
  static std::string robotKey(const std::string& what) {
    return "formation.robots." + what + (what == "link" ? "s (one file per drone)" : " (one for the three)");
  }
  static std::string lawRefusal() { return ""; }  // --law chooses its law
  static File read(const FormationDocument& d, const std::string& law) { return readTriangleFile(d, law); }
  // A sweep's (as every entry's, shapes.h): three AR.Drones on the underactuated
  // law; its five laws a sweep's formation_law (0 .. 4).
  using SweepRun = TriangleRun<TriangleDroneLaw>;
  template <class VehicleSet>
  static SweepRun sweepRun(const File& s, const VehicleSet&) { return triangleRun<TriangleDroneLaw>(s); }
  static ShapeSweepFacts sweepFacts(const File& s) {
    ShapeSweepFacts facts;
    facts.duration = s.duration;
    facts.controller = TriangleDroneLaw::name();
    if (s.kinematic) {
      facts.refusal = "has kinematic robots (no formation.robots.vehicle): a sweep flies robots with a law; give its "
                      "robots a vehicle (" + flyingTriangleKeys() + ")";
    }
    return facts;
  }
  template <class F>
  static void withRobotLaw(const std::string&, F&& f) { f(TriangleDroneLaw()); }
  using ParamShape = Shape;
  static constexpr int kSweepLaws = 5;
  static std::string sweepLawNames() { return triangleLawNames(); }
  static ShapedFlight flyTable(const File& file, const FormationFlightOptions& o, FlightTable& table);  // triangle_flight.cpp
  static void fly(const File& file, const FormationFlightOptions& o);  // src/triangle/triangle_flight.cpp
  static std::unique_ptr<FormationCrew> crew(const File& file, const CrewRequest& q);  // src/triangle/triangle_crew.cpp
};

}  // namespace aurora_control
