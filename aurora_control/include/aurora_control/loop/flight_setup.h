// One offline flight's inputs, loaded and checked once for every caller
// (the `flight` tool, Python's aurora.simulate): the vehicle, the
// controller, the task, the delay and an optional link, from their YAML
// files, refused with the node's messages (ConfigError naming the key).
#pragma once

#include <string>

#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/law/compensator_yaml.h"
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

// What every flight reads besides its vehicle and law, for a vehicle of
// sample time Ts: the task (its steps 0..N), the link and the delay in
// force, each checked.
struct FlightCourse {
  Task<double> task;
  long steps = 0;
  LinkParams link;
  long delay = 0;
};

inline FlightCourse loadCourse(const FlightFiles& f, double Ts) {
  FlightCourse c;
  if (!f.link.empty()) c.link = readLinkFile(f.link);
  c.delay = delayInForce(f.delay, c.link);  // docs/links.md, "A delay beside a link"
  c.task = readTask(YamlReader("task file '" + f.task + "': "), loadYamlFile("task file", f.task)["task"], "task");
  c.steps = taskStepCount(c.task.duration(), Ts);
  long samples = 0;
  const std::string refusal = delayRefusal(double(c.delay), false, Ts, samples);
  if (!refusal.empty()) throw ConfigError("--delay " + std::to_string(c.delay) + " " + refusal);
  if (!delayShorterThanRun(c.delay, c.steps)) throw ConfigError("--delay " + delayRunText(c.delay, c.steps, Ts));
  const std::string late = latestPacketRefusal(c.link, c.delay, c.steps, Ts);
  if (!late.empty()) throw ConfigError("--link " + f.link + ": " + late);
  return c;
}

inline FlightSetup loadFlight(const FlightFiles& f) {
  FlightSetup s;
  s.settings = readControllerFile(f.controller).settings;
  // The vehicle its law flies (both AR.Drone laws: ArdroneLawData::Vehicle).
  s.vehicle = aurora_sim::loadVehicleFile<ArdroneLawData::Vehicle>(
      f.vehicle, std::string("the controller '") + lawName(s.settings.law) + "'");
  s.settings.clamp_commands = !f.no_clamp;
  s.settings.vehicle = s.vehicle;
  s.settings.Ts = s.vehicle.Ts;
  const FlightCourse c = loadCourse(f, s.vehicle.Ts);
  s.settings.link = c.link, s.settings.delay = c.delay, s.task = c.task, s.steps = c.steps;
  return s;
}

// The vehicle a controller file's law flies, by name (its file:
// config/vehicles/NAME.yaml): where a flight chooses its vehicle.
inline std::string controllerVehicle(const std::string& controller_file) {
  return controllerFileName(controller_file) == Bebop2Compensator::name() ? aurora_sim::Bebop2::name()
                                                                           : LawVehicle::name();
}

// A rate given (`given`, e.g. "--rate", non-zero `rate`) for a law that has
// none of its own (one flying `vehicle`, controllerVehicle's) is refused.
inline void refuseRateFor(const std::string& vehicle, double rate, const std::string& given) {
  if (rate != 0.0 && vehicle != aurora_sim::Bebop2::name()) {
    throw ConfigError(given + " is refused here: it sets the Bebop 2 compensator's rate (controller "
                      "bebop2_compensator); the AR.Drone's laws and a formation run at the vehicle's rate");
  }
}

// A Bebop 2 flight with its compensator (docs/bebop2.md): the run (the
// vehicle file as plant and as the law's model) and the runner's settings.
// Its driver clamps what it receives, and so does the controller unless
// the file says otherwise; no_clamp clamps nowhere (AuRoRA's simulation).
struct CompensatorFlight {
  StudyRun<Bebop2Compensator, double> run;
  RunnerConfig<double> cfg;
  double rate = 30.0;  // [Hz] the law's
  long steps = 0;
};

// `rate` [Hz]: instead of the file's (0: the file's), named `rate_option`
// in a refusal ("--rate " for the tool, "rate=" for Python).
inline CompensatorFlight loadCompensatorFlight(const FlightFiles& f, double rate = 0.0,
                                               const std::string& rate_option = "--rate ") {
  CompensatorFile file = readCompensatorFile(f.controller);
  const std::string given = rate != 0.0 ? rate_option + YamlReader::fmt(rate)
                                        : "controller file '" + f.controller + "': 'controller.rate' = " +
                                              YamlReader::fmt(file.rate);
  if (rate != 0.0) file.rate = rate;
  const aurora_sim::Bebop2::Params<double> vehicle = aurora_sim::loadVehicleFile<aurora_sim::Bebop2>(
      f.vehicle, std::string("the controller '") + Bebop2Compensator::name() + "'");
  CompensatorFlight s;
  s.rate = file.rate;
  s.run.plant = s.run.model = vehicle;
  s.run.gains = file.gains;
  s.run.gains.period_steps = double(compensatorPeriod(given, file.rate, vehicle.Ts));
  const FlightCourse c = loadCourse(f, vehicle.Ts);
  s.run.delay = c.delay;
  s.cfg.task = c.task, s.cfg.link = c.link, s.steps = c.steps;
  s.cfg.clamp_commands = !f.no_clamp && (!file.has_clamp || file.clamp);
  s.cfg.clamp_at_drone = !f.no_clamp;
  return s;
}

}  // namespace aurora_control
