// One offline flight's inputs, loaded and checked once for every caller
// (the `flight` tool, Python's aurora.simulate): the vehicle, the
// controller, the task, the delay and an optional link, from their YAML
// files, refused with the node's messages (ConfigError naming the key).
#pragma once

#include <string>
#include <type_traits>

#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/loop/law_settings_yaml.h"  // every law's controller-file reader
#include "aurora_control/params/limits.h"
#include "aurora_control/predictor/predictor_yaml.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/task/task_yaml.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_control {

struct FlightFiles {
  std::string controller, task, vehicle, link;  // link: "" for the ideal link
  long delay = kDelayNotGiven;                  // [samples]; not given: the link's uplink delay (0 without a link)
  bool no_clamp = false;                        // do not clamp the law's commands (the sim still does)
};

// What every flight reads besides its vehicle and law, for a vehicle of
// sample time Ts: the task (its steps 0..N, at the vehicle's heights), the
// link and the delay in force, each checked.
struct FlightCourse {
  Task<double> task;
  long steps = 0;
  LinkParams link;
  long delay = 0;
};

inline FlightCourse loadCourse(const FlightFiles& f, double Ts, const TaskHeights& heights = TaskHeights::flying()) {
  FlightCourse c;
  if (!f.link.empty()) c.link = readLinkFile(f.link);
  c.delay = delayInForce(f.delay, c.link);  // docs/links.md, "A delay beside a link"
  c.task = readTask(YamlReader("task file '" + f.task + "': "), loadYamlFile("task file", f.task)["task"], "task",
                    heights);
  c.steps = taskStepCount(c.task.duration(), Ts);
  long samples = 0;
  const std::string refusal = delayRefusal(double(c.delay), false, Ts, samples);
  if (!refusal.empty()) throw ConfigError("--delay " + std::to_string(c.delay) + " " + refusal);
  if (!delayShorterThanRun(c.delay, c.steps)) throw ConfigError("--delay " + delayRunText(c.delay, c.steps, Ts));
  const std::string late = latestPacketRefusal(c.link, c.delay, c.steps, Ts);
  if (!late.empty()) throw ConfigError("--link " + f.link + ": " + late);
  return c;
}

// The vehicle a controller file's law flies, by name (its file:
// config/vehicles/NAME.yaml).
inline std::string controllerVehicle(const std::string& controller_file) {
  return vehicleOfLaw(controllerFileName(controller_file));
}

// A rate given (`given`, e.g. "--rate", non-zero `rate`) for law `law` (a
// controller file's law name) that has none of its own (lawHasRate) is
// refused, naming the laws that have one.
inline void refuseRateFor(const std::string& law, double rate, const std::string& given) {
  const auto with = [](auto&& f) { forEachLawWithARate(f); };
  if (rate == 0.0 || aurora_common::isEntryName(with, law)) return;
  throw ConfigError(given + " is refused here: it sets the rate of a law that runs at one of its own (" +
                    aurora_common::entryNames(with) + "); '" + law + "' and a formation run at the vehicle's rate");
}

// A flight of `Law` with `gains` on the vehicle file (as plant and as the
// law's model) over the files' course; no clamp yet.
template <class Law>
LawFlight<Law> lawFlight(const FlightFiles& f, const typename Law::template Gains<double>& gains) {
  using Vehicle = typename Law::Vehicle;
  const typename Vehicle::template Params<double> vehicle =
      aurora_sim::loadVehicleFile<Vehicle>(f.vehicle, std::string("the controller '") + Law::name() + "'");
  LawFlight<Law> s;
  s.run.plant = s.run.model = vehicle;
  s.run.gains = gains;
  const FlightCourse c = loadCourse(f, vehicle.Ts, TaskHeights::of<Vehicle>());
  s.run.delay = c.delay;
  s.cfg.task = c.task, s.cfg.link = c.link, s.steps = c.steps;
  return s;
}

