// Sweeps over either law, any task and the model's parameters: the shipped
// 13-parameter and robustness studies (cut to a few hundred samples) give
// the same results on every backend; the sweep's simulation at the
// underactuated law's defaults flies exactly the offline `flight` runner's
// trajectory; mistakes in such sweep files are refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "aurora_control/loop/ardrone2/ardrone_study.h"
#include "aurora_control/loop/flight_runner.h"
#include "aurora_sweep/backends.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;
using aurora_control::LawType;

namespace {

using test::readText;
using test::refusal;
using test::relClose;
using test::robustness;
using test::runOn;
using test::study13;
using test::widestIsa;
using test::writeTemp;

// The AR.Drone law the study's controller names.
LawType studyLaw(const SweepSpec& spec) {
  LawType law = LawType::kPdSaturated;
  EXPECT_TRUE(aurora_control::lawFromName(spec.controller, law)) << spec.controller;
  return law;
}

// The kernel's per-thread function (simulateCombination) on the host.
std::vector<SimResult> runKernelBody(const SweepSpec& spec) {
  std::vector<SimResult> out;
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  const GridView grid = spec.view();
  for (long i = 0; i < spec.size(); ++i) {
    out.push_back(studyLaw(spec) == LawType::kPdSaturated
                      ? simulateCombination<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>, double, 64>(setup, grid, i)
                      : simulateCombination<aurora_control::ArdroneLaw<aurora_control::LawType::kUnderactuated>, double, 64>(setup, grid, i));
  }
  return out;
}

// Double: identical flags and step counts, metrics to 1e-9 relative (the
// libm differences between scalar and SIMD functions). Both outcomes occur.
void expectSameResults(const std::vector<SimResult>& ref, const std::vector<SimResult>& got,
                       const std::string& what) {
  ASSERT_EQ(ref.size(), got.size()) << what;
  long feasible = 0, compared = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    ASSERT_EQ(ref[i].ok, got[i].ok) << what << ", combination " << i;
    ASSERT_EQ(ref[i].steps, got[i].steps) << what << ", combination " << i;
    feasible += aurora_sweep::feasible(ref[i]);
    if (!(ref[i].ok & 1)) continue;  // diverged: metrics meaningless
    ++compared;
    EXPECT_PRED3(relClose, ref[i].iae, got[i].iae, 1e-9) << what << " " << i;
    EXPECT_PRED3(relClose, ref[i].itae, got[i].itae, 1e-9) << what << " " << i;
    EXPECT_PRED3(relClose, ref[i].iasc, got[i].iasc, 1e-9) << what << " " << i;
  }
  EXPECT_GT(feasible, 10) << what;
  EXPECT_GT(static_cast<long>(ref.size()) - feasible, 10) << what;
  EXPECT_GT(compared, 20) << what;
}

void expectBackendsAgree(const SweepSpec& spec) {
  const std::vector<SimResult> scalar = runOn("scalar", spec);
  expectSameResults(scalar, runKernelBody(spec), "kernel body");
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported) expectSameResults(scalar, runOn(isa.key, spec), "cpu " + isa.key);
  }
}

double flagAgreement(const std::vector<SimResult>& a, const std::vector<SimResult>& b) {
  long agree = 0;
  for (size_t i = 0; i < a.size(); ++i) agree += feasible(a[i]) == feasible(b[i]);
  return double(agree) / double(a.size());
}

}  // namespace

TEST(Study13, TheShippedStudyVariesTwelveGainsAndTheDelay) {
  const SweepSpec spec = study13(64);
  EXPECT_EQ(studyLaw(spec), LawType::kUnderactuated);
  EXPECT_EQ(spec.point_params.size(), 13u);
  EXPECT_EQ(spec.max_delay, 63);
  // Parameters of the result rows: the 12 gains and the delay, no model factor.
  EXPECT_EQ(spec.columns().size(), 13u);
  EXPECT_FALSE(spec.variesModel());
  // The first Sobol point is the middle of every range: the spec's defaults.
  const Combination c = spec.view().decode(0);
  const auto defaults = aurora_control::UnderactuatedGains<double>::defaults();
  for (int i = 0; i < kUnderactuatedGainCount; ++i) {
    EXPECT_NEAR(c.v[kParamFirstUnderactuatedGain + i], aurora_control::underactuatedGain(defaults, i), 1e-12)
        << paramName(kParamFirstUnderactuatedGain + i, SweepShape::kNone);
  }
}

