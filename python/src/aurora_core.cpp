// aurora._core: the C++ core for Python, no copy of it in Python
// (aurora/simulation.py wraps it as aurora.simulate). A flight is the
// `flight` tool's (flight_setup.h, flight_runner.h): the same files, the
// same refusals (ValueError with the tool's message), the same numbers.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "aurora_control/loop/flight_setup.h"
#include "aurora_control/formation/line/line_flight.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/params/shipped_files.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace py = pybind11;
using namespace aurora_control;

namespace {

// Rows k = 0..n-1 of flight `f` (n steps), as flight --csv writes them: t,
// the state after k model steps (the vehicle's kStates, named in
// state_names), the command the vehicle applied at step k (kInputs), the
// reference of step k and its tracking error; and the delay in force
// (samples between state k and the one the law received). The arrays are
// filled in place (no copy).
template <class Flight>
py::dict flightArrays(const Flight& f) {
  using Law = typename Flight::Law;
  using Vehicle = typename Law::Vehicle;
  constexpr int kStates = Vehicle::kStates, kInputs = Vehicle::kInputs;
  const double Ts = f.run.plant.Ts;
  const py::ssize_t n = f.steps;
  py::array_t<double> t(n), states({n, py::ssize_t(kStates)}), commands({n, py::ssize_t(kInputs)}),
      reference({n, py::ssize_t(3)}), error(n);
  py::array_t<long> delay_in_force(n);
  double *pt = t.mutable_data(), *px = states.mutable_data(), *pu = commands.mutable_data(),
         *pr = reference.mutable_data(), *pe = error.mutable_data();
  long* pd = delay_in_force.mutable_data();
  FlightResult r;
  {
    py::gil_scoped_release unlocked;  // the flight touches no Python object
    r = flyLaw(f, [&](const LoopObservation<Vehicle, double>& o, double e) {
      const long k = o.k;
      pt[k] = taskTime(k, Ts);
      for (int i = 0; i < kStates; ++i) px[kStates * k + i] = o.X_before[i];
      for (int i = 0; i < kInputs; ++i) pu[kInputs * k + i] = o.step.U[i];
      for (int i = 0; i < 3; ++i) pr[3 * k + i] = o.step.ref.pos[i];
      pe[k] = e;
      pd[k] = k - o.received;
    });
  }
  py::dict metrics;
  metrics["steps"] = r.steps;
  metrics["iae"] = r.iae, metrics["itae"] = r.itae, metrics["iasc"] = r.iasc;
  metrics["rms_tracking_error"] = r.rms_tracking_error, metrics["max_tracking_error"] = r.max_tracking_error;
  metrics["delay"] = f.run.delay;
  py::list names;
  for (int i = 0; i < kStates; ++i) names.append(Vehicle::stateName(i));
  py::dict out;
  out["t"] = t, out["states"] = states, out["commands"] = commands, out["reference"] = reference, out["error"] = error;
  out["delay_in_force"] = delay_in_force;
  out["metrics"] = metrics;
  out["sample_time"] = Ts;
  out["law"] = f.law;
  out["vehicle"] = Vehicle::name();
  out["state_names"] = names;
  return out;
}

// One flight from its files, as the flight tool flies it: the controller
// file's law chooses the vehicle; `rate` [Hz] (0: the file's) is its law's,
// for a law that runs at a rate of its own (lawHasRate).
py::dict simulateFiles(const std::string& controller, const std::string& task, const std::string& vehicle, long delay,
                       const std::string& link, bool clamp, double rate) {
  const FlightFiles files{controller, task, vehicle, link, delay, !clamp};
  const std::string law = controllerFileName(controller);
  refuseRateFor(law, rate, "rate=" + YamlReader::fmt(rate));
  py::dict out;
  withFlight(files, law, {rate, "rate=", "clamp=False"}, [&](const auto& f) { out = flightArrays(f); });
  return out;
}

// The vehicle a controller file's law flies (its name).
std::string vehicleOf(const std::string& controller) { return controllerVehicle(controller); }

// A vehicle type this build does not know refused, naming the known ones.
void refuseUnknownVehicle(const std::string& type) {
  if (!aurora_sim::isKnownVehicleType(type)) {
    throw py::value_error("'" + type + "' is not a vehicle type: accepted " + aurora_sim::knownVehicleTypes());
  }
}

// Whether a vehicle type flies (a drone: it takes off, hovers, lands) or
// drives on the floor (a ground robot: it stands still), by its sim profile.
bool vehicleFlies(const std::string& type) {
  refuseUnknownVehicle(type);
  bool flies = true;
  aurora_sim::withVehicleOfType(type, [&](auto v) { flies = aurora_sim::SimProfile<decltype(v)>::kFlies; });
  return flies;
}

// The formation checks and errors of a formation flight, as flight --formation prints them.
py::dict formationMetrics(const FormationFlight& r) {
  const auto& m = r.judge.metrics;
  py::dict out;
  out["ticks"] = r.ticks;
  out["delays"] = py::make_tuple(r.run.drone[0].delay, r.run.drone[1].delay);
  out["rms_rho"] = r.rms[0], out["rms_alpha"] = r.rms[1], out["rms_beta"] = r.rms[2];
  out["rms_position_xy"] = r.rms[3], out["rms_height"] = r.rms[4];
  out["max_position_error"] = m.max_position, out["max_shape_error"] = m.max_shape;
  out["iae_position"] = m.iae_position, out["iae_shape"] = m.iae_shape, out["min_distance"] = m.closest;
  out["checks"] = py::make_tuple(m.ok[0], m.ok[1], m.ok[2], m.ok[3], m.ok[4]);
  out["feasible"] = m.feasible();
  return out;
}

// Rows k = 0..n-1, as flight --formation --csv writes them: per drone
// (axis 0) the state after k steps, the command applied at tick k and its
// held reference; Q of those positions and the layer's held Qd.
py::dict simulateFormationFiles(const std::string& formation, const std::string& vehicle, const std::vector<long>& delays,
                                const std::string& config_dir) {
  using Drone = LineShapeEntry::UnnamedVehicle;  // the line's drones
  FormationFlightOptions o;
  o.formation = formation, o.vehicle = vehicle, o.delays = delays, o.config_dir = config_dir;
  std::vector<double> t, X, U, R, Q, Qd;  // filled by the run, then moved into arrays of the run's length
  FormationFlight r;
  {
    py::gil_scoped_release unlocked;
    r = flyFormationFiles(o, [&](const auto& obs, double Ts) {
      t.push_back(taskTime(double(obs.k), Ts));
      double P[6], q[6];
      for (int d = 0; d < 2; ++d) {
        X.insert(X.end(), obs.X_before[d], obs.X_before[d] + Drone::kStates);
        U.insert(U.end(), obs.steps[d].U, obs.steps[d].U + Drone::kInputs);
        R.insert(R.end(), obs.steps[d].ref.pos, obs.steps[d].ref.pos + 3);
      }
      dronePositions<LineFormation<double>, Drone>(obs.X_before, P);
      LineFormation<double>::variables(P, q);
      Q.insert(Q.end(), q, q + 6);
      Qd.insert(Qd.end(), obs.layer.Qd(), obs.layer.Qd() + 6);
    });
  }
  const py::ssize_t n = static_cast<py::ssize_t>(t.size());
  const auto array = [n](const std::vector<double>& v, std::vector<py::ssize_t> shape) {
    py::array_t<double> a(shape);
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  py::dict out;
  out["t"] = array(t, {n});
  out["states"] = array(X, {n, 2, Drone::kStates}), out["commands"] = array(U, {n, 2, Drone::kInputs});
  out["reference"] = array(R, {n, 2, 3});
  out["Q"] = array(Q, {n, 6}), out["Qd"] = array(Qd, {n, 6});
  out["metrics"] = formationMetrics(r);
  out["sample_time"] = r.Ts;
  out["law"] = formationLawName(r.file.law);
  out["drone_law"] = lawNameOf(r.file.drones[0].controller);
  out["drones"] = py::make_tuple(r.file.drones[0].name_space, r.file.drones[1].name_space);
  return out;
}

// A shape's flight as a table (its entry's flyTable, shapes.h); the line
// has none: its flights are simulate_formation_files'.
template <class Entry>
ShapedFlight tableFlight(Entry, const typename Entry::File& file, const FormationFlightOptions& o, FlightTable& table) {
  return Entry::flyTable(file, o, table);
}
inline ShapedFlight tableFlight(LineShapeEntry, const FormationFile&, const FormationFlightOptions&, FlightTable&) {
  throw aurora_common::ConfigError("simulate_shaped_formation_files flies a shape with a table flight: the two-drone "
                                   "line's flight is simulate_formation_files'");
}

// A file of a shape with a table flight flown as flight --formation flies it (the
// options' delays and the triangle's law; "" keeps the file's): its CSV's
// columns and rows as one array, its printed summary and errors by name.
py::dict simulateShapedFormationFiles(const std::string& formation, const std::vector<long>& delays,
                                      const std::string& law, const std::string& config_dir) {
  FormationFlightOptions o;
  o.formation = formation, o.delays = delays, o.law = law, o.config_dir = config_dir;
  std::string shape;
  std::vector<std::string> columns;
  std::vector<double> values;
  FlightTable table;
  table.columns = [&](const std::vector<std::string>& c) { columns = c; };
  table.row = [&](const std::vector<double>& v) { values.insert(values.end(), v.begin(), v.end()); };
  ShapedFlight f;
  {
    py::gil_scoped_release unlocked;
    withFormationFile(formation, config_dir, law, [&](auto e, const auto& file) {
      shape = e.name();
      f = tableFlight(e, file, o, table);
    });
  }
  const py::ssize_t m = static_cast<py::ssize_t>(columns.size()), n = m > 0 ? py::ssize_t(values.size()) / m : 0;
  py::array_t<double> rows({n, m});
  std::copy(values.begin(), values.end(), rows.mutable_data());
  py::dict errors;
  for (const auto& e : f.errors) errors[py::str(e.first)] = e.second;
  py::dict out;
  out["shape"] = shape, out["columns"] = columns, out["rows"] = rows, out["errors"] = errors;
  out["summary"] = f.summary;
  return out;
}

// The shape of a formation file (its formation.shape; "" when it gives none).
std::string shapeOf(const std::string& formation) { return loadFormationDocument(formation, "").shape; }

// Each shape's entry as Python chooses by it: its robots, whether its file
// names their vehicles (the two-drone line's does not: the flight's vehicle
// file flies both), its own laws ("" none).
py::dict formationShapeInfo() {
  py::dict out;
  forEachShape([&](auto e) {
    using E = decltype(e);
    py::dict info;
    info["robots"] = int(E::kRobots);
    info["names_its_vehicles"] = bool(E::kNamesItsVehicles);
    // A shape whose file names no vehicle flies the caller's: the type the crew takes (its default).
    info["vehicle"] = unnamedVehicleName(e);
    info["laws"] = ownLawNames(e);
    out[py::str(E::name())] = info;
  });
  return out;
}

// Q~ = Qd - Q of a shape's variables as its layer and checks take it (the
// shape's own angle wraps: the triangle's, the UAV-UGV line's; the line's
// none), at positions X: for the formation report.
template <class Shape>
std::vector<double> shapeError(const std::vector<double>& X, const std::vector<double>& Qd,
                               const std::vector<double>& Q) {
  constexpr int n = Shape::kVariables;
  if (X.size() != size_t(n) || Qd.size() != size_t(n) || Q.size() != size_t(n)) {
    throw aurora_common::ConfigError("formation_error: X, Qd and Q must hold " + std::to_string(n) +
                                     " values each for this shape (" + std::to_string(X.size()) + ", " +
                                     std::to_string(Qd.size()) + ", " + std::to_string(Q.size()) + " given)");
  }
  std::vector<double> e(n);
  Shape::error(X.data(), Qd.data(), Q.data(), e.data());
  return e;
}

std::vector<double> formationError(const std::string& shape, const std::vector<double>& X,
                                   const std::vector<double>& Qd, const std::vector<double>& Q) {
  std::vector<double> e;
  const bool known = withShapeNamed(shape, [&](auto entry) { e = shapeError<typename decltype(entry)::Shape>(X, Qd, Q); });
  if (!known) throw aurora_common::ConfigError("formation_error: shape '" + shape + "' is unknown: accepted " + knownShapeNames());
  return e;
}


// The names `each(vehicle, names)` gives of a vehicle type (an unknown type
// refused).
template <class Each>
std::vector<std::string> vehicleNames(const std::string& type, Each each) {
  refuseUnknownVehicle(type);
  std::vector<std::string> names;
  aurora_sim::withVehicleOfType(type, [&](auto v) { each(v, names); });
  return names;
}

// A vehicle type's commands, as its Control messages name them.
std::vector<std::string> vehicleCommandNames(const std::string& type) {
  return vehicleNames(type, [](auto v, std::vector<std::string>& names) {
    for (int i = 0; i < decltype(v)::kInputs; ++i) names.push_back(decltype(v)::inputName(i));
  });
}

// The model factors a vehicle type scales (its factorName order): what
// identify's output-error fit may vary.
std::vector<std::string> vehicleFactorNames(const std::string& type) {
  return vehicleNames(type, [](auto v, std::vector<std::string>& names) {
    for (int i = 0; i < decltype(v)::kFactors; ++i) names.push_back(decltype(v)::factorName(i));
  });
}

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Flights of a vehicle through its own model, open loop (identify's
// output-error fit and figures; docs/identify.md, eq. I7). The vehicle of
// `type`, its file's parameters with each factor scaling its factorName.
// For each start k0: the model is forced over the `forced` steps before k0
// (its state set to the recorded X_k before each step, so what a recorded
// state does not hold, the rotors' speeds, the on-board loop's memory, a
// ground robot's speeds, follows the recording), then set to X_k0 and flown
// `length` steps on the commands U_k0.. (each limited as its driver does).
// Returns the states after each free step: (starts, length, kStates).
template <class Vehicle>
py::array_t<double> openLoopOf(const typename Vehicle::template Params<double>& file_params,
                               const std::vector<double>& factors, const Rows& X, const Rows& U,
                               const std::vector<long>& starts, long length, long forced) {
  constexpr int kStates = Vehicle::kStates, kInputs = Vehicle::kInputs;
  if (factors.size() != size_t(Vehicle::kFactors)) {
    throw py::value_error("open_loop: " + std::to_string(factors.size()) + " factors given, a " + Vehicle::name() +
                          " has " + std::to_string(Vehicle::kFactors));
  }
  const long n = long(X.shape(0)), recorded = X.ndim() == 2 ? long(X.shape(1)) : 0;
  if (X.ndim() != 2 || recorded < 1 || recorded > kStates || U.ndim() != 2 || U.shape(1) != kInputs ||
      U.shape(0) != n) {
    throw py::value_error(std::string("open_loop: X must be (n, at most ") + std::to_string(kStates) +
                          ") and U (n, " + std::to_string(kInputs) + ") for a " + Vehicle::name());
  }
  for (long k0 : starts) {
    if (k0 - forced < 0 || k0 + length > n || length < 1 || forced < 0) {
      throw py::value_error("open_loop: start " + std::to_string(k0) + " forced " + std::to_string(forced) +
                            " steps and flown " + std::to_string(length) + " leaves the " + std::to_string(n) +
                            " recorded steps");
    }
  }
  const auto p = Vehicle::scaled(file_params, factors.data());
  const py::ssize_t m = py::ssize_t(starts.size());
  py::array_t<double> out({m, py::ssize_t(length), py::ssize_t(kStates)});
  const double *x = X.data(), *u = U.data();
  double* o = out.mutable_data();
  py::gil_scoped_release unlocked;
  for (py::ssize_t j = 0; j < m; ++j) {
    typename Vehicle::template State<double> s;
    Vehicle::start(p, s);
    const auto stepAt = [&](long k) {
      double Uk[kInputs];
      for (int i = 0; i < kInputs; ++i) Uk[i] = Vehicle::limitInput(p, i, u[kInputs * k + i]);
      Vehicle::step(p, s, Uk);
    };
    const auto record = [&](long k) { std::copy(x + recorded * k, x + recorded * (k + 1), s.X); };
    for (long k = starts[j] - forced; k < starts[j]; ++k) record(k), stepAt(k);
    record(starts[j]);
    for (long i = 0; i < length; ++i) {
      stepAt(starts[j] + i);
      std::copy(s.X, s.X + kStates, o + (j * length + i) * kStates);
    }
  }
  return out;
}

// A vehicle file's open-loop flights (openLoopOf), the file read once:
// identify's output-error fit flies it thousands of times (reading the
// file was half of each flight's time).
class OpenLoop {
 public:
  using Fly = std::function<py::array_t<double>(const std::vector<double>&, const Rows&, const Rows&,
                                                const std::vector<long>&, long, long)>;
  OpenLoop(const std::string& type, const std::string& vehicle_file) {
    refuseUnknownVehicle(type);
    aurora_sim::withVehicleOfType(type, [&](auto v) {
      using Vehicle = decltype(v);
      const auto params = aurora_sim::loadVehicleFile<Vehicle>(vehicle_file, "identify");
      fly_ = [params](const std::vector<double>& factors, const Rows& X, const Rows& U,
                      const std::vector<long>& starts, long length, long forced) {
        return openLoopOf<Vehicle>(params, factors, X, U, starts, length, forced);
      };
    });
  }
  py::array_t<double> operator()(const std::vector<double>& factors, const Rows& X, const Rows& U,
                                 const std::vector<long>& starts, long length, long forced) const {
    return fly_(factors, X, U, starts, length, forced);
  }

 private:
  Fly fly_;
};

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "The C++ core of AuRoRA-ROS (use aurora.simulate)";
  py::register_exception<aurora_common::ConfigError>(m, "ConfigError", PyExc_ValueError);
  // The delay rule's constants, for aurora/arguments.py (limits.h, link_yaml.h).
  m.attr("MAX_DELAY_SAMPLES") = kMaxDelaySamples;
  m.attr("DELAY_NOT_GIVEN") = kDelayNotGiven;
  // The names a choice takes, from the lists (for aurora/simulation.py's refusals).
  m.attr("SHAPE_LAWS") = shapeLawNames();
  m.attr("LAWS") = knownLawNames();
  m.def("simulate_files", &simulateFiles, py::arg("controller"), py::arg("task"), py::arg("vehicle"), py::arg("delay"),
        py::arg("link"), py::arg("clamp"), py::arg("rate"),
        "One flight from YAML files, as the flight tool flies it: a dict of numpy arrays and metrics.");
  m.def("is_shipped_name", &isShippedName, py::arg("given"),
        "whether a file option is a shipped NAME (config/<folder>/NAME.yaml) rather than a path: flight's rule");
  m.def("shipped_or_path", [](const std::string& given, const std::string& config, const std::string& folder) {
          return shippedOrPath(given, config, folder.c_str());
        }, py::arg("given"), py::arg("config"), py::arg("folder"),
        "config/<folder>/NAME.yaml for a shipped NAME, a path as it is: flight's rule");
  m.def("controller_vehicle", &vehicleOf, py::arg("controller"),
        "The name of the vehicle a controller file's law flies (config/vehicles/NAME.yaml).");
  m.attr("DEFAULT_VEHICLE") = aurora_sim::DefaultVehicle::name();
  m.def("vehicle_command_names", &vehicleCommandNames, py::arg("type"),
        "A vehicle type's commands with their units, in its model's order (Control.command_names).");
  m.def("vehicle_flies", &vehicleFlies, py::arg("type"),
        "True for a vehicle type that flies (a drone), False for a ground robot (its sim profile).");
  m.def("simulate_formation_files", &simulateFormationFiles, py::arg("formation"), py::arg("vehicle"),
        py::arg("delays"), py::arg("config_dir"),
        "One formation flight from YAML files, as flight --formation flies it: a dict of numpy arrays and metrics.");
  m.def("simulate_shaped_formation_files", &simulateShapedFormationFiles, py::arg("formation"), py::arg("delays"),
        py::arg("law"), py::arg("config_dir"),
        "A formation file of a shape with a table flight (every shape but the two-drone line) flown as "
        "flight --formation flies it: its CSV's columns and rows.");
  m.def("vehicle_factor_names", &vehicleFactorNames, py::arg("type"),
        "The model factors a vehicle type scales, in their order (a sweep's names).");
  py::class_<OpenLoop>(m, "OpenLoop",
                       "A vehicle file's model (of a vehicle type), read once, flown open loop: calling it with "
                       "(factors, X, U, starts, length, forced) flies from recorded states X and commands U and "
                       "gives (starts, length, states) after each step (docs/identify.md, eq. I7).")
      .def(py::init<const std::string&, const std::string&>(), py::arg("type"), py::arg("vehicle_file"))
      .def("__call__", &OpenLoop::operator(), py::arg("factors"), py::arg("X"), py::arg("U"), py::arg("starts"),
           py::arg("length"), py::arg("forced"));
  m.def("formation_shape", &shapeOf, py::arg("formation"), "The shape of a formation file.");
  m.def("formation_shape_info", &formationShapeInfo,
        "The shapes this build knows: each one's robots, names_its_vehicles, vehicle (the type its robots fly "
        "where its file names none; '' else), laws (its own; '' none).");
  m.def("formation_error", &formationError, py::arg("shape"), py::arg("X"), py::arg("Qd"), py::arg("Q"),
        "Qd - Q of a shape's variables with the shape's own angle wraps, at positions X (3 per robot).");
}