// A Bebop 2 flight with its compensator (docs/bebop2.md). Its driver clamps
// what it receives, and so does the controller unless the file says
// otherwise; no_clamp clamps nowhere (AuRoRA's simulation). `rate` [Hz]:
// instead of the file's (0: the file's), named `rate_option` in a refusal
// ("--rate " for the tool, "rate=" for Python).
inline LawFlight<Bebop2Compensator> loadCompensatorFlight(const FlightFiles& f, double rate = 0.0,
                                                          const std::string& rate_option = "--rate ") {
  CompensatorFile file = readCompensatorFile(f.controller);
  const std::string given = rate != 0.0 ? rate_option + YamlReader::fmt(rate)
                                        : "controller file '" + f.controller + "': 'controller.rate' = " +
                                              YamlReader::fmt(file.rate);
  if (rate != 0.0) file.rate = rate;
  LawFlight<Bebop2Compensator> s = lawFlight<Bebop2Compensator>(f, file.gains);
  s.rate = file.rate;
  s.run.gains.period_steps = double(compensatorPeriod(given, file.rate, s.run.plant.Ts));
  // The task's steps 0 .. steps - 1 span steps - 1 periods of Ts: a law
  // period that long would run at step 0 alone and its command hold for the
  // whole task.
  if (long(s.run.gains.period_steps) >= s.steps - 1) {
    const double task = s.cfg.task.duration();
    throw ConfigError(given + " Hz is refused: the law would run every " + YamlReader::fmt(s.run.gains.period_steps) +
                      " steps (" + YamlReader::fmt(s.run.gains.period_steps * s.run.plant.Ts) + " s), as long as the task (" +
                      YamlReader::fmt(task) + " s) or longer: its first command would be held for the whole flight; "
                      "accepted rates above " + YamlReader::fmt(1.0 / task) + " Hz");
  }
  s.cfg.clamp_commands = !f.no_clamp && (!file.has_clamp || file.clamp);
  s.cfg.clamp_at_drone = !f.no_clamp;
  return s;
}

// Any law's flight from its controller file: its gains by its own reader
// (readLawGains, given the vehicle's Ts), its commands clamped to the unit
// range, as the drivers clamp, unless no_clamp. A law that saturates its
// own commands (lawSaturation: the Pioneer's, whose driver clamps nothing)
// has no clamp, and no clamp to leave out: no_clamp is refused, named
// `no_clamp_option` ("--no-clamp", "clamp=False"). A law with options of its
// own has a loadFlightOf of its own (below).
template <class Law>
LawFlight<Law> loadLawFlight(const FlightFiles& f, const std::string& no_clamp_option = "--no-clamp") {
  const char* saturation = lawSaturation<Law>();
  if (saturation && f.no_clamp) throw ConfigError(no_clamp_option + " is refused " + saturation);
  LawFlight<Law> s = lawFlight<Law>(f, presetGains<typename Law::Data>());
  const LawFile<Law> file = readLawFile<Law>(f.controller, s.run.plant.Ts);
  s.run.gains = file.gains;
  if (saturation) return s;
  s.cfg.clamp_commands = !f.no_clamp && file.clamp;
  s.cfg.clamp_at_drone = Law::Vehicle::kAlwaysClamps || !f.no_clamp;
  return s;
}

// The flight of law `law` from the files (withFlight's, per law): the
// compensator's with its rate, any other law's loadLawFlight.
struct FlightOptionNames {
  double rate;                  // [Hz] the compensator's instead of its file's (0: the file's)
  std::string rate_option;      // how the rate was given, for a refusal ("--rate ", "rate=")
  std::string no_clamp_option;  // how no clamp was asked for ("--no-clamp", "clamp=False")
};
template <class Law>
LawFlight<Law> loadFlightOf(Law, const FlightFiles& f, const FlightOptionNames& o) {
  return loadLawFlight<Law>(f, o.no_clamp_option);
}
inline LawFlight<Bebop2Compensator> loadFlightOf(Bebop2Compensator, const FlightFiles& f, const FlightOptionNames& o) {
  return loadCompensatorFlight(f, o.rate, o.rate_option);
}

// The controller file's predictor (predictor_yaml.h) put into flight `s`:
// its command delay the link's downlink base delay, the vehicle's clamp
// its (docs/predictor.md, "The commands applied").
template <class Law>
LawFlight<Law> withPredictor(LawFlight<Law> s, const std::string& controller_file) {
  const LinkParams& link = s.cfg.link;
  const long history = link.ideal() ? s.run.delay : link.historyNeeded(s.run.delay);
  s.predictor = predictorRun<Law>(readControllerPredictor(controller_file), s.run.plant.Ts, link.downlink.delay,
                                  history, s.cfg.clamp_at_drone);
  return s;
}

// Calls fly(LawFlight<Law>) with the flight of the controller file's law
// `law` (its controller.name): the one place a flight's law is chosen, for
// the flight tool and Python.
template <class Fly>
void withFlight(const FlightFiles& f, const std::string& law, const FlightOptionNames& o, Fly&& fly) {
  const bool known = withLawNamed(law, [&](auto l) { fly(withPredictor(loadFlightOf(l, f, o), f.controller)); });
  if (!known) {  // refused as the node refuses it, naming the file
    lawNameIn(YamlReader("controller file '" + f.controller + "': "),
              loadYamlFile("controller file", f.controller)["controller"], "controller");
  }
}

}  // namespace aurora_control
