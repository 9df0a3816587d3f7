// The launch files' defaults (config/bringup, its README.md): one file per
// vehicle, law, driver and shape, read by roslaunch's $(eval) without a YAML
// parser. Each file is checked against the lists of vehicles and laws, and
// against what that reading gives.
#include <dirent.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "aurora_control/formation/shapes.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "config_dir.h"

namespace {

using aurora_tests::kConfig;

std::string strip(const std::string& s, const std::string& chars = " \t\r") {
  const auto first = s.find_first_not_of(chars);
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(chars) - first + 1);
}

// What the launch files' one-line reader gives: each line with a ':' not
// starting with '#', split at the first ':', the value cut at '#', blanks
// and quotes stripped (each launch file's `read_flat`).
std::map<std::string, std::string> launchReading(const std::string& path) {
  std::map<std::string, std::string> read;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos || strip(line).rfind('#', 0) == 0) continue;
    const std::string rest = line.substr(colon + 1);
    read[strip(line.substr(0, colon))] = strip(strip(rest.substr(0, rest.find('#'))), "'\"");
  }
  return read;
}

// The file's keys as YAML reads them; fails unless every value is a scalar
// and the launch files' reading gives the same keys and values.
std::map<std::string, std::string> readDefaults(const std::string& path) {
  std::map<std::string, std::string> yaml;
  const YAML::Node root = YAML::LoadFile(path);
  EXPECT_TRUE(root.IsMap()) << path;
  for (const auto& kv : root) {
    EXPECT_TRUE(kv.second.IsScalar()) << path << ": '" << kv.first.as<std::string>()
                                      << "' is not a plain value (the launch files read flat lines)";
    if (kv.second.IsScalar()) yaml[kv.first.as<std::string>()] = kv.second.as<std::string>();
  }
  EXPECT_EQ(launchReading(path), yaml) << path << ": roslaunch's reading differs from YAML's";
  return yaml;
}

std::vector<std::string> namesIn(const std::string& dir) {
  std::vector<std::string> names;
  DIR* d = opendir(dir.c_str());
  if (!d) return names;
  while (const dirent* e = readdir(d)) {
    const std::string f = e->d_name;
    if (f.size() > 5 && f.compare(f.size() - 5, 5, ".yaml") == 0) names.push_back(f.substr(0, f.size() - 5));
  }
  closedir(d);
  return names;
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

// The law a controller file names (controller.name).
std::string lawOfControllerFile(const std::string& name) {
  return YAML::LoadFile(kConfig + "/controllers/" + name + ".yaml")["controller"]["name"].as<std::string>();
}

std::string vehicleOfLawFile(const std::string& law) {
  return readDefaults(kConfig + "/bringup/laws/" + law + ".yaml")["vehicle"];
}

void expectKeys(const std::map<std::string, std::string>& read, const std::set<std::string>& keys,
                const std::string& path) {
  std::set<std::string> given;
  for (const auto& kv : read) given.insert(kv.first);
  EXPECT_EQ(given, keys) << path;
}

}  // namespace

TEST(LaunchDefaults, EveryLawNamesTheVehicleItFlies) {
  std::set<std::string> laws;
  aurora_control::forEachLaw([&](auto law) {
    using Law = decltype(law);
    laws.insert(law.name());
    const std::string path = kConfig + "/bringup/laws/" + law.name() + ".yaml";
    ASSERT_TRUE(exists(path)) << "real.launch reads " << path << " for a controller file of " << law.name();
    const auto read = readDefaults(path);
    expectKeys(read, {"vehicle"}, path);
    EXPECT_EQ(read.at("vehicle"), Law::Vehicle::name()) << path;
  });
  for (const auto& name : namesIn(kConfig + "/bringup/laws")) EXPECT_TRUE(laws.count(name)) << name << ": no such law";
}

