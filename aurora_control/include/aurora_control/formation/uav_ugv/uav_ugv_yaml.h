// A UAV-UGV line formation file (config/formations/line_pioneer_ardrone*.yaml;
// docs/formation.md, "The UAV-UGV line"), read strictly:
//
//   formation:
//     shape: uav_ugv_line
//     tick: 0.03333333333333333   # s: every robot's law and model step, and the layer
//     duration: 130               # s
//     gains: {k1: [6], k2: [6]}   # optional: AuRoRA's
//     robots:                     # robot 1 the Pioneer (the reference), robot 2 the drone
//       - {vehicle: vehicles/pioneer3dx.yaml, kinematic_model: false, controller: {...}, start: [x, y, 0]}
//       - {vehicle: vehicles/ardrone2.yaml, controller: {...}, start: [x, y, z]}
//     (each robot may add `link: links/NAME.yaml`, its link: docs/links.md; and
//     both or neither `namespace: NAME`, their ROS namespaces: pioneer1, ardrone2)
//
// Unknown keys, another robot count, another vehicle or law for a robot,
// a ground robot off the floor, a drone below it: refused naming the key.
#pragma once

#include <string>

#include "aurora_control/formation/formation_file.h"
#include "aurora_control/formation/line/line_formation.h"  // its parameters are named as the line's
#include "aurora_control/formation/uav_ugv/uav_ugv_run.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_control {

namespace uav_ugv_detail {

// A robot's start [x, y, z] [m], its height within [lo, hi] (`why` says it).
inline void readStart(const YamlReader& r, const YAML::Node& n, const std::string& key, double lo, double hi,
                      const std::string& why, double start[3]) {
  const std::vector<double> s =
      formation_detail::numbers(r, r.require(n, key, "start", "[x, y, z] in m"), r.key(key, "start"), 3);
  for (int i = 0; i < 3; ++i) start[i] = s[i];
  formation_detail::refuseStartHeight(r, r.key(key, "start"), start, lo, hi, why);
}

// The robot's controller mapping, whose name must be `law`.
inline YAML::Node controllerOf(const YamlReader& r, const YAML::Node& n, const std::string& key, const char* law) {
  const std::string ckey = r.key(key, "controller");
  const YAML::Node c = r.require(n, key, "controller", std::string("a mapping {name: ") + law + ", gains ...}");
  if (!c.IsMap()) r.fail(ckey, std::string("must be a mapping {name: ") + law + ", gains ...}");
  const std::string name = r.text(r.require(c, ckey, "name", law), r.key(ckey, "name"));
  if (name != law) r.fail(r.key(ckey, "name"), "= '" + name + "' is refused: this robot flies " + law);
  return c;
}

// Robot `index`'s optional `link` (a link file, docs/links.md): its uplink
// delay is the robot's delay unless --delay gives one.
inline void readRobotLink(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          const std::string& config_dir, int index, UavUgvLineSetup& s) {
  if (!n["link"]) return;
  s.link[index] = formation_detail::linkFileAt(r, n["link"], r.key(key, "link"), config_dir);
  s.delay[index] = delayInForce(kDelayNotGiven, s.link[index]);
}

// A robot's vehicle file (robots[i].vehicle: vehicles/NAME.yaml of the
// robot's vehicle), in the config folder.
template <class Vehicle>
std::string vehicleFileAt(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          const std::string& config_dir) {
  const std::string hint = std::string("vehicles/") + Vehicle::name() + ".yaml";
  return formation_detail::inConfig(r.text(r.require(n, key, "vehicle", hint), r.key(key, "vehicle")), config_dir);
}

inline void readGround(const YamlReader& r, const YAML::Node& n, const std::string& key,
                       const std::string& config_dir, UavUgvLineSetup& s) {
  r.onlyKeys(n, key, {"namespace", "vehicle", "kinematic_model", "controller", "start", "link"});
  if (n["namespace"]) s.name_space[0] = formation_detail::namespaceAt(r, n["namespace"], r.key(key, "namespace"));
  const std::string file = vehicleFileAt<UavUgvGround>(r, n, key, config_dir);
  s.ground = aurora_sim::loadVehicleFile<UavUgvGround>(file, "the UAV-UGV line's robot 1");
  s.vehicle_file[0] = file;
  if (n["kinematic_model"]) s.ground.kinematic = r.boolean(n["kinematic_model"], r.key(key, "kinematic_model")) ? 1 : 0;
  const YAML::Node c = controllerOf(r, n, key, UavUgvGroundLaw::name());
  readGainsOf(UavUgvGroundLaw(), r, c, r.key(key, "controller"), s.ground_gains, s.tick);
  readStart(r, n, key, 0.0, 0.0, "accepted z = 0 (a ground robot's control point lies on the floor)", s.ground_start);
  readRobotLink(r, n, key, config_dir, 0, s);
}

inline void readDrone(const YamlReader& r, const YAML::Node& n, const std::string& key, const std::string& config_dir,
                      UavUgvLineSetup& s) {
  r.onlyKeys(n, key, {"namespace", "vehicle", "controller", "start", "link"});
  if (n["namespace"]) s.name_space[1] = formation_detail::namespaceAt(r, n["namespace"], r.key(key, "namespace"));
  const std::string file = vehicleFileAt<UavUgvDrone>(r, n, key, config_dir);
  s.drone = aurora_sim::loadVehicleFile<UavUgvDrone>(file, "the UAV-UGV line's robot 2");
  s.vehicle_file[1] = file;
  LawSettings<UavUgvDroneLaw::Data> set;
  readLawMapping(r, controllerOf(r, n, key, UavUgvDroneLaw::name()), r.key(key, "controller"), set);
  s.drone_gains = set.gains;
  readStart(r, n, key, 0.0, formation_detail::kHighestStart, "", s.drone_start);
  readRobotLink(r, n, key, config_dir, 1, s);
}

}  // namespace uav_ugv_detail

