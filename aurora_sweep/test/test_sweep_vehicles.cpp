// The studies of the lab's other robots (issue 33): the shipped sweeps of
// the Bebop 2 (at 30 and 5 Hz) and of the Pioneer P3-DX fly their own
// vehicle and law; a combination's record is the flight of its gains and
// delay; the scalar loop, the SIMD lanes and the kernel's per-thread entry
// agree; the sweep program draws their max-tolerable-delay figure; a gain,
// a model factor or a task they cannot take is refused naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/kernel_entry.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

SweepSpec shipped(const std::string& name) {
  return loadSweepFile(test::configDir() + "/sweeps/" + name + ".yaml", test::configDir());
}

std::vector<std::string> columnNames(const SweepSpec& spec) {
  std::vector<std::string> names;
  for (int id : spec.columns()) names.push_back(spec.paramNameOf(id));
  return names;
}

// Combination `index` flown by hand: law `Law` with the gains `gains`
// built from the combination's values by the caller, its delay, the
// sweep's setup (its task, criteria and clamp).
template <class Law>
SimResult flownByHand(const SimSetup<typename Law::Vehicle, double>& setup, long delay,
                      const typename Law::template Gains<double>& gains) {
  aurora_control::StudyRun<typename Law::Data, double> run{setup.model, setup.model, gains, delay};
  return compactResult(aurora_control::runLoop<Law>(run, setup.config, setup.iterations));
}

void expectSameRecord(const SimResult& a, const SimResult& b, long index) {
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(SimResult)), 0) << "combination " << index;
}

// The spec cut to [begin, begin + n): the scalar loop, the SIMD lanes and
// the kernel's threads agree.
template <class Law>
void expectBackendsAgree(SweepSpec spec, long begin, long n) {
  spec.range_begin = begin, spec.range_end = begin + n;
  const std::vector<SimResult> scalar = test::runOn("scalar", spec);
  test::expectRunsAgree(scalar, test::runOn("cpu", spec), 0.0);
  const auto setup = makeSetup<typename Law::Vehicle, double>(spec);
  const GridView grid = spec.view();
  const std::vector<SimResult> threads = test::launchOnHost(n, 32, [&](unsigned b, unsigned block, unsigned t,
                                                                       SimResult* out) {
    sweepThread<Law, double, aurora_control::kShortHistory>(setup, grid, begin, n, out, b, block, t);
  });
  for (long i = 0; i < n; ++i) expectSameRecord(scalar[static_cast<size_t>(i)], threads[static_cast<size_t>(i)], i);
}

}  // namespace

TEST(SweepVehicles, TheShippedStudiesFlyTheirOwnVehicle) {
  const SweepSpec b30 = shipped("bebop2_delay"), b5 = shipped("bebop2_delay_5hz"), p = shipped("pioneer_delay");
  EXPECT_EQ(b30.vehicle_type, "bebop2");
  EXPECT_EQ(p.vehicle_type, "pioneer3dx");
  EXPECT_EQ(b30.size(), 16 * 16 * 48);
  EXPECT_EQ(p.size(), 16 * 16 * 32);
  EXPECT_EQ(b30.iterations(), 1801);  // 60 s of 1/30 s
  EXPECT_EQ(p.iterations(), 600);     // while t < 60 s, t += 0.1 s (t accumulated: 60.000000000000085 after 600)
  const int period = b30.paramId("period_steps");
  EXPECT_EQ(period, LawGainBlock<aurora_control::Bebop2Compensator>::kFirst + 9);
  EXPECT_EQ(b30.fixed[period], 1.0);
  EXPECT_EQ(b5.fixed[period], 6.0);  // 5 Hz
  const std::vector<std::string> bebop = {"delay", "ksp_xy", "ksp_z", "ksp_yaw", "ksd_xy", "ksd_z",
                                          "ksd_yaw", "kp_xy", "kp_z", "kp_yaw", "period_steps"};
  EXPECT_EQ(columnNames(b30), bebop);
  const std::vector<std::string> pioneer = {"delay", "kc1", "kc2", "kd1_u", "kd1_omega", "kd2_u", "kd2_omega"};
  EXPECT_EQ(columnNames(p), pioneer);
  // AuRoRA's gains are on the grids (the docs' max tolerable delay there).
  const GridView g = b30.view();
  const Combination c = g.decode(3 + 16 * 3);
  EXPECT_EQ(c.v[SweepSpec().paramId("kp_xy")], 1.0);
  EXPECT_EQ(c.v[SweepSpec().paramId("ksd_xy")], 2.0);
  EXPECT_EQ(c.v[SweepSpec().paramId("ksp_xy")], 2.0);  // the file's default: AuRoRA's
}

