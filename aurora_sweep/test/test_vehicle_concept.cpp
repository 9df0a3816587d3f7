// The vehicle seam (issue 32): a vehicle and a law defined only under
// test/ (point_mass.h) fly through the generic code of every backend, with
// no edit outside test/: the offline runner, the sweep's scalar loop
// (simulateCombination), its SIMD engine (BatchWorker on this build's
// default instruction set) and the CUDA kernel's per-thread entry
// (sweepThread, run on the host for every thread of a launch). Every
// backend gives the same bytes, over the delay rule and over a lossy link.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#ifdef AURORA_SWEEP_LANES  // xsimd >= 8 (Ubuntu 20.04's xsimd 7: no SIMD engine to test)
#include "../src/lanes/batch_engine.h"
#else
#include "aurora_sweep/backends.h"
#endif
#include "aurora_control/law/bebop2/bebop2_compensator.h"
#include "aurora_control/law/pioneer3dx/pioneer_laws.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "aurora_sweep/parameters.h"
#include "aurora_sweep/kernel_entry.h"
#include "point_mass.h"
#include "sweep_test_support.h"

namespace {

using namespace aurora_sweep;
using Law = point_mass::PointPd;
using Vehicle = point_mass::PointMass;
using BebopLaw = aurora_control::Bebop2Compensator;

// A grid over kp, kd, the delay and the mass factor (48 combinations).
struct PointGrid {
  std::vector<std::vector<double>> axes{{1.0, 2.0, 4.0}, {1.5, 3.0}, {0, 3, 9, 20}, {1.0, 1.5}};
  GridView view{};
  PointGrid() {
    const int params[4] = {kParamKp, kParamKd, kParamDelay, kParamFirstModelFactor};
    for (int i = 0; i < kParamCount; ++i) view.fixed[i] = 0.0;
    forEachLawGainParam([&](int i) { view.fixed[i] = paramDefault(i, SweepShape::kNone); });  // the laws' own
    for (int i = 0; i < kModelFactorCount; ++i) view.fixed[kParamFirstModelFactor + i] = 1.0;
    for (int i = 0; i < kLinkParamCount; ++i) view.fixed[kParamFirstLinkValue + i] = std::nan("");
    test::setAxes(view, params, axes);
  }
};

// A vehicle of parameters `vehicle` flying 60 s towards the setup's task,
// (2, 1, 2); over `link` unless it is ideal.
template <typename T, class V>
SimSetup<V, T> setupOf(const typename V::template Params<double>& vehicle, const aurora_control::LinkParams& link) {
  SimSetup<V, T> s;
  s.vehicle = vehicle;
  s.model = s.vehicle.template cast<T>();
  s.config.link = link;
  s.iterations = aurora_control::studyIterationCount(60.0, s.vehicle.Ts);
  s.varies_model = true;
  s.ideal_link = link.ideal();
  return s;
}

// The point mass of 0.5 kg, from the origin.
template <typename T>
SimSetup<Vehicle, T> pointSetup(const aurora_control::LinkParams& link) {
  return setupOf<T, Vehicle>(point_mass::Params<double>{1.0 / 30.0, 0.5}, link);
}

aurora_control::LinkParams lossyLink() {
  aurora_control::LinkParams l;
  l.uplink.jitter = aurora_control::JitterKind::kUniform;
  l.uplink.jitter_max = 3;
  l.uplink.loss = 0.2;
  l.uplink.burst = 2.0;
  l.downlink.delay = 2;
  l.downlink.loss = 0.1;
  l.seed = 7;
  return l;
}

template <typename T, bool Linked, class L = Law>
std::vector<SimResult> scalarLoop(const SimSetup<typename L::Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out;
  for (long i = 0; i < grid.size(); ++i) out.push_back(simulateCombination<L, T, 64, Linked>(setup, grid, i));
  return out;
}

template <typename T, bool Linked, class L = Law>
std::vector<SimResult> kernelThreads(const SimSetup<typename L::Vehicle, T>& setup, const GridView& grid) {
  return test::launchOnHost(grid.size(), 16, [&](unsigned b, unsigned block, unsigned t, SimResult* out) {
    sweepThread<L, T, 64, Linked>(setup, grid, 0, grid.size(), out, b, block, t);
  });
}

#ifdef AURORA_SWEEP_LANES
template <class L = Law, typename T>
std::vector<SimResult> simdLanes(const SimSetup<typename L::Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out(static_cast<size_t>(grid.size()));
  std::atomic<long> next{0};
  Progress progress{0};
  LaneWork work(grid, 0, grid.size(), out, next, progress);
  BatchWorker<T, xsimd::default_arch, L>(setup, 64, work).run();
  EXPECT_EQ(progress.load(), grid.size());
  return out;
}
#endif

// The offline runner, one combination at a time: runLoop over the delay
// rule; over a link, the combination's link keyed by its index (as a sweep).
template <class L = Law, typename T>
std::vector<SimResult> runner(const SimSetup<typename L::Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out;
  for (long i = 0; i < grid.size(); ++i) {
    const Combination c = grid.decode(i);
    const auto run = studyRun<L>(setup, c);
    aurora_control::RunnerConfig<T> cfg = setup.config;
    cfg.link = combinationLink(setup.config.link, run.delay, c);
    aurora_control::NoObserver none;
    out.push_back(compactResult(
        setup.ideal_link ? aurora_control::runLoop<L>(run, cfg, setup.iterations)
                         : aurora_control::runOverModelLink<L, T, 64>(run, cfg, setup.iterations, none, c.key)));
  }
  return out;
}

void expectSameBytes(const std::vector<SimResult>& a, const std::vector<SimResult>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(std::memcmp(&a[i], &b[i], sizeof(SimResult)), 0) << what << " " << i;
}

// The runner and the kernel's threads give the scalar loop's bytes; the
// SIMD lanes too, or (simd_rel > 0: a law with sin, cos or tanh, which
// xsimd computes to the last bits differently from libm) the same flags
// and steps, and metrics to simd_rel.
template <class L, typename T>
void expectEveryBackendAgrees(const SimSetup<typename L::Vehicle, T>& setup, const GridView& grid,
                              double simd_rel = 0.0) {
  const bool ideal = setup.ideal_link;
  const std::vector<SimResult> scalar =
      ideal ? scalarLoop<T, false, L>(setup, grid) : scalarLoop<T, true, L>(setup, grid);
  expectSameBytes(scalar, runner<L>(setup, grid), "runner");
#ifdef AURORA_SWEEP_LANES
  if (simd_rel > 0.0) test::expectRecordsAgree("simd lanes", scalar, simdLanes<L>(setup, grid), simd_rel, 8);
  else expectSameBytes(scalar, simdLanes<L>(setup, grid), "simd lanes");
#endif
  expectSameBytes(scalar, ideal ? kernelThreads<T, false, L>(setup, grid) : kernelThreads<T, true, L>(setup, grid),
                  "kernel threads");
}

template <typename T>
void expectEveryBackendAgrees(const aurora_control::LinkParams& link) {
  expectEveryBackendAgrees<Law>(pointSetup<T>(link), PointGrid().view);
}

// The Bebop 2 (the vehicle file's) flying its compensator towards the
// setup's task for 60 s; over `link` unless it is ideal.
template <typename T>
SimSetup<aurora_sim::Bebop2, T> bebopSetup(const aurora_control::LinkParams& link) {
  return setupOf<T, aurora_sim::Bebop2>(
      aurora_sim::loadVehicleFile<aurora_sim::Bebop2>(test::configDir() + "/vehicles/bebop2.yaml"), link);
}

}  // namespace

