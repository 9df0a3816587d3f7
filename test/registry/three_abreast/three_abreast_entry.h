// The registry test's shape (issue 53, 6): three robots abreast
// (aurora_sweep/test/three_abreast.h: robot 1's position and the other two's
// offsets from it), each a test_quad flying test_quad_pd (../test_quad/),
// held at one point. Its entry in the shapes' list (shapes.h) gives what the
// formation node reads: its name, its robots, its file's reader and its
// crew (three_abreast_crew.cpp). Declared here only; it joins the shapes'
// list of a test build of the formation node (extra_shapes.h). Its file:
//
//   formation:
//     shape: three_abreast
//     period: 0.2                          # s: the layer's, whole robot steps
//     duration: 20                         # s
//     position: [x, y, z]                  # m: robot 1 held there
//     offsets: [[dx, dy, dz], [dx, dy, dz]]  # m: robots 2 and 3 from robot 1
//     robots:
//       namespaces: [quad1, quad2, quad3]
//       starts: [[x, y, z], [x, y, z], [x, y, z]]   # m
//       vehicle: test_quad/test_quad.yaml           # in the config folder
//       controller: test_quad/test_quad_pd.yaml
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_document.h"
#include "aurora_control/formation/formation_file.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/loop/law_yaml.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "test_quad/test_quad_pd.h"
#include "three_abreast.h"

namespace registry {

using ThreeAbreastRun = aurora_control::FormationRun<double, three_abreast::ThreeAbreast<double>, TestQuadPd>;

// A three_abreast file, read: the run (robots, layer, reference), the
// robots' namespaces, their vehicle file and law.
struct ThreeAbreastFile {
  ThreeAbreastRun run;
  aurora_control::LawSettings<TestQuadPd> law;
  std::string name_space[3] = {"quad1", "quad2", "quad3"};
  std::string vehicle_file;
  long ticks = 0;
};

namespace three_abreast_detail {

using aurora_control::YamlReader;
namespace fd = aurora_control::formation_detail;

// The robots: namespaces, starts, their vehicle file and controller file.
inline void readRobots(const YamlReader& r, const YAML::Node& n, const std::string& config_dir, ThreeAbreastFile& f) {
  const std::string key = "formation.robots";
  r.onlyKeys(n, key, {"namespaces", "starts", "vehicle", "controller"});
  const YAML::Node names = r.require(n, key, "namespaces", "three ROS namespaces");
  if (!names.IsSequence() || names.size() != 3) r.fail(r.key(key, "namespaces"), "must list 3 namespaces, one per robot");
  const YAML::Node starts = r.require(n, key, "starts", "three [x, y, z] in m");
  if (!starts.IsSequence() || starts.size() != 3) r.fail(r.key(key, "starts"), "must list 3 robots' [x, y, z] in m");
  f.vehicle_file = fd::inConfig(r.text(r.require(n, key, "vehicle", "a test_quad file"), r.key(key, "vehicle")), config_dir);
  const auto vehicle = aurora_sim::loadVehicleFile<TestQuad>(f.vehicle_file, "the three_abreast robots");
  const std::string law_file =
      fd::inConfig(r.text(r.require(n, key, "controller", "a test_quad_pd file"), r.key(key, "controller")), config_dir);
  f.law = aurora_control::readControllerFile<TestQuadPd>(law_file);
  for (int d = 0; d < 3; ++d) {
    const std::string at = "[" + std::to_string(d) + "]";
    f.name_space[d] = fd::namespaceAt(r, names[d], r.key(key, "namespaces") + at);
    const std::vector<double> p = fd::numbers(r, starts[d], r.key(key, "starts") + at, 3);
    auto& robot = f.run.drone[d];
    for (int i = 0; i < 3; ++i) robot.start[i] = p[i];
    fd::refuseStartHeight(r, r.key(key, "starts") + at, robot.start);
    robot.plant = robot.model = vehicle;
    robot.gains = f.law.gains;
  }
  fd::refuseSharedNamespaces(r, r.key(key, "namespaces"), {f.name_space[0], f.name_space[1], f.name_space[2]});
}

// The layer's period in whole robot steps (the line's rule, wholeRobotSteps).
inline long periodSteps(const YamlReader& r, double period, double Ts) {
  const long p = aurora_control::wholeRobotSteps(period, Ts);
  if (p == 0) {
    r.fail("formation.period", "= " + YamlReader::fmt(period) + " s is refused: accepted whole robot steps of " +
                                   YamlReader::fmt(Ts) + " s");
  }
  return p;
}

// The held formation: robot 1's position, then the two offsets.
inline void readHeld(const YamlReader& r, const YAML::Node& n, ThreeAbreastFile& f) {
  const std::vector<double> p = fd::numbers(r, r.require(n, "formation", "position", "[x, y, z] in m"),
                                            "formation.position", 3);
  const YAML::Node offsets = r.require(n, "formation", "offsets", "robots 2 and 3's [dx, dy, dz] from robot 1, in m");
  if (!offsets.IsSequence() || offsets.size() != 2) r.fail("formation.offsets", "must list 2 offsets [dx, dy, dz] in m");
  for (int i = 0; i < 3; ++i) f.run.reference.Q[i] = p[i];
  for (int o = 0; o < 2; ++o) {
    const std::vector<double> v = fd::numbers(r, offsets[o], "formation.offsets[" + std::to_string(o) + "]", 3);
    for (int i = 0; i < 3; ++i) f.run.reference.Q[3 + 3 * o + i] = v[i];
  }
}

}  // namespace three_abreast_detail

inline ThreeAbreastFile readThreeAbreastFile(const aurora_control::FormationDocument& d) {
  namespace fd = aurora_control::formation_detail;
  const aurora_control::YamlReader r = aurora_control::formationReader(d);
  const YAML::Node n = fd::formationSection(r, d, {"shape", "period", "duration", "position", "offsets", "robots"});
  ThreeAbreastFile f;
  three_abreast_detail::readRobots(r, r.require(n, "formation", "robots", "namespaces, starts, vehicle, controller"),
                                   d.config_dir, f);
  const double Ts = f.run.drone[0].plant.Ts;
  const double period = r.numberIn(r.require(n, "formation", "period", "s"), "formation.period", 0.0, 10.0, "s", false);
  f.run.schedule.period_ticks = three_abreast_detail::periodSteps(r, period, Ts);
  const double duration =
      r.numberIn(r.require(n, "formation", "duration", "s"), "formation.duration", 0.0, 3600.0, "s", false);
  aurora_control::refuseShortFormation(r, duration, "formation.duration");
  f.run.reference.duration = duration;
  f.ticks = aurora_control::formationTicks(duration, Ts);
  three_abreast_detail::readHeld(r, n, f);
  return f;
}

// Its entry in the shapes' list: what the formation node reads.
struct ThreeAbreastEntry {
  using Shape = three_abreast::ThreeAbreast<double>;
  using File = ThreeAbreastFile;
  static constexpr int kRobots = 3;
  static constexpr bool kNamesItsVehicles = true;
  static const char* name() { return "three_abreast"; }
  static std::string robotKey(const std::string& what) { return "formation.robots." + what; }
  static std::string lawRefusal() { return "its robots fly their file's controller"; }
  static std::string sweepLawNames() { return ""; }
  static File read(const aurora_control::FormationDocument& d, const std::string&) { return readThreeAbreastFile(d); }
  static std::unique_ptr<aurora_control::FormationCrew> crew(const File& file,
                                                             const aurora_control::CrewRequest& q);  // three_abreast_crew.cpp
};

}  // namespace registry