TEST(SweepVehicles, ACombinationIsTheFlightOfItsGainsAndDelay) {
  SweepSpec b5 = shipped("bebop2_delay_5hz");
  b5.range_begin = 0, b5.range_end = 512;  // the first 2 delays of the grid
  const std::vector<SimResult> bebop = test::runOn("scalar", b5);
  const auto bsetup = makeSetup<aurora_sim::Bebop2, double>(b5);
  for (long i : {0L, 17L, 51L, 300L, 511L}) {
    const Combination c = b5.view().decode(i);
    auto g = aurora_control::CompensatorGains<double>::defaults();
    g.kp[0] = g.kp[1] = c.v[SweepSpec().paramId("kp_xy")];
    g.ksd[0] = g.ksd[1] = c.v[SweepSpec().paramId("ksd_xy")];
    g.period_steps = 6.0;
    expectSameRecord(bebop[static_cast<size_t>(i)], flownByHand<aurora_control::Bebop2Compensator>(bsetup, c.delay(), g),
                     i);
  }
  SweepSpec p = shipped("pioneer_delay");
  p.range_begin = 256 * 7, p.range_end = 256 * 8;  // delay 7
  const std::vector<SimResult> pioneer = test::runOn("scalar", p);
  const auto psetup = makeSetup<aurora_sim::Pioneer3dx, double>(p);
  for (long i : {0L, 99L, 255L}) {
    const Combination c = p.view().decode(p.range_begin + i);
    ASSERT_EQ(c.delay(), 7);
    auto g = aurora_control::PioneerDynamicGains<double>::defaults();
    g.kc1[0] = g.kc1[1] = c.v[SweepSpec().paramId("kc1")];
    g.kc2[0] = g.kc2[1] = c.v[SweepSpec().paramId("kc2")];
    expectSameRecord(pioneer[static_cast<size_t>(i)], flownByHand<aurora_control::PioneerDynamic>(psetup, 7, g), i);
  }
}

TEST(SweepVehicles, EveryBackendAgrees) {
  expectBackendsAgree<aurora_control::Bebop2Compensator>(shipped("bebop2_delay"), 256 * 5, 256);
  expectBackendsAgree<aurora_control::Bebop2Compensator>(shipped("bebop2_delay_5hz"), 256 * 9, 256);
  expectBackendsAgree<aurora_control::PioneerDynamic>(shipped("pioneer_delay"), 256 * 4, 256);
}

TEST(SweepVehicles, TheSweepProgramDrawsTheMaxTolerableDelay) {
  const std::string out = ::testing::TempDir() + "/sweep_pioneer_delay";
  FILE* pipe = popen((std::string(AURORA_SWEEP_BIN) + " --config " + test::configDir() +
                      "/sweeps/pioneer_delay.yaml --out " + out + " --backend cpu --quiet --overwrite 2>&1").c_str(),
                     "r");
  std::string log;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) log += buf;
  ASSERT_EQ(pclose(pipe), 0) << log;
  const std::string summary = test::readText(out + "/summary.json");
  EXPECT_NE(summary.find("\"gains\": [\n      \"kc1\",\n      \"kc2\"\n    ]"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"vehicle_type\": \"pioneer3dx\""), std::string::npos) << summary;
  EXPECT_TRUE(std::ifstream(out + "/max_tolerable_delay.png").good());
  EXPECT_TRUE(std::ifstream(out + "/feasible_volume.png").good());
}

