// The spec's self-check rows (docs/delay-and-study.md, "Self-check values"),
// reproduced through the runner, full 1801 iterations, no early stop.
#include <gtest/gtest.h>

#include <cmath>

#include "aurora_control/loop/ardrone2/ardrone_study.h"
#include "aurora_control/loop/positioning_runner.h"

using namespace aurora_control;

namespace {

struct SelfCheckRow {
  long delay;
  int kp_index, kd_index;
  bool ok[4];
  double iae, itae, iasc;
  double final_pos[3];
};

// Values printed to 10 significant digits in the spec.
const SelfCheckRow kRows[] = {
    {0, 14, 5, {true, true, true, true}, 9.696094275, 44.87231536, 2.489013563,
     {2.000003154, 0.9999987361, 1.999999961}},
    {3, 1, 19, {true, true, false, true}, 79.66617453, 1877.785809, 0.607348822,
     {1.666709805, 0.8924462953, 1.381598616}},
    {53, 15, 25, {false, false, false, false}, 399.2117079, 13313.32912, 56.0389837,
     {-5.025406388, -7.054979735, 1.952541747}},
};

// 1e-8 relative, but the spec prints 10 significant digits, so a printed
// value carries up to 5e-10 relative rounding of its own.
void expectRel(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, 1e-8 * std::fabs(expected)) << what;
}

}  // namespace

class SelfCheck : public ::testing::TestWithParam<SelfCheckRow> {};

TEST_P(SelfCheck, RunnerReproducesReference) {
  const SelfCheckRow& row = GetParam();
  const PdGains<double> gains{row.kp_index * 0.75 / 31.0, row.kd_index / 31.0};
  RunnerConfig<double> cfg;  // the study: (2, 1, 2), 60 s, unclamped, no early stop
  const RunnerResult r =
      runPositioning(aurora_sim::referenceArdrone2Params(), cfg, gains, row.delay);
  EXPECT_EQ(r.steps, 1801);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(r.ok[i], row.ok[i]) << "check " << i + 1;
  EXPECT_EQ(r.feasible, row.ok[0] && row.ok[1] && row.ok[2] && row.ok[3]);
  expectRel(r.iae, row.iae, "IAE");
  expectRel(r.itae, row.itae, "ITAE");
  expectRel(r.iasc, row.iasc, "IASC");
  expectRel(r.final_pos[0], row.final_pos[0], "final x");
  expectRel(r.final_pos[1], row.final_pos[1], "final y");
  expectRel(r.final_pos[2], row.final_pos[2], "final z");
}

INSTANTIATE_TEST_SUITE_P(SpecRows, SelfCheck, ::testing::ValuesIn(kRows));

TEST(Runner, IterationCountIs1801) {
  EXPECT_EQ(studyIterationCount(60.0, 1.0 / 30.0), 1801);
}

TEST(Runner, EarlyStopKeepsFeasibilityAndStopsAtFirstFailure) {
  const auto p = aurora_sim::referenceArdrone2Params();
  RunnerConfig<double> full, early;
  early.early_stop = true;
  const PdGains<double> gains{15 * 0.75 / 31.0, 25 / 31.0};
  const RunnerResult a = runPositioning(p, full, gains, 53);
  const RunnerResult b = runPositioning(p, early, gains, 53);
  EXPECT_EQ(a.feasible, b.feasible);
  EXPECT_LT(b.steps, a.steps);
  EXPECT_FALSE(b.ok[0] && b.ok[1] && b.ok[2] && b.ok[3]);
}

TEST(Runner, ClampOptionBoundsCommands) {
  const auto p = aurora_sim::referenceArdrone2Params();
  RunnerConfig<double> cfg;
  cfg.clamp_commands = true;
  double max_abs = 0.0;
  runPositioning(p, cfg, PdGains<double>{0.75, 1.0}, 10,
                 [&](const FlightObservation& o) {
                   for (int i = 0; i < 4; ++i) max_abs = std::max(max_abs, std::fabs(o.step.U[i]));
                 });
  EXPECT_LE(max_abs, 1.0);
  EXPECT_EQ(max_abs, 1.0);  // these gains saturate at the start
}

TEST(Runner, RejectsNegativeDelay) {
  RunnerConfig<double> cfg;
  EXPECT_THROW(runPositioning(aurora_sim::referenceArdrone2Params(), cfg,
                              PdGains<double>{0.5, 0.85}, -1),
               aurora_common::ConfigError);
}