TEST(VehicleConcept, ATestVehicleFliesEveryBackend) {
  // It flies: no delay, it ends at the waypoint; each run's steps are the task's.
  const PointGrid grid;
  const SimSetup<Vehicle, double> ideal = pointSetup<double>(aurora_control::LinkParams());
  const std::vector<SimResult> flown = scalarLoop<double, false>(ideal, grid.view);
  const Combination c = grid.view.decode(4);  // kp 2, kd 3, no delay, nominal mass
  ASSERT_EQ(c.v[kParamKp], 2.0);
  ASSERT_EQ(c.v[kParamKd], 3.0);
  ASSERT_EQ(c.delay(), 0);
  const double goal[3] = {2.0, 1.0, 2.0};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(flown[4].final_pos[i], goal[i], 1e-3);
  for (const SimResult& r : flown) EXPECT_EQ(r.steps, 1801);
  // The delay and the mass factor reach it: the runs of one gain pair differ.
  EXPECT_NE(flown[4].iae, flown[4 + 6].iae);
  EXPECT_NE(flown[4].iae, flown[4 + 24].iae);
  for (int bits : {0, 1}) {
    SCOPED_TRACE(bits ? "float" : "double");
    if (bits) expectEveryBackendAgrees<float>(aurora_control::LinkParams());
    else expectEveryBackendAgrees<double>(aurora_control::LinkParams());
  }
  SCOPED_TRACE("over a lossy link");
  ASSERT_FALSE(lossyLink().ideal());
  expectEveryBackendAgrees<double>(lossyLink());
  expectEveryBackendAgrees<float>(lossyLink());
}