TEST(Study13, BackendsAgreeInDouble) { expectBackendsAgree(study13(512)); }

TEST(Study13, FloatFeasibleFlagsTrackDouble) {
  const double share = flagAgreement(runOn("scalar", study13(2048)), runOn(widestIsa(), study13(2048, Precision::kFloat)));
  std::printf("underactuated_13, 2048 samples: float flags agree with double on %.2f %%\n", 100 * share);
  EXPECT_GE(share, 0.995);
}

TEST(Robustness, BackendsAgreeInDouble) {
  const SweepSpec spec = robustness(512);
  EXPECT_TRUE(spec.variesModel());
  expectBackendsAgree(spec);
}

TEST(Robustness, FloatFeasibleFlagsTrackDouble) {
  const double share = flagAgreement(runOn("scalar", robustness(1024)), runOn(widestIsa(), robustness(1024, Precision::kFloat)));
  std::printf("robustness, 1024 samples: float flags agree with double on %.2f %%\n", 100 * share);
  EXPECT_GE(share, 0.995);
}

// Sample i is fixed by the file: the same points on every load, the same
// results on any number of threads.
TEST(Study13, SamplesAndResultsDoNotDependOnRunOrThreads) {
  const SweepSpec a = study13(300), b = study13(300);
  EXPECT_EQ(a.points, b.points);
  const std::vector<SimResult> one = runOn(widestIsa(), a, 1), two = runOn(widestIsa(), b, 2);
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].ok, two[i].ok) << i;
    ASSERT_EQ(one[i].iae, two[i].iae) << i;  // bit for bit: a lane's work does not depend on its neighbours
  }
}

namespace {

// A one-combination sweep: `law_and_task` gives controller and task keys.
SweepSpec single(const std::string& name, const std::string& body) {
  return loadSweepFile(writeTemp(name + ".yaml", "sweep:\n  early_stop: false\n" + body), test::configDir());
}

// The states the sweep's simulation of combination 0 flies (studyRun and
// runClosedLoop: what simulateCombination runs in every backend).
std::vector<std::vector<double>> sweepStates(const SweepSpec& spec, aurora_control::RunnerResult& result) {
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  const aurora_control::ArdroneRun<double> run = studyRun<aurora_control::ArdroneLaw<LawType::kPdSaturated>>(setup, spec.view().decode(0));
  std::vector<std::vector<double>> states;
  auto observe = [&](const aurora_control::FlightObservation& o) {
    states.emplace_back(o.after.model.X, o.after.model.X + aurora_sim::kStateSize);
  };
  result = aurora_control::runStudy(studyLaw(spec), run, setup.config, observe);
  return states;
}

// The same flight with the offline runner of the `flight` tool (the
// controller node's core), with the law's defaults from the controller file.
std::vector<std::vector<double>> flightStates(const SweepSpec& spec, aurora_control::FlightResult& result) {
  aurora_control::LawSettings<aurora_control::ArdroneLawData> set;
  set.law = int(studyLaw(spec));
  set.gains.pd = {spec.fixed[kParamKp], spec.fixed[kParamKd]};
  set.vehicle = spec.paramsOf(aurora_sim::Ardrone2());
  set.delay = static_cast<long>(spec.fixed[kParamDelay]);
  set.clamp_commands = spec.clamp_commands;
  set.Ts = spec.paramsOf(aurora_sim::Ardrone2()).Ts;
  std::vector<std::vector<double>> states;
  result = aurora_control::runFlight(
      spec.paramsOf(aurora_sim::Ardrone2()), set, spec.task, aurora_control::studyIterationCount(spec.duration(), spec.paramsOf(aurora_sim::Ardrone2()).Ts),
      [&](const aurora_control::FlightObservation& o, double) {
        states.emplace_back(o.after.model.X, o.after.model.X + aurora_sim::kStateSize);
      });
  return states;
}

// Every state bit for bit, the same steps, and the metrics bit for bit: one
// closed loop, and one metric time (the loop clock) for the study and the
// node's core.
void expectSameFlight(const SweepSpec& spec) {
  aurora_control::RunnerResult sweep;
  aurora_control::FlightResult flight;
  const auto a = sweepStates(spec, sweep);
  const auto b = flightStates(spec, flight);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(sweep.steps, flight.steps);
  long mismatches = 0;
  for (size_t k = 0; k < a.size(); ++k) mismatches += a[k] != b[k];
  EXPECT_EQ(mismatches, 0) << "of " << a.size() << " states";
  EXPECT_EQ(sweep.iae, flight.iae);
  EXPECT_EQ(sweep.iasc, flight.iasc);
  EXPECT_EQ(sweep.itae, flight.itae);
  // Not a vacuous pass: the drone flew away from the start.
  double farthest = 0;
  for (const auto& x : a) farthest = std::max(farthest, std::hypot(x[aurora_sim::kX], x[aurora_sim::kY]));
  EXPECT_GT(farthest, 0.5);
  // And the backends' compact results are that run's: the scalar loop's bit
  // for bit, the SIMD lanes' to the libm differences of their functions.
  const SimResult scalar = runOn("scalar", spec)[0], simd = runOn(widestIsa(), spec)[0];
  EXPECT_EQ(scalar.steps, flight.steps);
  EXPECT_EQ(scalar.iae, flight.iae);
  EXPECT_EQ(scalar.final_pos[0], static_cast<float>(flight.final_pos[0]));
  EXPECT_EQ(simd.steps, flight.steps);
  EXPECT_PRED3(relClose, simd.iae, flight.iae, 1e-9);
  EXPECT_NEAR(simd.final_pos[0], flight.final_pos[0], 1e-5);
}

}  // namespace

