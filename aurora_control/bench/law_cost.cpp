// Cost per call of every control law this build knows (law/other_laws.h),
// side by side in one run (scalar double): each law is called on the
// (received state, reference) pairs of its own flight (lawCalls), in
// alternating rounds; the median per-call time of each and its ratio to the
// first law's are printed. Measured, never asserted (bench/laws.sh runs it).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "aurora_common/ros/config_dir.h"
#include "aurora_control/loop/flight_setup.h"
#include "aurora_control/params/shipped_files.h"

using namespace aurora_control;

namespace {

constexpr int kRounds = 41;

// A law's calls: one round over its flight's pairs gives ns per call.
struct LawCalls {
  std::string name;
  std::function<double(double& sink)> round;
  size_t calls = 0;
  std::vector<double> ns;
};

// Law's flight to the waypoint (2, 1, h) for 60 s, h 1.5 m or its
// vehicle's task height (a ground robot's: 0), with its shipped controller
// and vehicle files: the (received state, reference) pair of each step.
template <class Law>
LawCalls lawCalls(const std::string& config) {
  using Vehicle = typename Law::Vehicle;
  const auto vehicle = aurora_sim::loadVehicleFile<Vehicle>(shippedOrPath(Vehicle::name(), config, "vehicles"));
  const LawFile<Law> file = readLawFile<Law>(shippedOrPath(Law::name(), config, "controllers"), vehicle.Ts);
  const TaskHeights heights = TaskHeights::of<Vehicle>();
  RunnerConfig<double> cfg;
  cfg.task.waypoints = WaypointTask<double>::singlePoint(2.0, 1.0, std::min(std::max(1.5, heights.min), heights.max), 60.0);
  const StudyRun<typename Law::Data, double> run{vehicle, vehicle, file.gains, 0};
  struct Pair {
    double X[Vehicle::kStates];
    Reference<double> ref;
  };
  std::vector<Pair> pairs;
  flyLaw<Law>(run, cfg, studyIterationCount(60.0, vehicle.Ts), [&](const LoopObservation<Vehicle, double>& o, double) {
    Pair p;
    std::copy(o.xc, o.xc + Vehicle::kStates, p.X);
    p.ref = o.step.ref;
    pairs.push_back(p);
  });
  LawCalls c;
  c.name = Law::name();
  c.calls = pairs.size();
  c.round = [run, pairs](double& sink) {
    typename Law::template Memory<double> memory;
    memory.reset();
    const auto t0 = std::chrono::steady_clock::now();
    for (const Pair& p : pairs) {
      double U[Vehicle::kInputs], err[3];
      Law::command(run.model, run.gains, memory, p.ref, p.X, U, err);
      sink += U[0];
    }
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / double(pairs.size());
  };
  return c;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main() {
  const std::string config = aurora_common::configDir();
  std::vector<LawCalls> laws;
  forEachLaw([&](auto law) { laws.push_back(lawCalls<decltype(law)>(config)); });
  double sink = 0.0;
  for (int round = 0; round < kRounds; ++round) {
    for (LawCalls& c : laws) c.ns.push_back(c.round(sink));
  }
  std::printf("law cost per call (scalar double, median of %d alternating rounds over each law's 60 s flight):\n",
              kRounds);
  const double first = median(laws.front().ns);
  for (const LawCalls& c : laws) {
    const double ns = median(c.ns);
    std::printf("  %-20s %8.1f ns  %6.2fx %s  (%zu calls)\n", c.name.c_str(), ns, ns / first,
                laws.front().name.c_str(), c.calls);
  }
  return sink == 12345.0;  // keeps the loops from being optimised away
}
