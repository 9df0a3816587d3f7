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

#include "../src/batch_engine.h"
#include "aurora_sweep/kernel_entry.h"
#include "point_mass.h"
#include "sweep_test_support.h"

namespace {

using namespace aurora_sweep;
using Law = point_mass::PointPd;
using Vehicle = point_mass::PointMass;

// A grid over kp, kd, the delay and the mass factor (48 combinations).
struct PointGrid {
  std::vector<std::vector<double>> axes{{1.0, 2.0, 4.0}, {1.5, 3.0}, {0, 3, 9, 20}, {1.0, 1.5}};
  GridView view{};
  PointGrid() {
    const int params[4] = {kParamKp, kParamKd, kParamDelay, kParamFirstModelFactor};
    for (int i = 0; i < kParamCount; ++i) view.fixed[i] = 0.0;
    for (int i = 0; i < kModelFactorCount; ++i) view.fixed[kParamFirstModelFactor + i] = 1.0;
    for (int i = 0; i < kLinkParamCount; ++i) view.fixed[kParamFirstLinkValue + i] = std::nan("");
    test::setAxes(view, params, axes);
  }
};

// 60 s towards (2, 1, 2) from the origin; over `link` unless it is ideal.
template <typename T>
SimSetup<Vehicle, T> pointSetup(const aurora_control::LinkParams& link) {
  SimSetup<Vehicle, T> s;
  s.vehicle = point_mass::Params<double>{1.0 / 30.0, 0.5};
  s.model = s.vehicle.template cast<T>();
  s.config.link = link;
  s.iterations = aurora_control::studyIterationCount(60.0, s.vehicle.Ts);
  s.varies_model = true;
  s.ideal_link = link.ideal();
  return s;
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

template <typename T, bool Linked>
std::vector<SimResult> scalarLoop(const SimSetup<Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out;
  for (long i = 0; i < grid.size(); ++i) out.push_back(simulateCombination<Law, T, 64, Linked>(setup, grid, i));
  return out;
}

template <typename T, bool Linked>
std::vector<SimResult> kernelThreads(const SimSetup<Vehicle, T>& setup, const GridView& grid) {
  return test::launchOnHost(grid.size(), 16, [&](unsigned b, unsigned block, unsigned t, SimResult* out) {
    sweepThread<Law, T, 64, Linked>(setup, grid, 0, grid.size(), out, b, block, t);
  });
}

template <typename T>
std::vector<SimResult> simdLanes(const SimSetup<Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out(static_cast<size_t>(grid.size()));
  std::atomic<long> next{0};
  Progress progress{0};
  BatchWorker<T, xsimd::default_arch, 64, Law>(setup, grid, 0, grid.size(), out, next, progress).run();
  EXPECT_EQ(progress.load(), grid.size());
  return out;
}

// The offline runner, one combination at a time: runLoop over the delay
// rule; over a link, the combination's link keyed by its index (as a sweep).
template <typename T>
std::vector<SimResult> runner(const SimSetup<Vehicle, T>& setup, const GridView& grid) {
  std::vector<SimResult> out;
  for (long i = 0; i < grid.size(); ++i) {
    const Combination c = grid.decode(i);
    const auto run = studyRun<Law>(setup, c);
    aurora_control::RunnerConfig<T> cfg = setup.config;
    cfg.link = combinationLink(setup.config.link, run.delay, c);
    aurora_control::NoObserver none;
    out.push_back(compactResult(
        setup.ideal_link ? aurora_control::runLoop<Law>(run, cfg, setup.iterations)
                         : aurora_control::runOverModelLink<Law, T, 64>(run, cfg, setup.iterations, none, c.key)));
  }
  return out;
}

void expectSameBytes(const std::vector<SimResult>& a, const std::vector<SimResult>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(std::memcmp(&a[i], &b[i], sizeof(SimResult)), 0) << what << " " << i;
}

template <typename T>
void expectEveryBackendAgrees(const aurora_control::LinkParams& link) {
  const PointGrid grid;
  const SimSetup<Vehicle, T> setup = pointSetup<T>(link);
  const std::vector<SimResult> scalar =
      link.ideal() ? scalarLoop<T, false>(setup, grid.view) : scalarLoop<T, true>(setup, grid.view);
  expectSameBytes(scalar, runner(setup, grid.view), "runner");
  expectSameBytes(scalar, simdLanes(setup, grid.view), "simd lanes");
  expectSameBytes(scalar,
                  link.ideal() ? kernelThreads<T, false>(setup, grid.view) : kernelThreads<T, true>(setup, grid.view),
                  "kernel threads");
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