TEST(SweepVsFlight, UnderactuatedDefaultsReproduceTheFlightRunner) {
  for (const char* delay : {"0", "10"}) {
    SCOPED_TRACE(std::string("delay ") + delay);
    expectSameFlight(single("ua_defaults", std::string("  controller: underactuated\n  task: tasks/positioning.yaml\n"
                                                       "  parameters: {delay: ") + delay + "}\n"));
  }
}

TEST(SweepVsFlight, TrajectoryTasksAndMissionsFlyTheSame) {
  expectSameFlight(single("ua_circle", "  controller: underactuated\n  task: tasks/circle.yaml\n  parameters: {delay: 5}\n"));
  expectSameFlight(single("ua_lemniscate", "  controller: underactuated\n  task: tasks/lemniscate.yaml\n  parameters: {delay: 3}\n"));
  // The PD law on the thesis's mission: the drivers' clamp, as the node applies it.
  expectSameFlight(single("pd_mission", "  controller: pd_saturated\n  task: tasks/mission4.yaml\n  clamp_commands: true\n"
                                        "  parameters: {kp: 0.5, kd: 0.85, delay: 8}\n"));
}

namespace {

void expectRefused(const std::string& yaml, const std::string& text) {
  const std::string msg = refusal(yaml);
  EXPECT_NE(msg.find(text), std::string::npos) << "expected '" << text << "' in: " << msg;
}

}  // namespace

