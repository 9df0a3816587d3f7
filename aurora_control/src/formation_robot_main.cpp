// formation_robot: what formation.launch gives robot N of a formation file
// (docs/formation.md, "In the ROS loop"), read by the formation node's own
// reader (formation_crew.h), so that each robot's sim flies the node's run:
//   --print vehicle    its vehicle file as YAML, with the formation's changes
//                      (every robot's sample_time is the formation's tick; a
//                      Pioneer's kinematic_model), for <param type="yaml">;
//   --print start      its start [x, y, z] in m;
//   --print namespace  its namespace;
//   --print ground     true when it drives on the floor (its vehicle's
//                      kOnGround: formation.launch sends its commands to a
//                      ground robot's driver).
#include <yaml-cpp/yaml.h>

#include <boost/program_options.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "aurora_common/ros/config_dir.h"
#include "aurora_control/formation/formation_crew.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace po = boost::program_options;
using namespace aurora_control;
using aurora_common::ConfigError;

namespace {

struct Options {
  std::string formation, config_dir, vehicle, print;
  int robot = 0;
};

bool parse(int argc, char** argv, Options& o) {
  po::options_description d(
      "usage: formation_robot FORMATION_FILE --robot N --print vehicle|start|namespace|ground [options]\n\n"
      "Prints what formation.launch gives robot N's sim (docs/formation.md, \"In the ROS loop\").\n\noptions");
  d.add_options()("help,h", "this text")("formation", po::value(&o.formation)->required(), "formation YAML")
      ("robot", po::value(&o.robot)->required(), "the robot, 1-based, in the file's order")
      ("print", po::value(&o.print)->required(), "vehicle, start, namespace or ground")
      ("config-dir", po::value(&o.config_dir), "the folder the file's paths are in (default: $AURORA_CONFIG_DIR, else aurora_config's)")
      ("vehicle", po::value(&o.vehicle)->default_value(""), "the vehicle YAML of robots whose formation file names none (the two-drone line's drones)");
  po::positional_options_description positional;
  positional.add("formation", 1);
  po::variables_map vm;
  po::store(po::command_line_parser(argc, argv).options(d).positional(positional).run(), vm);
  if (vm.count("help")) {
    std::cout << d;
    return false;
  }
  po::notify(vm);
  if (o.print != "vehicle" && o.print != "start" && o.print != "namespace" && o.print != "ground") {
    throw ConfigError("--print " + o.print + " is refused: accepted vehicle, start, namespace or ground");
  }
  return true;
}

// The vehicle file's YAML with the formation's values in place of its own.
std::string vehicleYaml(const CrewRobot& r) {
  YAML::Node v = YAML::LoadFile(r.vehicle_file);
  for (const auto& change : r.vehicle_overrides) v[change.first] = change.second;
  YAML::Emitter out;
  out << v;
  return out.c_str();
}

int run(const Options& o) {
  CrewRequest q;
  q.file = o.formation, q.config_dir = o.config_dir.empty() ? aurora_common::configDir() : o.config_dir;
  const FormationDocument file = loadFormationDocument(q.file, q.config_dir);
  withUnnamedVehicleOf(file.shape, [&](auto v) {  // a shape whose file names no vehicle flies --vehicle's
    if (!o.vehicle.empty()) q.vehicle.set<decltype(v)>(aurora_sim::loadVehicleFile<decltype(v)>(o.vehicle), o.vehicle);
  });
  const auto crew = loadFormationCrew(q, file);
  if (o.robot < 1 || o.robot > crew->robots()) {
    throw ConfigError("--robot " + std::to_string(o.robot) + " is refused: the " + crew->shape() + " formation has robots 1 to " +
                      std::to_string(crew->robots()));
  }
  const CrewRobot& r = crew->robot(o.robot - 1);
  if (o.print == "namespace") std::printf("%s\n", r.name_space.c_str());
  if (o.print == "ground") std::printf("%s\n", r.ground ? "true" : "false");
  if (o.print == "start") {
    std::printf("[%s, %s, %s]\n", aurora_common::roundTripText(r.start[0]).c_str(),
                aurora_common::roundTripText(r.start[1]).c_str(), aurora_common::roundTripText(r.start[2]).c_str());
  }
  if (o.print == "vehicle") {
    std::printf("%s\n", vehicleYaml(r).c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Options o;
    if (!parse(argc, argv, o)) return 0;
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "formation_robot: %s\n", e.what());
    return 2;
  }
}
