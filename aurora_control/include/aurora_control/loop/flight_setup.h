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

// What a flight is asked besides its files, named as its caller names them
// in a refusal: the rate of a law with one of its own, no clamp.
struct FlightOptionNames {
  double rate = 0.0;                       // [Hz] instead of its file's (0: the file's)
  std::string rate_option = "--rate ";     // how the rate was given ("--rate ", "rate=")
  std::string no_clamp_option = "--no-clamp";  // how no clamp was asked for ("--no-clamp", "clamp=False")
};

namespace flight_detail {
// A law with a rate of its own (lawHasRate: the compensator's) runs at the
// file's or the given one, a whole number of model steps, shorter than the
// task: the task's steps 0 .. steps - 1 span steps - 1 periods of Ts, and a
// law period that long would run at step 0 alone and its command hold for
// the whole task.
template <class Law>
void applyRate(std::true_type, LawFlight<Law>& s, const YAML::Node& mapping, const FlightFiles& f,
               const FlightOptionNames& o) {
  const double file_rate = mappingRate(mapping, s.run.gains);
  const std::string given = o.rate != 0.0 ? o.rate_option + YamlReader::fmt(o.rate)
                                          : "controller file '" + f.controller + "': 'controller.rate' = " +
                                                YamlReader::fmt(file_rate);
  s.rate = o.rate != 0.0 ? o.rate : file_rate;
  const double Ts = s.run.plant.Ts;
  setLawRate(s.run.gains, s.rate, Ts, given);
  const long period = lawPeriodSteps(s.run.gains);
  if (period >= s.steps - 1) {
    const double task = s.cfg.task.duration();
    throw ConfigError(given + " Hz is refused: the law would run every " + YamlReader::fmt(double(period)) +
                      " steps (" + YamlReader::fmt(double(period) * Ts) + " s), as long as the task (" +
                      YamlReader::fmt(task) + " s) or longer: its first command would be held for the whole flight; "
                      "accepted rates above " + YamlReader::fmt(1.0 / task) + " Hz");
  }
}
template <class Law>
void applyRate(std::false_type, LawFlight<Law>&, const YAML::Node&, const FlightFiles&, const FlightOptionNames&) {}
}  // namespace flight_detail

// Any law's flight from its controller file: its gains by its own reader
// (given the vehicle's Ts), at its rate where it has one of its own (the
// file's, or o.rate), its commands clamped to the unit range, as the
// drivers clamp, unless the file says clamp_commands: false or o asks for
// no clamp (which the vehicle's sim ignores where it clamps anyway:
// kAlwaysClamps). A law that saturates its own commands (lawSaturation: the
// Pioneer's, whose driver clamps nothing) has no clamp, and no clamp to
// leave out: no clamp is refused, named o.no_clamp_option.
template <class Law>
LawFlight<Law> loadLawFlight(const FlightFiles& f, const FlightOptionNames& o = FlightOptionNames()) {
  const char* saturation = lawSaturation<Law>();
  if (saturation && f.no_clamp) throw ConfigError(o.no_clamp_option + " is refused " + saturation);
  LawFlight<Law> s = lawFlight<Law>(f, presetGains<typename Law::Data>());
  const LawFile<Law> file = readLawFile<Law>(f.controller, s.run.plant.Ts);
  s.run.gains = file.gains;
  flight_detail::applyRate(std::integral_constant<bool, lawHasRate<Law>()>(), s, file.mapping, f, o);
  if (saturation) return s;
  s.cfg.clamp_commands = !f.no_clamp && file.clamp;
  s.cfg.clamp_at_drone = Law::Vehicle::kAlwaysClamps || !f.no_clamp;
  return s;
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
  const bool known = withLawNamed(law, [&](auto l) { fly(withPredictor(loadLawFlight<decltype(l)>(f, o), f.controller)); });
  if (!known) {  // refused as the node refuses it, naming the file
    lawNameIn(YamlReader("controller file '" + f.controller + "': "),
              loadYamlFile("controller file", f.controller)["controller"], "controller");
  }
}

}  // namespace aurora_control
