// Cost per call of the two control laws, side by side in one run (scalar
// double): each law is evaluated on the 1801 states of a recorded mission
// flight, in alternating rounds; the median per-call time of each and their
// ratio are printed. Measured, never asserted (bench/laws.sh runs it).
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <vector>

#include "aurora_control/loop/ardrone_study.h"
#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/law/ardrone2/pd_controller.h"
#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/law/ardrone2/underactuated_law.h"

using namespace aurora_control;

int main() {
  const auto p = aurora_sim::referenceArdrone2Params();
  Task<double> task;
  task.waypoints = WaypointTask<double>::singlePoint(2.0, 1.0, 2.0, 60.0);
  auto set = LawSettings<ArdroneLawData>::flying<ArdroneLaw<LawType::kUnderactuated>>();
  set.vehicle = p;
  std::vector<std::array<double, aurora_sim::kStateSize>> states;
  runFlight(p, set, task, studyIterationCount(60.0, p.Ts),
            [&](const FlightObservation& o, double) {
              std::array<double, aurora_sim::kStateSize> x;
              std::copy(o.after.model.X, o.after.model.X + aurora_sim::kStateSize, x.begin());
              states.push_back(x);
            });
  const PdGains<double> pd{0.5, 0.85};
  const auto ua = UnderactuatedGains<double>::defaults();
  const double Xd[aurora_sim::kStateSize] = {2, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  double sink = 0.0;
  std::vector<double> t_pd, t_ua;
  for (int round = 0; round < 41; ++round) {
    auto t0 = std::chrono::steady_clock::now();
    for (const auto& x : states) {
      double U[4], err[3];
      pdSaturatedLaw(pd, Xd, zero, zero, x.data(), x.data() + aurora_sim::kVx, U, err);
      sink += U[0];
    }
    auto t1 = std::chrono::steady_clock::now();
    UnderactuatedMemory<double> mem;
    mem.reset();
    for (const auto& x : states) {
      double U[4];
      underactuatedCommand(p, ua, mem, Xd, zero, x.data(), U);
      sink += U[0];
    }
    auto t2 = std::chrono::steady_clock::now();
    t_pd.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / states.size());
    t_ua.push_back(std::chrono::duration<double, std::nano>(t2 - t1).count() / states.size());
  }
  std::nth_element(t_pd.begin(), t_pd.begin() + 20, t_pd.end());
  std::nth_element(t_ua.begin(), t_ua.begin() + 20, t_ua.end());
  std::printf("law cost per call (scalar double, median of 41 alternating rounds over %zu states):\n"
              "  pd_saturated   %8.1f ns\n  underactuated  %8.1f ns\n  ratio          %8.2fx\n",
              states.size(), t_pd[20], t_ua[20], t_ua[20] / t_pd[20]);
  return sink == 12345.0;  // keeps the loops from being optimised away
}
