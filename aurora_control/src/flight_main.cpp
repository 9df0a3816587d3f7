// flight: one whole flight offline (no roscore) with any controller and
// task, on the same core as the controller node (flight_runner.h): the
// lockstep ROS loop flies exactly this trajectory. The controller file's
// law chooses the vehicle: the AR.Drone's laws, the Bebop 2's compensator
// (docs/bebop2.md) or the Pioneer P3-DX's laws (docs/pioneer3dx.md). Prints the tracking error
// per lap (per waypoint segment for missions), the controller's metrics and
// the cost of the law per step; --csv writes the trajectory. --formation
// flies a formation file instead (formation_flight.h).
#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "aurora_common/number_text.h"
#include "aurora_control/loop/flight_setup.h"
#include "aurora_common/ros/config_dir.h"
#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/params/shipped_files.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "option_values.h"

namespace po = boost::program_options;
using namespace aurora_control;

namespace {

struct Options {
  std::string controller, task, vehicle, csv, link, formation, config, law;
  std::vector<long> delays;  // one (a flight), or one per robot (a formation)
  long delay = 0;            // a flight's
  double rate = 0.0;         // [Hz] the compensator's, instead of its file's (0: the file's)
  std::string flown_law;     // the controller file's law (its controller.name; a flight's)
  std::string flown;         // the vehicle it flies (vehicleOfLaw)
  bool no_clamp = false;
  std::vector<std::string> given;  // the options given on the command line (refuseFlightOnlyOptions)
};

// A formation file gives each robot's link and controller and never clamps
// (AuRoRA's formation scripts do not): the flight's --link, --no-clamp,
// --controller and --task would be ignored, so they are refused, naming the
// file's key for the file's shape (its entry's robotKey); so is --vehicle
// for a shape whose file names its robots' vehicles (aurora.simulate_formation's
// vehicle= alike).
template <class ShapeEntry>
void refuseFlightOnlyOptions(const std::vector<std::string>& given, ShapeEntry) {
  const std::string vehicle = ShapeEntry::kNamesItsVehicles ? "vehicle" : "";
  const std::string why[][2] = {
      {"link", "give each robot's link in the formation file (" + ShapeEntry::robotKey("link") + ": links/NAME.yaml)"},
      {"no-clamp", "a formation's commands are never clamped (AuRoRA's formation scripts do not clamp)"},
      {"controller", "give the robots' controllers in the formation file (" + ShapeEntry::robotKey("controller") + ")"},
      {"task", "the formation file's reference is the task"},
      {vehicle, "a formation file of shape '" + std::string(ShapeEntry::name()) + "' names its robots' vehicles (" +
                    ShapeEntry::robotKey("vehicle") + ": vehicles/NAME.yaml)"}};
  for (const auto& w : why) {
    if (!w[0].empty() && std::find(given.begin(), given.end(), w[0]) != given.end()) {
      throw ConfigError("--" + w[0] + " is refused with --formation: " + w[1]);
    }
  }
}

// Flies the formation file with the options: its shape's entry's flight
// (shapes.h), the file read once.
void flyFormationFile(const Options& o) {
  const FormationFlightOptions f{o.formation, o.vehicle, o.csv, o.config, o.delays, o.law};
  const FormationDocument doc = loadFormationDocument(o.formation, o.config);
  withShapeNamed(doc.shape, [&](auto e) { refuseFlightOnlyOptions(o.given, e); });  // an unknown shape: refused next
  withFormationDocument(doc, o.law, [&](auto e, const auto& file) { decltype(e)::fly(file, f); });
}

// The vehicles whose sim clamps in every flight (kAlwaysClamps), by name.
std::string alwaysClamping() {
  return aurora_common::entryNames([](auto&& f) {
    aurora_sim::forEachVehicle([&](auto v) {
      if (decltype(v)::kAlwaysClamps) f(v);
    });
  });
}

void resolve(const po::variables_map& vm, const std::string& config, Options& o);

bool parse(int argc, char** argv, Options& o) {
  const std::string config = o.config = aurora_common::configDir();  // throws: says what to source
  po::options_description d("usage: flight [options]\n\nFlies one task offline with the controller node's core and prints its tracking error.\n\noptions");
  d.add_options()("help,h", "this text")
      ("controller", po::value(&o.controller)->default_value(config + "/controllers/pd_saturated.yaml"), ("controller YAML (law and gains), or a shipped NAME (config/controllers/NAME.yaml; laws: " + knownLawNames() + "); its law chooses the vehicle").c_str())
      ("task", po::value(&o.task)->default_value(config + "/tasks/mission4.yaml"), "task YAML (waypoints, circle, lemniscate), or a shipped NAME (config/tasks/NAME.yaml)")
      ("rate", po::value(&o.rate), ("the rate [Hz] of a law that runs at one of its own (" + aurora_common::entryNames([](auto&& f) { forEachLawWithARate(f); }) + ") instead of its file's: the vehicle's rate divided by whole steps (at 30 Hz: 30, 15, 10, 7.5, 6, 5, ...)").c_str())
      ("vehicle", po::value(&o.vehicle), ("vehicle YAML or a shipped NAME (default: the controller's vehicle, config/vehicles/NAME.yaml: " + lawVehicleNames() + "); with --formation, the drones' of a shape whose file names none (the two-drone line)").c_str())
      ("delay", po::value(&o.delays)->multitoken()->composing(), "feedback delay [samples of Ts], 0 to 2047 (limits.h); with --formation one per robot (default: the file's)")
      ("no-clamp", po::bool_switch(&o.no_clamp), ("do not clamp the law's commands, nor the vehicle's sim (except " + alwaysClamping() + "'s, which clamps as its driver does); refused for a law that saturates its own commands (" + aurora_common::entryNames([](auto&& f) { forEachLawThatSaturates(f); }) + ")").c_str())
      ("formation", po::value(&o.formation), ("formation YAML or a shipped NAME (config/formations/*.yaml, docs/formation.md; shapes: " + knownShapeNames() + "): fly its robots and formation layer instead of --controller and --task").c_str())
      ("law", po::value(&o.law), ("with --formation, the shape's law instead of its file's, for a shape with laws of its own (" + shapeLawNames() + "; docs/formation.md)").c_str())
      ("link", po::value(&o.link), "link YAML or a shipped NAME (config/links/*.yaml, docs/links.md): jitter, losses, a command-path delay; its uplink delay unless --delay is given")
      ("csv", po::value(&o.csv), "write one row per step k = 0..N at round-trip precision: step, t, the vehicle's state after k model steps (x, y, z, phi, theta, psi, dx, dy, dz, dphi, dtheta, dpsi, then its own: a ground robot's u, omega), its commands u1..uN applied at step k (model order), the reference of step k and the tracking error (with --formation: each robot's state and commands, Q and Qd; docs/formation.md)");
  po::variables_map vm;
  po::store(po::command_line_parser(joinOptionValues(argc, argv, d)).options(d).run(), vm);
  if (vm.count("help")) {
    std::cout << d;
    return false;
  }
  po::notify(vm);
  if (o.formation.empty() && vm.count("law")) {
    throw ConfigError("--law " + o.law + " is refused without --formation: it chooses a formation shape's law; a flight's law "
                      "is its --controller file's");
  }
  if (vm.count("law") && o.law.empty()) {
    throw ConfigError("--law '' is refused: give a shape law's name (" + shapeLawNames() + "), or leave --law "
                      "out to fly the formation file's");
  }
  if (o.formation.empty() && o.delays.size() > 1) {
    throw ConfigError("--delay takes one value for a flight (one per drone with --formation): got " + std::to_string(o.delays.size()));
  }
  for (const char* file : {"link", "formation", "csv", "controller", "task", "vehicle"}) {
    if (vm.count(file) && !vm[file].defaulted() && vm[file].as<std::string>().empty()) {
      throw ConfigError(std::string("--") + file + " '' is refused: give a file's path (or leave --" + file + " out)");
    }
  }
  resolve(vm, config, o);
  return true;
}

// The files by their paths, the rate checked, the vehicle defaulted to the
// controller's, the one delay of a flight.
void resolve(const po::variables_map& vm, const std::string& config, Options& o) {
  o.controller = shippedOrPath(o.controller, config, "controllers");
  o.task = shippedOrPath(o.task, config, "tasks");
  o.vehicle = shippedOrPath(o.vehicle, config, "vehicles");
  o.link = shippedOrPath(o.link, config, "links");
  o.formation = shippedOrPath(o.formation, config, "formations");
  if (o.formation.empty()) o.flown_law = controllerFileName(o.controller), o.flown = vehicleOfLaw(o.flown_law);
  if (vm.count("rate")) {
    if (!o.formation.empty()) throw ConfigError("--rate is refused with --formation: its robots run at the vehicle's rate");
    if (!(o.rate > 0.0)) {
      throw ConfigError("--rate " + YamlReader::fmt(o.rate) + " is refused: accepted a rate above 0 Hz that divides "
                        "the vehicle's (30 Hz: 30, 15, 10, 7.5, 6, 5, ...)");
    }
    refuseRateFor(o.flown_law, o.rate, "--rate");
  }
  for (const auto& option : vm) {
    if (!option.second.defaulted()) o.given.push_back(option.first);
  }
  // A formation's robots: their file's vehicles, or (a file that names
  // none) its shape's default (line_flight.cpp).
  if (o.vehicle.empty() && o.formation.empty()) o.vehicle = config + "/vehicles/" + o.flown + ".yaml";
  o.delay = o.delays.empty() ? kDelayNotGiven : o.delays[0];
}

// RMS and maximum tracking error per segment (a waypoint's, or a lap), on
// the one definition of docs/controllers.md: state k against reference k.
class SegmentErrors {
 public:
  explicit SegmentErrors(const Task<double>& task) : task_(task) {}
  void add(long k, double Ts, double error) {
    const size_t i = static_cast<size_t>(task_.activeIndex(taskTime(k, Ts)));
    if (sq_.size() <= i) sq_.resize(i + 1, 0.0), max_.resize(i + 1, 0.0), n_.resize(i + 1, 0);
    sq_[i] += error * error, n_[i] += 1, max_[i] = std::max(max_[i], error);
  }
  void print() const {
    for (size_t i = 0; i < n_.size(); ++i) {
      if (n_[i] == 0) continue;
      std::printf("  %s %zu: RMS tracking error %.4f m, max %.4f m\n", task_.isTrajectory() ? "lap" : "segment",
                  i + 1, std::sqrt(sq_[i] / double(n_[i])), max_[i]);
    }
  }