TEST(LaunchDefaults, EveryVehicleFliesItsOwnLawAndTaskByDefault) {
  std::set<std::string> vehicles;
  aurora_sim::forEachVehicle([&](auto vehicle) {
    const std::string name = decltype(vehicle)::name();
    vehicles.insert(name);
    const std::string path = kConfig + "/bringup/vehicles/" + name + ".yaml";
    ASSERT_TRUE(exists(path)) << "sim.launch reads " << path << " for a vehicle file of type " << name;
    const auto read = readDefaults(path);
    expectKeys(read, {"namespace", "controller", "task"}, path);
    EXPECT_EQ(vehicleOfLawFile(lawOfControllerFile(read.at("controller"))), name) << path;
    EXPECT_TRUE(exists(kConfig + "/tasks/" + read.at("task") + ".yaml")) << path;
  });
  for (const auto& name : namesIn(kConfig + "/bringup/vehicles")) {
    EXPECT_TRUE(vehicles.count(name)) << name << ": no such vehicle";
  }
}

TEST(LaunchDefaults, EveryDriverGivesItsTopicsAndALawOfItsOwn) {
  const auto drivers = namesIn(kConfig + "/bringup/drivers");
  EXPECT_FALSE(drivers.empty()) << kConfig << "/bringup/drivers holds no driver";
  for (const auto& driver : drivers) {
    const std::string path = kConfig + "/bringup/drivers/" + driver + ".yaml";
    const auto read = readDefaults(path);
    expectKeys(read, {"namespace", "cmd_vel", "takeoff_land_prefix", "airborne", "robot_namespace", "controller",
                      "task", "safety"},
               path);
    const std::string law = lawOfControllerFile(read.at("controller"));
    EXPECT_TRUE(aurora_control::isKnownLawName(law)) << path;
    EXPECT_TRUE(read.at("airborne") == "true" || read.at("airborne") == "false") << path;
    EXPECT_EQ(read.at("namespace").front(), '/') << path;
    EXPECT_EQ(read.at("namespace").back(), '/') << path;
    EXPECT_TRUE(exists(kConfig + "/tasks/" + read.at("task") + ".yaml")) << path;
    EXPECT_TRUE(exists(kConfig + "/safety/" + read.at("safety") + ".yaml")) << path;
  }
}

TEST(LaunchDefaults, EveryShapeNamesItsRobotsAndTheOneOnTheFloor) {
  std::set<std::string> shapes;
  aurora_control::forEachShape([&](auto entry) {
    using Entry = decltype(entry);
    shapes.insert(Entry::name());
    const std::string path = kConfig + "/bringup/shapes/" + Entry::name() + ".yaml";
    ASSERT_TRUE(exists(path)) << "formation.launch reads " << path << " for a formation file of shape " << Entry::name();
    const auto read = readDefaults(path);
    expectKeys(read, {"robots", "ground_robot", "vehicle"}, path);
    // The robots' vehicle where the file names none (formation.launch's vehicle:= default): the
    // entry's; none where the file names them (there vehicle:= is refused).
    EXPECT_EQ(read.at("vehicle"), aurora_control::unnamedVehicleName(entry)) << path;
    std::istringstream robots(read.at("robots"));
    std::vector<std::string> names{std::istream_iterator<std::string>(robots), std::istream_iterator<std::string>()};
    const int robots_of_shape = Entry::kRobots;  // a copy: EXPECT_EQ binds references
    EXPECT_EQ(static_cast<int>(names.size()), robots_of_shape) << path;
    const int ground = std::stoi(read.at("ground_robot"));
    EXPECT_TRUE(ground >= 0 && ground <= Entry::kRobots) << path;
  });
  for (const auto& name : namesIn(kConfig + "/bringup/shapes")) EXPECT_TRUE(shapes.count(name)) << name << ": no such shape";
}

// The reading the test compares YAML's with: a comment, a quoted empty
// value and a value with a colon read as the launch files read them.
TEST(LaunchDefaults, TheLaunchReadingIsTheLaunchFilesOne) {
  const std::string path = ::testing::TempDir() + "launch_defaults_reading.yaml";
  std::ofstream(path) << "# a: comment\nnamespace: /bebop/   # where\nprefix: ''\nurl: http://x\n";
  const std::map<std::string, std::string> expected{{"namespace", "/bebop/"}, {"prefix", ""}, {"url", "http://x"}};
  EXPECT_EQ(launchReading(path), expected);
}
