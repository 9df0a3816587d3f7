// aurora._core: the C++ core for Python, no copy of it in Python
// (aurora/simulation.py wraps it as aurora.simulate). A flight is the
// `flight` tool's (flight_setup.h, flight_runner.h): the same files, the
// same refusals (ValueError with the tool's message), the same numbers.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "aurora_control/flight_setup.h"

namespace py = pybind11;
using namespace aurora_control;

namespace {

// Rows k = 0..n-1, as flight --csv writes them: t, the state after k model
// steps, the command the drone applied at step k, the reference of step k
// and its tracking error; the arrays are filled in place (no copy).
py::dict simulateFiles(const std::string& controller, const std::string& task, const std::string& vehicle, long delay,
                       const std::string& link, bool clamp) {
  const FlightSetup f = loadFlight(FlightFiles{controller, task, vehicle, link, delay, !clamp});
  const py::ssize_t n = f.steps;
  py::array_t<double> t(n), states({n, py::ssize_t(12)}), commands({n, py::ssize_t(4)}), reference({n, py::ssize_t(3)}),
      error(n);
  double *pt = t.mutable_data(), *px = states.mutable_data(), *pu = commands.mutable_data(),
         *pr = reference.mutable_data(), *pe = error.mutable_data();
  FlightResult r;
  {
    py::gil_scoped_release unlocked;  // the flight touches no Python object
    r = runFlight(f.vehicle, f.settings, f.task, f.steps, [&](const LoopObservation<double>& o, double e) {
      const long k = o.k;
      pt[k] = taskTime(k, f.vehicle.Ts);
      for (int i = 0; i < 12; ++i) px[12 * k + i] = o.X_before[i];
      for (int i = 0; i < 4; ++i) pu[4 * k + i] = o.step.U[i];
      for (int i = 0; i < 3; ++i) pr[3 * k + i] = o.step.ref.pos[i];
      pe[k] = e;
    });
  }
  py::dict metrics;
  metrics["steps"] = r.steps;
  metrics["iae"] = r.iae, metrics["itae"] = r.itae, metrics["iasc"] = r.iasc;
  metrics["rms_tracking_error"] = r.rms_tracking_error, metrics["max_tracking_error"] = r.max_tracking_error;
  metrics["delay"] = f.settings.delay;
  py::dict out;
  out["t"] = t, out["states"] = states, out["commands"] = commands, out["reference"] = reference, out["error"] = error;
  out["metrics"] = metrics;
  out["sample_time"] = f.vehicle.Ts;
  out["law"] = lawName(f.settings.law);
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "The C++ core of AuRoRA-ROS (use aurora.simulate)";
  py::register_exception<aurora_sim::ConfigError>(m, "ConfigError", PyExc_ValueError);
  m.def("simulate_files", &simulateFiles, py::arg("controller"), py::arg("task"), py::arg("vehicle"), py::arg("delay"),
        py::arg("link"), py::arg("clamp"),
        "One flight from YAML files, as the flight tool flies it: a dict of numpy arrays and metrics.");
}
