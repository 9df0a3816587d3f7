// One offline flight's inputs, loaded and checked once for every caller
// (the `flight` tool, Python's aurora.simulate): the vehicle, the
// controller, the task, the delay and an optional link, from their YAML
// files, refused with the node's messages (ConfigError naming the key).
#pragma once

#include <string>

#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/law/law_yaml.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/task/task_yaml.h"
#include "aurora_sim/vehicle_yaml.h"

namespace aurora_control {

struct FlightFiles {
  std::string controller, task, vehicle, link;  // link: "" for the ideal link
  long delay = kDelayNotGiven;                  // [samples]; not given: the link's uplink delay (0 without a link)
  bool no_clamp = false;                        // do not clamp the law's commands (the sim still does)
};

struct FlightSetup {
  LawVehicleParams vehicle;
  ControllerSettings settings;
  Task<double> task;
  long steps = 0;  // steps 0..N of the task (taskStepCount), as the node and report
};

inline FlightSetup loadFlight(const FlightFiles& f) {
  FlightSetup s;
  s.settings = readControllerFile(f.controller).settings;
  // The vehicle its law flies (both AR.Drone laws: ArdroneLawData::Vehicle).
  s.vehicle = aurora_sim::loadVehicleFile<ArdroneLawData::Vehicle>(
      f.vehicle, std::string("the controller '") + lawName(s.settings.law) + "'");
  s.settings.clamp_commands = !f.no_clamp;
  s.settings.vehicle = s.vehicle;
  s.settings.Ts = s.vehicle.Ts;
  if (!f.link.empty()) s.settings.link = readLinkFile(f.link);
  s.settings.delay = delayInForce(f.delay, s.settings.link);  // docs/links.md, "A delay beside a link"
  s.task = readTask(YamlReader("task file '" + f.task + "': "), loadYamlFile("task file", f.task)["task"], "task");
  s.steps = taskStepCount(s.task.duration(), s.vehicle.Ts);
  long samples = 0;
  const std::string refusal = delayRefusal(double(s.settings.delay), false, s.vehicle.Ts, samples);
  if (!refusal.empty()) throw ConfigError("--delay " + std::to_string(s.settings.delay) + " " + refusal);
  if (!delayShorterThanRun(s.settings.delay, s.steps)) {
    throw ConfigError("--delay " + delayRunText(s.settings.delay, s.steps, s.vehicle.Ts));
  }
  const std::string late = latestPacketRefusal(s.settings.link, s.settings.delay, s.steps, s.vehicle.Ts);
  if (!late.empty()) throw ConfigError("--link " + f.link + ": " + late);
  return s;
}

}  // namespace aurora_control
