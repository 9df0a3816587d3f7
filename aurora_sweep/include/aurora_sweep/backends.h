// The sweep's execution backends (host side). Each fills one SimResult per
// combination index of the spec.
#pragma once

#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_control/params/limits.h"
#include "aurora_sweep/formation_simulation.h"
#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_sweep {

// Progress counter the backends advance (finished simulations); a monitor
// thread reads it for the ETA.
using Progress = std::atomic<long>;

// The setup of a sweep whose law flies `Vehicle`.
template <class Vehicle, typename T>
SimSetup<Vehicle, T> makeSetup(const SweepSpec& spec) {
  SimSetup<Vehicle, T> s;
  s.vehicle = spec.paramsOf(Vehicle());
  s.model = s.vehicle.template cast<T>();
  s.config.task = spec.task.cast<T>();
  s.config.criteria = spec.criteria.cast<T>();
  s.config.clamp_commands = spec.clamp_commands;
  s.config.early_stop = spec.early_stop;
  s.config.link = spec.link;
  s.iterations = spec.iterations();
  s.varies_model = spec.variesModel();
  s.ideal_link = spec.linkIdeal();
  s.predictor = spec.predictor;
  if (spec.predicting()) {
    s.predictor_model = aurora_sim::loadVehicleFile<Vehicle>(spec.predictor_model_file).template cast<T>();
  }
  return s;
}

// A formation sweep's setup of the formation `run` (spec.withFormation's).
template <typename T, template <typename> class Shape, class Data>
FormationSetup<T, Shape, Data> makeFormationSetup(const SweepSpec& spec, const ShapeRun<double, Shape, Data>& run) {
  FormationSetup<T, Shape, Data> s;
  s.run = castFormationRun<T>(run);
  s.criteria = spec.formation_criteria.cast<T>();
  s.iterations = spec.iterations();
  s.early_stop = spec.early_stop;
  s.ideal_link = spec.linkIdeal();
  return s;
}

// Calls f(Law()) with the law type of a single-robot sweep's controller:
// the law of the list (other_laws.h) of that name (the one place a sweep's
// law is chosen by name; the sweep file's reader refuses any other name).
template <class F>
void withSweepLaw(const SweepSpec& spec, F&& f) {
  if (!aurora_control::withLawNamed(spec.controller, f)) {
    throw std::logic_error("sweep: controller '" + spec.controller + "' is no law of this build");
  }
}

// Calls f(T(), capacity, law): the sweep's precision, history capacity
// (limits.h) and law (chosen by `choose(spec, g)`) as compile-time values.
template <class Choose, class F>
void withTypesOf(const SweepSpec& spec, Choose&& choose, F&& f) {
  aurora_control::withHistoryCapacity(spec.historyNeeded(), [&](auto capacity) {
    choose(spec, [&](auto law) {
      if (spec.precision == Precision::kDouble) {
        f(double(), capacity, law);
      } else {
        f(float(), capacity, law);
      }
    });
  });
}

// A single-robot sweep's types (any law); the CPU backends instantiate
// their loops here, once.
template <class F>
void withSweepTypes(const SweepSpec& spec, F&& f) {
  withTypesOf(spec, [](const SweepSpec& s, auto&& g) { withSweepLaw(s, g); }, f);
}

// A formation sweep's: f(T(), capacity, law, run) with its shape's run
// (spec.withFormation: the line's drones' AR.Drone law, the UAV-UGV line's
// crew, the triangle's AR.Drones).
template <class F>
void withFormationTypes(const SweepSpec& spec, F&& f) {
  aurora_control::withHistoryCapacity(spec.historyNeeded(), [&](auto capacity) {
    spec.withFormation([&](const auto& run, auto law) {
      if (spec.precision == Precision::kDouble) {
        f(double(), capacity, law, run);
      } else {
        f(float(), capacity, law, run);
      }
    });
  });
}

// The scalar loops' body (scalar and threaded backends): `loop(n, simulate)`
// calls simulate(i) once for each i in [0, n), in any order and on any
// thread; simulate(i) runs combination rangeBegin() + i into out[i].
// Compiled once (scalar_backend.cpp): the loops' instantiations of every
// law's simulation are the same for both backends.
using CombinationLoop = std::function<void(long, const std::function<void(long)>&)>;
void runEachCombination(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress,
                        const CombinationLoop& loop);

// One simulation at a time on the calling thread: the plain reference loop.
void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress);

// Many simulations at once: SIMD lanes (a finished lane takes the next
// combination), on `threads` threads; over a link each lane has its own
// link model.
void runCpuBatch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                 Progress& progress);

// Lanes per SIMD batch the CPU engine uses for this precision, and the
// instruction set chosen at run time (for the summary): the widest this CPU
// runs among those built (cpu_dispatch.cpp), unless AURORA_SWEEP_SIMD names one.
// Throws std::runtime_error when AURORA_SWEEP_SIMD names a build that is
// missing or that this CPU cannot run.
int cpuBatchLanes(Precision precision);
std::string cpuBatchArch(Precision precision);

// The engine's builds, widest first ("none": threads without SIMD lanes),
// and whether this CPU runs each; running a chosen one (tests, benchmarks).
struct CpuIsa {
  std::string key, name;
  bool supported;
};
std::vector<CpuIsa> cpuBatchIsas();
void runCpuBatchOn(const std::string& key, const SweepSpec& spec, int threads,
                   std::vector<SimResult>& out, Progress& progress);

}  // namespace aurora_sweep