TEST(SweepVehicles, WhatTheyCannotTakeIsRefusedNamingTheKey) {
  const std::string bebop = "sweep:\n  controller: bebop2_compensator\n  task: tasks/positioning.yaml\n"
                            "  parameters:\n    delay: {from: 0, to: 3, count: 4}\n";
  EXPECT_EQ(test::refusal(bebop), "");
  std::string e = test::refusal(bebop + "    kp: 0.5\n");
  EXPECT_NE(e.find("'sweep.parameters.kp' is not a parameter of the bebop2_compensator controller: accepted delay, "
                   "Ku_x, Ku_y, Ku_z, Ku_yaw, Kv_x, Kv_y, Kv_z, Kv_yaw, uplink_jitter"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("ksp_xy, ksp_z, ksp_yaw, ksd_xy, ksd_z, ksd_yaw, kp_xy, kp_z, kp_yaw, period_steps"),
            std::string::npos)
      << e;
  e = test::refusal(bebop + "    m: 1.2\n");  // the AR.Drone's model factor
  EXPECT_NE(e.find("'sweep.parameters.m' is not a parameter of the bebop2_compensator controller"), std::string::npos)
      << e;
  e = test::refusal(bebop + "    period_steps: 0\n");
  EXPECT_NE(e.find("period_steps"), std::string::npos) << e;
  EXPECT_NE(e.find("[1, 30]"), std::string::npos) << e;
  e = test::refusal(bebop + "    period_steps: 2.5\n");
  EXPECT_NE(e.find("period_steps"), std::string::npos) << e;
  e = test::refusal(bebop + "    ksd_xy: 101\n");
  EXPECT_NE(e.find("'sweep.parameters.ksd_xy'"), std::string::npos) << e;
  EXPECT_NE(e.find("[0, 100]"), std::string::npos) << e;
  e = test::refusal(bebop + "  vehicle: vehicles/pioneer3dx.yaml\n");
  EXPECT_NE(e.find("is of type 'pioneer3dx', but the sweep's controller 'bebop2_compensator' flies type 'bebop2'"),
            std::string::npos)
      << e;
  const std::string pioneer = "sweep:\n  controller: pioneer_dynamic\n  parameters:\n    delay: 3\n";
  e = test::refusal(pioneer);
  EXPECT_NE(e.find("'sweep.task' is missing: the default task (the thesis's positioning, at 2 m) is not one a "
                   "pioneer3dx can fly"),
            std::string::npos)
      << e;
  e = test::refusal(pioneer + "  task: tasks/lemniscate.yaml\n");
  EXPECT_NE(e.find("'task.height' = 1.5 is outside the accepted range [0, 0] m (a ground robot's task lies on the "
                   "floor)"),
            std::string::npos)
      << e;
  e = test::refusal("sweep:\n  controller: pioneer_dynamic\n  task: tasks/pioneer_lemniscate.yaml\n  parameters:\n"
                    "    delay: 3\n    kc1: 11\n");
  EXPECT_NE(e.find("'sweep.parameters.kc1'"), std::string::npos) << e;
  EXPECT_NE(e.find("[0, 10]"), std::string::npos) << e;
}

// The model factors that docs/bebop2.md and docs/pioneer3dx.md promise for
// sweeps, by the vehicle's own names (its factorName): a sweep file's Ku_x
// (theta1) at 0.5 flies a plant whose input gain x (theta1) is halved under
// a law that keeps the vehicle file's model (a robustness study), to the
// bit of that flight by hand, on the scalar loop, the SIMD lanes and the
// CUDA kernel's per-thread entry (run on the host);
// summary.json lists them as model factors. (Refused as "not a parameter"
// before: the names were the AR.Drone's only.)
template <class Law>
void expectTheFactorScales(const char* name, const char* controller, const char* task,
                           void (*halve)(typename Law::Vehicle::template Params<double>&),
                           const typename Law::template Gains<double>& gains) {
  const std::string text = std::string("sweep:\n  controller: ") + controller + "\n  task: " + task +
                           "\n  early_stop: false\n  parameters:\n    delay: {from: 0, to: 2, count: 3}\n    " + name + ": 0.5\n";
  const SweepSpec spec =
      loadSweepFile(test::writeTemp(std::string("factor_") + name + ".yaml", text), test::configDir());
  ASSERT_EQ(spec.paramId(name), kParamFirstModelFactor) << name;
  const std::vector<std::string> names = columnNames(spec);
  EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  const std::vector<SimResult> swept = test::runOn("scalar", spec);
  expectBackendsAgree<Law>(spec, 0, 3);  // the lanes and the kernel's per-thread entry
  const auto setup = makeSetup<typename Law::Vehicle, double>(spec);
  auto plant = setup.vehicle;
  halve(plant);
  for (long delay = 0; delay < 3; ++delay) {
    aurora_control::StudyRun<typename Law::Data, double> run{plant, setup.model, gains, delay};
    const SimResult by_hand = compactResult(aurora_control::runLoop<Law>(run, setup.config, setup.iterations));
    expectSameRecord(swept[static_cast<size_t>(delay)], by_hand, delay);
    const SimResult nominal = flownByHand<Law>(setup, delay, gains);
    EXPECT_NE(swept[static_cast<size_t>(delay)].iae, nominal.iae) << name;  // the factor reaches the plant
    EXPECT_EQ(swept[static_cast<size_t>(delay)].steps, by_hand.steps) << name;
  }
}

TEST(SweepVehicles, TheirModelFactorsAreSweepParametersByTheirOwnNames) {
  expectTheFactorScales<aurora_control::Bebop2Compensator>(
      "Ku_x", "bebop2_compensator", "tasks/positioning.yaml",
      [](aurora_sim::Bebop2::Params<double>& p) { p.Ku[aurora_sim::kBebopX] *= 0.5; },
      aurora_control::CompensatorGains<double>::defaults());
  expectTheFactorScales<aurora_control::PioneerDynamic>(
      "theta1", "pioneer_dynamic", "tasks/pioneer_lemniscate.yaml",
      [](aurora_sim::Pioneer3dx::Params<double>& p) { p.theta[0] *= 0.5; },
      aurora_control::PioneerDynamicGains<double>::defaults());
  std::string e = test::refusal("sweep:\n  controller: pioneer_dynamic\n  task: tasks/pioneer_lemniscate.yaml\n"
                                "  parameters:\n    delay: 0\n    theta1: 11\n");
  EXPECT_NE(e.find("'sweep.parameters.theta1'"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 10x"), std::string::npos) << e;
  e = test::refusal("sweep:\n  controller: pioneer_dynamic\n  task: tasks/pioneer_lemniscate.yaml\n"
                    "  parameters:\n    delay: 0\n    Ku_x: 1.1\n");
  EXPECT_NE(e.find("'sweep.parameters.Ku_x' is not a parameter of the pioneer_dynamic controller: accepted delay, "
                   "theta1, theta2, theta3, theta4, theta5, theta6, uplink_jitter"),
            std::string::npos)
      << e;
}