// A real vehicle and its law, added as the seam says (aurora_sim/vehicle/
// bebop2.h, law/bebop2/bebop2_compensator.h): the Bebop 2 flies every backend
// (the SIMD lanes to rounding: xsimd's sin, cos and tanh), its gains
// (the sweep's ksp_xy, ksd_xy: sweep_gains.h), delay and model factor
// (Ku_x) reaching its runs.
TEST(VehicleConcept, TheBebop2FliesEveryBackend) {
  PointGrid grid;
  grid.axes = {{1.0, 2.0}, {1.0, 2.0}, {0, 3, 9}, {1.0, 0.8}};
  const int params[4] = {SweepSpec().paramId("ksp_xy"), SweepSpec().paramId("ksd_xy"), kParamDelay, kParamFirstModelFactor};
  test::setAxes(grid.view, params, grid.axes);
  const SimSetup<aurora_sim::Bebop2, double> ideal = bebopSetup<double>(aurora_control::LinkParams());
  const std::vector<SimResult> flown = scalarLoop<double, false, BebopLaw>(ideal, grid.view);
  const Combination c = grid.view.decode(3);  // ksp 2, ksd 2, no delay, nominal model
  ASSERT_EQ(c.delay(), 0);
  ASSERT_EQ(c.v[kParamFirstModelFactor], 1.0);
  const aurora_control::Reference<double> goal = ideal.config.task.at(60.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(flown[3].final_pos[i], goal.pos[i], 0.02) << i;
  EXPECT_TRUE(feasible(flown[3]));
  EXPECT_NE(flown[3].iae, flown[3 + 12].iae);  // Ku_x 0.8
  EXPECT_NE(flown[3].iae, flown[3 + 4].iae);   // delay 3
  expectEveryBackendAgrees<BebopLaw>(ideal, grid.view, 1e-9);
  expectEveryBackendAgrees<BebopLaw>(bebopSetup<float>(aurora_control::LinkParams()), grid.view, 2e-3);
  expectEveryBackendAgrees<BebopLaw>(bebopSetup<double>(lossyLink()), grid.view, 1e-9);
  expectEveryBackendAgrees<BebopLaw>(bebopSetup<float>(lossyLink()), grid.view, 2e-3);
}

// The Pioneer P3-DX (aurora_sim/vehicle/pioneer3dx/pioneer3dx.h, law/pioneer3dx/pioneer_laws.h):
// 14 states, 2 inputs, Ts 0.1 s, on the floor; every backend, its delay and
// model factor (theta1) reaching its runs.
TEST(VehicleConcept, ThePioneerFliesEveryBackend) {
  using PioneerLaw = aurora_control::PioneerDynamic;
  PointGrid grid;
  grid.axes = {{0.2, 0.35}, {0.5, 0.75}, {0, 2, 5}, {1.0, 1.2}};
  const int params[4] = {SweepSpec().paramId("kc1"), SweepSpec().paramId("kd1_u"), kParamDelay, kParamFirstModelFactor};
  test::setAxes(grid.view, params, grid.axes);
  auto setup = [](const aurora_control::LinkParams& link, auto precision) {
    using T = decltype(precision);
    auto s = setupOf<T, aurora_sim::Pioneer3dx>(
        aurora_sim::loadVehicleFile<aurora_sim::Pioneer3dx>(test::configDir() + "/vehicles/pioneer3dx.yaml"), link);
    s.config.task = aurora_control::positioningTask(T(2), T(1), T(0), T(60));  // on the floor
    s.iterations = aurora_control::studyIterationCount(60.0, s.vehicle.Ts);
    return s;
  };
  const auto ideal = setup(aurora_control::LinkParams(), 0.0);
  const std::vector<SimResult> flown = scalarLoop<double, false, PioneerLaw>(ideal, grid.view);
  const Combination c = grid.view.decode(3);  // kc1 0.35, kd1_u 0.75 (AuRoRA's), no delay, nominal model
  ASSERT_EQ(c.delay(), 0);
  EXPECT_NEAR(flown[3].final_pos[0], 2.0, 0.02);
  EXPECT_NEAR(flown[3].final_pos[1], 1.0, 0.02);
  EXPECT_EQ(flown[3].final_pos[2], 0.0);
  EXPECT_NE(flown[3].iae, flown[3 + 12].iae);  // theta1 x 1.2
  EXPECT_NE(flown[3].iae, flown[3 + 4].iae);   // delay 2
  expectEveryBackendAgrees<PioneerLaw>(ideal, grid.view, 1e-9);
  expectEveryBackendAgrees<PioneerLaw>(setup(aurora_control::LinkParams(), 0.0f), grid.view, 2e-3);
  expectEveryBackendAgrees<PioneerLaw>(setup(lossyLink(), 0.0), grid.view, 1e-9);
  expectEveryBackendAgrees<PioneerLaw>(setup(lossyLink(), 0.0f), grid.view, 2e-3);
}

// The delay rule holds for the test vehicle as for the AR.Drone: the state
// the law receives at iteration k is that of k - d once k >= d.
TEST(VehicleConcept, TheDelayInForceIsTheConfiguredOne) {
  const PointGrid grid;
  const SimSetup<Vehicle, double> setup = pointSetup<double>(aurora_control::LinkParams());
  const Combination c = grid.view.decode(4 + 2 * 6);  // delay 9
  ASSERT_EQ(c.delay(), 9);
  long checked = 0;
  aurora_control::runLoop<Law>(studyRun<Law>(setup, c), setup.config, 100,
                               [&](const aurora_control::LoopObservation<Vehicle, double>& o) {
                                 EXPECT_EQ(o.received, o.k >= 9 ? o.k - 9 : o.k);
                                 // The vehicle stepped with the command applied: dv = F / m Ts.
                                 for (int i = 0; i < 3; ++i) {
                                   EXPECT_NEAR(o.after.model.X[3 + i] - o.X_before[3 + i],
                                               o.step.U[i] / 0.5 * setup.vehicle.Ts, 1e-12);
                                 }
                                 ++checked;
                               });
  EXPECT_EQ(checked, 100);
}