inline UavUgvLineSetup readUavUgvLineFile(const FormationDocument& d) {
  using namespace uav_ugv_detail;
  const YamlReader r = formationReader(d);
  const std::string& config_dir = d.config_dir;
  const YAML::Node n = formation_detail::formationSection(r, d, {"shape", "tick", "duration", "gains", "robots"});
  UavUgvLineSetup s;
  UavUgvLine<double>::defaultGains(s.k1, s.k2);
  s.tick = r.numberIn(r.require(n, "formation", "tick", "s (AuRoRA's 1/30)"), "formation.tick", 0.0, 1.0, "s", false);
  s.duration = r.numberIn(r.require(n, "formation", "duration", "s"), "formation.duration", 0.0, 3600.0, "s", false);
  refuseShortFormation(r, s.duration, "formation.duration");
  if (n["gains"]) {
    FormationGains<double, 6> g;
    for (int i = 0; i < 6; ++i) g.k1[i] = s.k1[i], g.k2[i] = s.k2[i];
    formation_detail::readGains(r, n["gains"], "formation.gains", g);
    for (int i = 0; i < 6; ++i) s.k1[i] = g.k1[i], s.k2[i] = g.k2[i];
  }
  const YAML::Node robots = r.require(n, "formation", "robots", "the ground robot, then the drone");
  if (!robots.IsSequence() || robots.size() != 2) {
    r.fail("formation.robots", "must list 2 robots: the ground robot (robot 1, the reference), then the drone");
  }
  readGround(r, robots[0], "formation.robots[0]", config_dir, s);
  readDrone(r, robots[1], "formation.robots[1]", config_dir, s);
  if (bool(robots[0]["namespace"]) != bool(robots[1]["namespace"])) {
    // Both or neither: formation.launch places each robot's nodes by the file's names.
    r.fail(std::string("formation.robots[") + (robots[0]["namespace"] ? "1" : "0") + "].namespace",
           "is missing: name both robots' namespaces or neither (" + UavUgvLineSetup().name_space[0] + ", " +
               UavUgvLineSetup().name_space[1] + " by default)");
  }
  formation_detail::refuseSharedNamespaces(r, "formation.robots[1].namespace", {s.name_space[0], s.name_space[1]});
  double gap = 0.0;
  for (int i = 0; i < 3; ++i) gap += (s.drone_start[i] - s.ground_start[i]) * (s.drone_start[i] - s.ground_start[i]);
  if (!(gap > 0.0)) {
    r.fail("formation.robots[1].start", "is robot 1's: rho = 0 and the line's angles are undefined; accepted a start "
                                        "apart from the ground robot's");
  }
  s.ground.Ts = s.tick;  // every robot steps at the formation's tick (AuRoRA's 2018 line: 1/30 s)
  s.drone.Ts = s.tick;
  return s;
}

inline UavUgvLineSetup readUavUgvLineFile(const std::string& path, const std::string& config_dir) {
  return readUavUgvLineFile(loadFormationDocument(path, config_dir));
}

// AuRoRA's UAV-UGV line's entry in the shapes' list (shapes.h): a ground
// robot and a drone, one law each.
struct UavUgvShapeEntry {
  using Shape = UavUgvShape;
  using File = UavUgvLineSetup;
  static constexpr int kRobots = 2;
  static constexpr bool kNamesItsVehicles = true;
  static const char* name() { return "uav_ugv_line"; }
  static std::string robotKey(const std::string& what) { return "formation.robots[i]." + what; }
  static std::string lawRefusal() { return "the UAV-UGV line has one law (docs/formation.md, \"The UAV-UGV line\")"; }
  static File read(const FormationDocument& d, const std::string&) { return readUavUgvLineFile(d); }
  // A sweep's (as every entry's, shapes.h): its parameters are named as the line's
  // (2 robots, 6 variables of the same names).
  using SweepRun = UavUgvRun;
  template <class VehicleSet>
  static SweepRun sweepRun(const File& s, const VehicleSet&) { return uavUgvRun(s); }
  static ShapeSweepFacts sweepFacts(const File& s) {
    ShapeSweepFacts facts;
    facts.duration = s.duration;
    facts.controller = std::string(UavUgvGroundLaw::name()) + " + " + UavUgvDroneLaw::name();
    return facts;
  }
  template <class F>
  static void withRobotLaw(const std::string&, F&& f) { f(UavUgvRobots()); }
  using ParamShape = LineFormation<double>;
  static constexpr int kSweepLaws = 0;
  static std::string sweepLawNames() { return ""; }
  static ShapedFlight flyTable(const File& file, const FormationFlightOptions& o, FlightTable& table);  // uav_ugv_flight.cpp
  static void fly(const File& file, const FormationFlightOptions& o);  // src/uav_ugv/uav_ugv_flight.cpp
  static std::unique_ptr<FormationCrew> crew(const File& file, const CrewRequest& q);  // src/uav_ugv/uav_ugv_crew.cpp
};

}  // namespace aurora_control