TEST(Study13Refusal, MistakesNameTheKey) {
  const std::string ua = "sweep:\n  controller: underactuated\n";
  // A name the chosen law does not have: the accepted ones listed.
  expectRefused(ua + "  parameters: {kp: 0.5, delay: 0}\n",
                "'sweep.parameters.kp' is not a parameter of the underactuated controller: accepted delay, k1_x, "
                "k2_x, k1_y, k2_y, k1_z, k2_z, k1_phi, k2_phi, k1_theta, k2_theta, k1_psi, k2_psi, m, Ixx, Iyy, Izz, "
                "Cf, Ct, Km, Jm");
  expectRefused(ua + "  parameters: {delay: 0}\n  order: [k1_x, k9]\n", "'sweep.order' is not a parameter");
  // Ranges beyond physical limits, naming them.
  expectRefused(ua + "  design: sobol\n  samples: 8\n  parameters: {delay: 0, k1_x: {from: 0, to: 1}}\n",
                "'sweep.parameters.k1_x.from' = 0 is outside the accepted range [0.001, 100] of k1_x");
  expectRefused(ua + "  parameters: {delay: 0, m: {from: 0.8, to: 20, count: 3}}\n",
                "'sweep.parameters.m.to' = 20 is outside the accepted range [0.1, 10] of m (a factor of the vehicle "
                "file's value");
  expectRefused(ua + "  parameters: {k1_x: 0.5}\n", "'sweep.parameters.delay' is missing");
  expectRefused("sweep:\n  parameters: {kp: 0.5, delay: 0}\n", "'sweep.parameters.kd' is missing");
  // A delay not shorter than the task, in a design's range.
  expectRefused(ua + "  design: random\n  samples: 8\n  parameters: {delay: {from: 0, to: 1801}}\n",
                "'sweep.parameters.delay' = 1801 samples is not shorter than the run's 1801 steps");
  // Points files: any parameter names as columns, checked the same way.
  const std::string csv = writeTemp("ua_points.csv", "k1_z,delay,m\n5,3,1.1\n4,0,12\n");
  expectRefused(ua + "  points: " + csv + "\n", "row 3 m' = 12 is outside the accepted range [0.1, 10] of m");
  const std::string bad = writeTemp("ua_bad_points.csv", "k1_z,kp\n5,0.5\n");
  expectRefused(ua + "  points: " + bad + "\n", "header column kp' is not a parameter of the underactuated controller");
}

TEST(Study13, PointsFileTakesAnyParameterColumns) {
  const std::string csv = writeTemp("ua_points_ok.csv", "k1_z,delay,m\n5,3,1.1\n4,0,0.9\n");
  const SweepSpec spec = loadSweepFile(writeTemp("ua_points.yaml", "sweep:\n  controller: underactuated\n  points: " +
                                                                       csv + "\n  parameters: {k2_z: 3}\n"),
                                       test::configDir());
  ASSERT_EQ(spec.size(), 2);
  const Combination c = spec.view().decode(1);
  EXPECT_EQ(c.v[kParamFirstUnderactuatedGain + 4], 4.0);  // k1_z from the file
  EXPECT_EQ(c.v[kParamFirstUnderactuatedGain + 5], 3.0);  // k2_z fixed in parameters
  EXPECT_EQ(c.v[kParamFirstUnderactuatedGain + 0], 0.5);  // k1_x: the spec's default
  EXPECT_EQ(c.v[kParamFirstModelFactor], 0.9);            // m
  EXPECT_EQ(c.delay(), 0);
  EXPECT_TRUE(spec.variesModel());
}

#ifdef AURORA_SWEEP_BIN
// The program on a small 13-parameter design: one column per parameter of
// the law, summary.json names them, the marginal and pair plots are drawn
// (the Kp x Kd figures are not: this law has no Kp, Kd).
TEST(Study13, TheProgramWritesEveryParameterAndItsPlots) {
  const SweepSpec small = study13(256);
  const std::string out = ::testing::TempDir() + "/study13_program";
  const std::string cmd = std::string(AURORA_SWEEP_BIN) + " --config " + small.file + " --config-dir " +
                          test::configDir() + " --out " + out + " --backend cpu --output both --quiet --overwrite 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string log;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) log += buf;
  ASSERT_EQ(pclose(p), 0) << log;
  std::ifstream csv(out + "/results.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("index,delay,k1_x,k2_x,k1_y,k2_y,k1_z,k2_z,k1_phi,k2_phi,k1_theta,k2_theta,k1_psi,k2_psi,ok1,", 0),
            0u) << header;
  const std::string summary = readText(out + "/summary.json");
  EXPECT_NE(summary.find("\"controller\": \"underactuated\""), std::string::npos);
  EXPECT_NE(summary.find("\"k2_psi\""), std::string::npos);
  EXPECT_TRUE(std::ifstream(out + "/results.h5").good());
  EXPECT_TRUE(std::ifstream(out + "/feasible_marginals.png").good()) << log;
  EXPECT_TRUE(std::ifstream(out + "/feasible_pairs.png").good()) << log;
  EXPECT_FALSE(std::ifstream(out + "/feasible_volume.png").good());
}
#endif