 private:
  const Task<double>& task_;
  std::vector<double> sq_, max_;
  std::vector<long> n_;
};

// One row per step k: the state after k model steps (the vehicle's state
// names), the command the vehicle applied at step k (u1 .. uN, model
// order), the reference of step k and its tracking error; each number the
// shortest text that reads back to the same double (number_text.h).
template <class Vehicle>
std::string csvHeader() {
  std::string h = "step,t";
  for (int i = 0; i < Vehicle::kStates; ++i) h += std::string(",") + Vehicle::stateName(i);
  for (int i = 0; i < Vehicle::kInputs; ++i) h += ",u" + std::to_string(i + 1);
  return h + ",xd,yd,zd,error\n";
}

template <class Vehicle>
void writeCsvRow(FILE* csv, const LoopObservation<Vehicle, double>& o, double t, double error) {
  using aurora_common::writeNumber;
  std::fprintf(csv, "%ld", o.k);
  writeNumber(csv, t);
  for (int i = 0; i < Vehicle::kStates; ++i) writeNumber(csv, o.X_before[i]);
  for (int i = 0; i < Vehicle::kInputs; ++i) writeNumber(csv, o.step.U[i]);
  for (int i = 0; i < 3; ++i) writeNumber(csv, o.step.ref.pos[i]);
  writeNumber(csv, error);
  std::fprintf(csv, "\n");
}

// Flies `f` once and prints what it measured.
template <class Flight>
void flyAndReport(const Options& o, const Flight& f) {
  using Law = typename Flight::Law;
  const Task<double>& task = f.cfg.task;
  const LinkParams& link = f.cfg.link;
  const double Ts = f.run.plant.Ts;
  const std::string law = f.law + (f.rate != 0.0 ? " at " + YamlReader::fmt(f.rate) + " Hz" : "") +
                          (f.predictor.on() ? std::string(" with the ") + predictorFormName(f.predictor.form) +
                                                  " predictor (docs/predictor.md)"
                                            : "");
  FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
  if (!o.csv.empty() && !csv) throw std::runtime_error("cannot write '" + o.csv + "'");
  if (csv) std::fprintf(csv, "%s", csvHeader<typename Law::Vehicle>().c_str());
  SegmentErrors segments(task);
  const auto t0 = std::chrono::steady_clock::now();
  const FlightResult r = flyLaw(f, [&](const auto& ob, double e) {
    segments.add(ob.k, Ts, e);
    if (csv) writeCsvRow(csv, ob, taskTime(ob.k, Ts), e);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (csv) std::fclose(csv);
  std::printf("flight: %s, %s task of %.1f s, delay %s, link %s: %ld steps in %.3f s (%.2f us per step, model included)\n",
              law.c_str(), task.isTrajectory() ? (task.type == TaskType::kCircle ? "circle" : "lemniscate") : "waypoint",
              task.duration(), delayOriginText(o.delay, link).c_str(),
              o.link.empty() ? "ideal" : ("'" + o.link + "' (" + linkText(link) + ")").c_str(), r.steps, seconds,
              1e6 * seconds / double(r.steps));
  segments.print();
  std::printf("  whole flight: RMS %.4f m, max %.4f m; IAE %.4f, ITAE %.4f, IASC %.4f\n", r.rms_tracking_error,
              r.max_tracking_error, r.iae, r.itae, r.iasc);
}

// Flies the options' task once with the controller file's law on its vehicle.
void run(const Options& o) {
  const FlightFiles files{o.controller, o.task, o.vehicle, o.link, o.delay, o.no_clamp};
  withFlight(files, o.flown_law, {o.rate, "--rate ", "--no-clamp"}, [&](const auto& f) { flyAndReport(o, f); });
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    if (!parse(argc, argv, o)) return 0;
    if (o.formation.empty()) {
      run(o);
    } else {
      flyFormationFile(o);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "flight: %s\n", e.what());
    return 2;
  }
  return 0;
}
