// The sweep: grid decoding, backend agreement (scalar vs SIMD batches),
// points files, the sweep program's outputs, and refusal of bad sweep files.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/recent_rate.h"
#include "aurora_sweep/results.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

SweepSpec load(const std::string& path) { return loadSweepFile(path, test::configDir()); }

using test::refusal;
using test::relClose;
using test::runOn;
using test::writeTemp;

const char* kGoodParams =
    "  parameters:\n"
    "    kp: {from: 0.0, to: 0.75, count: 4}\n"
    "    kd: {from: 0.0, to: 1.0, count: 4}\n"
    "    delay: {from: 0, to: 3, count: 4}\n";

}  // namespace

TEST(SweepFile, ThesisGridDecodesToTheThesisValues) {
  const SweepSpec spec = load(test::configDir() + "/sweeps/positioning_delay.yaml");
  EXPECT_EQ(spec.size(), 65536);
  EXPECT_EQ(spec.max_delay, 63);
  EXPECT_TRUE(spec.early_stop);
  EXPECT_FALSE(spec.clamp_commands);
  EXPECT_EQ(spec.criteria.max_iae, 30 * 5.3218);
  EXPECT_EQ(spec.criteria.max_itae, 50 * 7.3256);
  const GridView g = spec.view();
  // order [kp, kd, delay]: kp fastest.
  for (long d : {0L, 3L, 53L}) {
    for (int i : {0, 1, 14, 31}) {
      for (int j : {0, 5, 19, 31}) {
        const Combination c = g.decode(i + 32 * (j + 32 * d));
        EXPECT_EQ(c.v[kParamKp], i * 0.75 / 31) << i;  // bit-identical to the thesis's formula
        EXPECT_EQ(c.v[kParamKd], j / 31.0) << j;
        EXPECT_EQ(c.delay(), d);
      }
    }
  }
}

TEST(SweepFile, OrderChangesTheIndexing) {
  const std::string path = writeTemp("order.yaml", std::string("sweep:\n") + kGoodParams +
                                                       "  order: [delay, kp, kd]\n");
  const SweepSpec spec = load(path);  // the view points into the spec
  const GridView g = spec.view();
  EXPECT_EQ(g.decode(1).delay(), 1);
  EXPECT_EQ(g.decode(1).v[kParamKp], 0.0);
  EXPECT_EQ(g.decode(4).v[kParamKp], 0.25);
}

TEST(Backends, ScalarAndCpuAgreeInDouble) {
  const SweepSpec spec = load(test::dataDir() + "/small_grid.yaml");
  ASSERT_EQ(spec.size(), 80);
  const auto scalar = runOn("scalar", spec);
  const auto cpu = runOn("cpu", spec);
  int compared = 0, feasible = 0, infeasible = 0;
  for (long i = 0; i < spec.size(); ++i) {
    EXPECT_EQ(scalar[i].ok, cpu[i].ok) << "combination " << i;
    EXPECT_EQ(scalar[i].steps, cpu[i].steps) << "combination " << i;
    feasible += aurora_sweep::feasible(scalar[i]);
    infeasible += !aurora_sweep::feasible(scalar[i]);
    if (scalar[i].ok & 1) {  // check 1 held: the run did not diverge
      ++compared;
      EXPECT_PRED3(relClose, scalar[i].iae, cpu[i].iae, 1e-9) << i;
      EXPECT_PRED3(relClose, scalar[i].itae, cpu[i].itae, 1e-9) << i;
      EXPECT_PRED3(relClose, scalar[i].iasc, cpu[i].iasc, 1e-9) << i;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(scalar[i].final_pos[k], cpu[i].final_pos[k], 1e-6) << i;
      }
    }
  }
  // The grid must exercise both outcomes and the metric comparison.
  EXPECT_GT(compared, 20);
  EXPECT_GT(feasible, 5);
  EXPECT_GT(infeasible, 5);
}

TEST(Backends, KernelBodyOnTheHostMatchesTheCpuBackend) {
  // simulateCombination() is what each CUDA thread runs; here it runs on the CPU.
  const SweepSpec spec = load(test::dataDir() + "/small_grid.yaml");
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  const GridView grid = spec.view();
  const auto cpu = runOn("cpu", spec);
  for (long i = 0; i < spec.size(); ++i) {
    const SimResult r = simulateCombination<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>, double, 64>(setup, grid, i);
    EXPECT_EQ(r.ok, cpu[i].ok) << i;
    EXPECT_EQ(r.steps, cpu[i].steps) << i;
    if (r.ok & 1) {
      EXPECT_PRED3(relClose, r.iae, cpu[i].iae, 1e-9) << i;
      EXPECT_PRED3(relClose, r.itae, cpu[i].itae, 1e-9) << i;
    }
  }
}

TEST(Backends, EarlyStopKeepsTheFeasibleSetAndSavesSteps) {
  SweepSpec spec = load(test::dataDir() + "/small_grid.yaml");
  const auto full = runOn("cpu", spec);
  spec.early_stop = true;
  const auto early = runOn("cpu", spec);
  long steps_full = 0, steps_early = 0;
  for (long i = 0; i < spec.size(); ++i) {
    EXPECT_EQ(feasible(full[i]), feasible(early[i])) << i;
    steps_full += full[i].steps;
    steps_early += early[i].steps;
  }
  EXPECT_LT(steps_early, steps_full);
}

TEST(Backends, FloatFeasibilityTracksDouble) {
  SweepSpec spec = load(test::dataDir() + "/small_grid.yaml");
  const auto d = runOn("cpu", spec);
  spec.precision = Precision::kFloat;
  const auto f_cpu = runOn("cpu", spec);
  const auto f_scalar = runOn("scalar", spec);
  int agree = 0;
  for (long i = 0; i < spec.size(); ++i) {
    agree += feasible(d[i]) == feasible(f_cpu[i]);
    EXPECT_EQ(feasible(f_cpu[i]), feasible(f_scalar[i])) << i;
  }
  EXPECT_GE(agree, 0.95 * spec.size());
}

TEST(Backends, PointsFileReproducesTheSpecSelfCheckRows) {
  const SweepSpec spec = load(test::dataDir() + "/points.yaml");
  ASSERT_EQ(spec.size(), 3);
  struct Row {
    unsigned char ok;
    double iae, itae, iasc, x;
  } rows[] = {{0x1f, 9.696094275, 44.87231536, 2.489013563, 2.000003154},
              {0x0b, 79.66617453, 1877.785809, 0.607348822, 1.666709805},
              {0x00, 399.2117079, 13313.32912, 56.0389837, -5.025406388}};
  for (const std::string backend : {"scalar", "cpu"}) {
    const auto r = runOn(backend, spec);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(r[i].ok, rows[i].ok) << backend << " row " << i;
      EXPECT_EQ(r[i].steps, 1801);
      EXPECT_NEAR(r[i].iae, rows[i].iae, 1e-8 * rows[i].iae) << backend << " row " << i;
      EXPECT_NEAR(r[i].itae, rows[i].itae, 1e-8 * rows[i].itae) << backend << " row " << i;
      EXPECT_NEAR(r[i].iasc, rows[i].iasc, 1e-8 * rows[i].iasc) << backend << " row " << i;
      EXPECT_NEAR(r[i].final_pos[0], rows[i].x, 1e-6) << backend << " row " << i;
    }
  }
}

TEST(SweepFileRefusal, UnknownKey) {
  const std::string msg = refusal(std::string("sweep:\n") + kGoodParams + "  early_stopp: true\n");
  EXPECT_NE(msg.find("'sweep.early_stopp' is not a known key"), std::string::npos) << msg;
  EXPECT_NE(msg.find("early_stop"), std::string::npos) << msg;
}

TEST(SweepFileRefusal, EmptyRange) {
  std::string msg = refusal(
      "sweep:\n  parameters:\n    kp: {from: 0.5, to: 0.1, count: 4}\n    kd: 0.5\n    delay: 0\n");
  EXPECT_NE(msg.find("'sweep.parameters.kp' is an empty range"), std::string::npos) << msg;
  msg = refusal("sweep:\n  parameters:\n    kp: {values: []}\n    kd: 0.5\n    delay: 0\n");
  EXPECT_NE(msg.find("'sweep.parameters.kp.values' is empty"), std::string::npos) << msg;
}

TEST(SweepFileRefusal, UnknownController) {
  const std::string msg =
      refusal(std::string("sweep:\n  controller: lqr\n") + kGoodParams);
  EXPECT_NE(msg.find("'sweep.controller' = 'lqr' is not a known controller: accepted 'pd_saturated', 'underactuated'"),
            std::string::npos)
      << msg;
}

TEST(SweepFileRefusal, UnknownParameter) {
  const std::string msg = refusal(std::string("sweep:\n") + kGoodParams + "    mass: 0.5\n");
  EXPECT_NE(msg.find("'sweep.parameters.mass' is not a parameter of the pd_saturated controller: accepted kp, kd, "
                     "delay, m, Ixx, Iyy, Izz, Cf, Ct, Km, Jm"),
            std::string::npos)
      << msg;
}

TEST(SweepFileRefusal, CountBelowOne) {
  const std::string msg = refusal(
      "sweep:\n  parameters:\n    kp: {from: 0, to: 1, count: 0}\n    kd: 0.5\n    delay: 0\n");
  EXPECT_NE(msg.find("'sweep.parameters.kp.count' = 0 is below 1: accepted counts >= 1"),
            std::string::npos)
      << msg;
}

TEST(SweepFileRefusal, OtherMistakesAreNamed) {
  EXPECT_NE(refusal("sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.5\n").find("'sweep.parameters.delay' is missing"),
            std::string::npos);
  EXPECT_NE(refusal("sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.5\n    delay: 2.5\n").find("accepted integer samples in [0, 2047]"),
            std::string::npos);
  EXPECT_NE(refusal(std::string("sweep:\n") + kGoodParams + "  precision: half\n").find("'double' or 'float'"),
            std::string::npos);
  EXPECT_NE(refusal(std::string("sweep:\n") + kGoodParams + "  order: [kp, kd]\n").find("must list every varied parameter"),
            std::string::npos);
  EXPECT_NE(refusal(std::string("sweep:\n") + kGoodParams + "  points: x.csv\n").find("with points, parameters only fix values"),
            std::string::npos);
  EXPECT_NE(refusal("sweep:\n  points: missing.csv\n").find("cannot be read"), std::string::npos);
  EXPECT_NE(refusal(std::string("sweep:\n  vehicle: nowhere.yaml\n") + kGoodParams).find("nowhere.yaml"),
            std::string::npos);
  EXPECT_NE(refusal("not_sweep: 1\n").find("'not_sweep' is not a known key"), std::string::npos);
  // Issue 31: a missing link file did not name its key; a key given twice was read as its first value.
  const std::string missing_link = refusal(std::string("sweep:\n  link: links/nowhere.yaml\n") + kGoodParams);
  EXPECT_NE(missing_link.find("'sweep.link' names a link file that is refused: link file"), std::string::npos)
      << missing_link;
  const std::string late = refusal(std::string("sweep:\n") + kGoodParams + "    uplink_jitter: 1900\n");
  EXPECT_NE(late.find("'sweep.parameters' gives packets that would never arrive: the latest (the largest delay plus "
                      "the jitter, or the command path) is 1903 samples is not shorter than the run's"),
            std::string::npos) << late;
  const std::string twice = refusal(std::string("sweep:\n  precision: float\n  precision: double\n") + kGoodParams);
  EXPECT_NE(twice.find("'sweep.precision' is given twice, on lines 2 and 3"), std::string::npos) << twice;
}

#ifdef AURORA_SWEEP_BIN
namespace {
int runSweep(const std::string& args, std::string& output) {
  FILE* p = popen((std::string(AURORA_SWEEP_BIN) + " " + args + " 2>&1").c_str(), "r");
  char buf[512];
  output.clear();
  while (fgets(buf, sizeof buf, p)) output += buf;
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST(SweepProgram, WritesResultsSummaryAndPlots) {
  const std::string out = ::testing::TempDir() + "/sweep_program_out";
  std::string log;
  const int rc = runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + out +
                              " --backend cpu --threads 2 --quiet --overwrite",
                          log);
  ASSERT_EQ(rc, 0) << log;
  std::ifstream csv(out + "/results.csv");
  std::string line;
  int rows = -1;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 80);
  std::ifstream summary(out + "/summary.json");
  std::stringstream ss;
  ss << summary.rdbuf();
  EXPECT_NE(ss.str().find("\"combinations\": 80"), std::string::npos) << ss.str();
  EXPECT_NE(ss.str().find("\"backend\": \"cpu\""), std::string::npos);
  EXPECT_NE(ss.str().find("\"simulations_per_s\""), std::string::npos);
  EXPECT_TRUE(std::ifstream(out + "/feasible_volume.png").good());
  EXPECT_TRUE(std::ifstream(out + "/check1_region.png").good());  // early_stop false
  // Readable in many dimensions: marginals, pairs, and for a 3-parameter
  // grid the max tolerable delay and the count of non-monotone gain pairs.
  EXPECT_TRUE(std::ifstream(out + "/feasible_marginals.png").good());
  EXPECT_TRUE(std::ifstream(out + "/feasible_pairs.png").good());
  EXPECT_TRUE(std::ifstream(out + "/max_tolerable_delay.png").good());
  EXPECT_NE(ss.str().find("\"delay_monotony\""), std::string::npos) << ss.str();
  EXPECT_NE(ss.str().find("\"gain_pairs\": 16"), std::string::npos) << ss.str();
}

// With repeats: one results row per run (its repeat), feasible_share.csv
// one row per combination whose feasible runs are those rows' count, the
// summary's tally of them; the figure drawn.
TEST(SweepProgram, RepeatsReportTheFeasibleShare) {
  const std::string file = writeTemp("repeats.yaml",
      "sweep:\n  name: repeats\n  repeats: 5\n  early_stop: false\n  parameters:\n    kp: 0.5\n    kd: 0.85\n"
      "    delay: {values: [6, 9, 12]}\n    uplink_jitter: {values: [0, 6]}\n    uplink_loss: 0.3\n");
  const std::string out = ::testing::TempDir() + "/sweep_repeats";
  std::string log;
  ASSERT_EQ(runSweep("--config " + file + " --out " + out + " --backend cpu --overwrite", log), 0) << log;
  // Issue 51 (10): runs are counted as runs in the plan and result lines too.
  EXPECT_NE(log.find("sweep: plan: 30 runs in 1 chunk: "), std::string::npos) << log;
  EXPECT_NE(log.find("sweep: 30 runs, "), std::string::npos) << log;
  std::ifstream results(out + "/results.csv");
  std::string line;
  std::getline(results, line);
  EXPECT_EQ(line.rfind("index,kp,kd,delay,uplink_jitter,uplink_loss,uplink_burst,downlink_delay,downlink_jitter,"
                       "downlink_loss,downlink_burst,repeat,ok1", 0), 0u) << line;
  std::vector<int> runs(6, 0);
  long rows = 0;
  while (std::getline(results, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    EXPECT_EQ(std::stol(f[11]), rows % 5) << line;  // the repeat varies fastest
    // Issue 51 (6): the shortest text that reads back (pd.read_csv(...)[kd == 0.85] selects the row).
    EXPECT_EQ(f[2], "0.85") << line;
    EXPECT_EQ(f[5], "0.3") << line;
    runs[static_cast<size_t>(rows / 5)] += std::stoi(f[16]);  // feasible
    ++rows;
  }
  EXPECT_EQ(rows, 30);
  std::ifstream shares(out + "/feasible_share.csv");
  std::getline(shares, line);
  EXPECT_EQ(line, "combination,kp,kd,delay,uplink_jitter,uplink_loss,uplink_burst,downlink_delay,downlink_jitter,"
                  "downlink_loss,downlink_burst,repeats,feasible_runs,feasible_share");
  std::vector<long> by_runs(6, 0);
  int mixed = 0;
  for (size_t k = 0; std::getline(shares, line); ++k) {
    const size_t last = line.rfind(','), before = line.rfind(',', last - 1);
    EXPECT_NE(line.find(",0.5,0.85,"), std::string::npos) << line;
    const std::string share = line.substr(last + 1);
    EXPECT_TRUE(share == "0" || share == "0.2" || share == "0.4" || share == "0.6" || share == "0.8" || share == "1") << line;
    EXPECT_EQ(std::stoi(line.substr(before + 1, last - before - 1)), runs[k]) << line;
    ++by_runs[static_cast<size_t>(runs[k])];
    mixed += runs[k] > 0 && runs[k] < 5;
  }
  const nlohmann::json summary = nlohmann::json::parse(test::readText(out + "/summary.json"));
  EXPECT_EQ(summary["feasible_share"]["combinations_by_feasible_runs"].get<std::vector<long>>(), by_runs);
  EXPECT_EQ(summary["feasible_share"]["combinations"], 6);
  EXPECT_EQ(summary["repeats"], 5);
  EXPECT_EQ(summary["combinations"], 30);
  EXPECT_GT(by_runs[0], 0);  // some combinations never fly ...
  EXPECT_GT(by_runs[5] + mixed, 0);  // ... some do
  struct stat st;
  EXPECT_EQ(stat((out + "/feasible_share.png").c_str(), &st), 0) << log;
}

TEST(DelayMonotony, CountsPairsThatComeBackAtALongerDelay) {
  const SweepSpec spec = load(test::dataDir() + "/small_grid.yaml");  // 4 kp x 4 kd x 5 delays, kp fastest
  DelayMonotony m(spec);
  ASSERT_TRUE(m.applies());
  std::vector<SimResult> r(static_cast<size_t>(spec.size()));
  for (SimResult& x : r) x.ok = 0x1f;  // all feasible: monotone
  const GridView g = spec.view();
  for (long i = 0; i < spec.size(); ++i) {
    const Combination c = g.decode(i);
    if (c.v[kParamKp] == 0.0 && c.v[kParamKd] == 0.0 && c.delay() == 3) r[i].ok = 0;  // fails at 3, holds at 20: not monotone
    if (c.v[kParamKp] == 0.75 && c.v[kParamKd] == 1.0 && c.delay() >= 20) r[i].ok = 0;  // fails from 20 on: monotone
  }
  m.add(0, std::vector<SimResult>(r.begin(), r.begin() + 37));  // in two pieces, as chunks come
  m.add(37, std::vector<SimResult>(r.begin() + 37, r.end()));
  EXPECT_EQ(m.pairs(), 16);
  EXPECT_EQ(m.nonMonotonePairs(), 1);
}

TEST(SweepProgram, RefusesUnwritableOutputAndMissingDevice) {
  std::string log;
  EXPECT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out /proc/aurora_sweep_out", log), 2);
  EXPECT_NE(log.find("'/proc/aurora_sweep_out' is not writable"), std::string::npos) << log;
  EXPECT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out x --backend gpu", log), 2);
  EXPECT_NE(log.find("accepted scalar, cpu, cuda, auto"), std::string::npos) << log;
  EXPECT_EQ(runSweep("--config " + test::dataDir() + "/nope.yaml --out x", log), 2);
  EXPECT_NE(log.find("cannot be read"), std::string::npos) << log;
}
#endif

// sweep.task is the node's task schema: a task file or the same keys inline.
TEST(SweepFileTask, OneSchemaWithTheNode) {
  const SweepSpec byFile = load(test::configDir() + "/sweeps/positioning_delay.yaml");  // task: tasks/positioning.yaml
  EXPECT_EQ(byFile.task.waypoints.position[0][0], 2.0);
  EXPECT_EQ(byFile.duration(), 60.0);
  const std::string inline_task =
      "sweep:\n  task: {waypoints: [[1.5, -1, 1]], end_times: [30], duration: 30}\n" + std::string(kGoodParams);
  const SweepSpec in = load(writeTemp("inline_task.yaml", inline_task));
  EXPECT_EQ(in.task.waypoints.position[0][0], 1.5);
  EXPECT_EQ(in.task.waypoints.position[0][1], -1.0);
  EXPECT_EQ(in.duration(), 30.0);
  // Every task of the node's schema: trajectories and waypoint missions.
  const SweepSpec circle = load(writeTemp("circle.yaml", "sweep:\n  task: tasks/circle.yaml\n" + std::string(kGoodParams)));
  EXPECT_TRUE(circle.task.isTrajectory());
  const SweepSpec mission = load(writeTemp("mission.yaml", "sweep:\n  task: tasks/mission4.yaml\n" + std::string(kGoodParams)));
  EXPECT_EQ(mission.task.waypoints.count, 4);
  // Task keys are checked by the node's loader, naming them under sweep.task.
  EXPECT_NE(refusal("sweep:\n  task: {desired: [2, 1, 2], duration: 60}\n" + std::string(kGoodParams))
                .find("'sweep.task.desired' is not a known key: accepted name, type, duration, waypoints, end_times"),
            std::string::npos);
}

// The delay limit is the node's and replay's (limits.h), not a sweep's own.
TEST(SweepFileRefusal, DelayLimitIsTheNodes) {
  const std::string msg = refusal("sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.5\n    delay: 3000\n");
  EXPECT_NE(msg.find("[0, " + std::to_string(aurora_control::kMaxDelaySamples) + "]"), std::string::npos) << msg;
  EXPECT_EQ(aurora_control::kMaxDelaySamples, 2047);
  // The default task is 60 s (1801 iterations): a delay of 1801 would never
  // take force and is refused naming the key; 1800 is the longest accepted.
  EXPECT_EQ(refusal("sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.5\n    delay: 1800\n"), "");
  const std::string beyond = refusal("sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.5\n    delay: 2000\n");
  EXPECT_NE(beyond.find("'sweep.parameters.delay' = 2000 samples is not shorter than the "
                        "run's 1801 steps"), std::string::npos) << beyond;
  EXPECT_NE(beyond.find("accepted delays up to 1800 samples"), std::string::npos) << beyond;
  EXPECT_EQ(refusal("sweep:\n  task: {waypoints: [[1, 1, 1]], end_times: [60], duration: 100}\n"
                    "  parameters:\n    kp: 0.5\n    kd: 0.5\n    delay: 2047\n"), "");
}

// With early stop a run ends at its first failed check: the checks it had
// not failed by then are "not reached", not "passed".
TEST(SweepCounts, EarlyStopChecksAreNotReached) {
  const std::string yaml =
      "sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.85\n    delay: {values: [0, 53]}\n  early_stop: true\n";
  const SweepSpec spec = load(writeTemp("early_counts.yaml", yaml));
  const std::vector<SimResult> results = runOn("scalar", spec);
  const Counts c = countResults(results, aurora_control::studyIterationCount(spec.duration(), spec.paramsOf(aurora_sim::Ardrone2()).Ts));
  ASSERT_EQ(c.combinations, 2);
  EXPECT_EQ(c.feasible, 1);  // delay 0 flies; delay 53 fails early
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(c.passed[i] + c.failed[i] + c.not_reached[i], 2) << "check " << i + 1;
    EXPECT_EQ(c.passed[i], 1) << "check " << i + 1 << ": only the complete run passes";
  }
  long failed = 0, not_reached = 0;
  for (int i = 0; i < 4; ++i) failed += c.failed[i], not_reached += c.not_reached[i];
  EXPECT_GE(failed, 1);
  EXPECT_GE(not_reached, 1);  // the stopped run's other checks
  EXPECT_EQ(failed + not_reached, 4);
}

#ifdef AURORA_SWEEP_BIN
// Refusals that used to come after work or leave traces: no CUDA device
// leaves no output folder; --rviz without a master is refused before any
// simulation.
TEST(SweepProgram, RefusalsLeaveNothingBehind) {
  std::string log;
  const std::string out = ::testing::TempDir() + "/sweep_no_device_out";
  std::remove(out.c_str());
  const int rc = runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + out + " --backend cuda", log);
  if (rc == 3) {  // no usable device here (CI); with one, the run is legitimate
    struct stat st;
    EXPECT_NE(stat(out.c_str(), &st), 0) << "output folder created although nothing ran: " << log;
  }
  const std::string out2 = ::testing::TempDir() + "/sweep_no_master_out";
  EXPECT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + out2 +
                         " --rviz __master:=http://localhost:1 --no-plots",
                     log), 7);
  EXPECT_NE(log.find("no ROS master"), std::string::npos) << log;
  EXPECT_EQ(log.find("combinations, backend"), std::string::npos) << "work started before the check: " << log;
  struct stat st;
  EXPECT_NE(stat((out2 + "/results.csv").c_str(), &st), 0);
}

// --config takes a shipped NAME as flight does (config/sweeps/NAME.yaml of
// the config folder, README's `sweep --config link_margin`), or a path; a
// NAME no file has is refused naming the file it looked for.
TEST(SweepProgram, AShippedSweepIsTakenByItsName) {
  const std::string config = ::testing::TempDir() + "/sweep_named_config";
  std::string log;
  ASSERT_EQ(std::system(("rm -rf '" + config + "' && mkdir -p '" + config + "/sweeps' && cp '" + test::dataDir() +
                         "/small_grid.yaml' '" + config + "/sweeps/' && ln -s '" + test::configDir() + "/vehicles' '" +
                         config + "/vehicles'").c_str()), 0);
  const std::string out = ::testing::TempDir() + "/sweep_named_out";
  ASSERT_EQ(runSweep("--config small_grid --config-dir " + config + " --out " + out +
                         " --backend scalar --no-plots --quiet --overwrite",
                     log), 0)
      << log;
  std::stringstream summary;
  summary << std::ifstream(out + "/summary.json").rdbuf();
  EXPECT_NE(summary.str().find("\"combinations\": 80"), std::string::npos) << summary.str();
  EXPECT_EQ(runSweep("--config nowhere --config-dir " + config + " --out " + out + "_no --no-plots", log), 2);
  EXPECT_NE(log.find("'" + config + "/sweeps/nowhere.yaml' cannot be read"), std::string::npos) << log;
}

// The plots start without a shell: an output folder whose name holds
// quotes and $(...) is taken as it is (the shell used to run the $(...)).
TEST(SweepProgram, AnOutputFolderNameIsNotShellCode) {
  const std::string marker = ::testing::TempDir() + "/aurora_injected";
  std::remove(marker.c_str());
  const std::string out = ::testing::TempDir() + "/sweep \"odd\" $(touch " + marker + ")";
  std::string log;
  ASSERT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out '" + out + "' --backend scalar --overwrite",
                     log),
            0)
      << log;
  EXPECT_TRUE(std::ifstream(out + "/feasible_volume.png").good()) << log;
  EXPECT_FALSE(std::ifstream(marker).good()) << "the folder name ran as a command";
}

// The cuda backend's limits are checked before anything is written, with
// or without a device: delays beyond its history, blocks beyond CUDA's.
TEST(SweepProgram, CudaLimitsAreCheckedBeforeTheRun) {
  const std::string long_delay = writeTemp("cuda_long_delay.yaml", "sweep:\n  parameters:\n    kp: 0.5\n"
                                           "    kd: 0.85\n    delay: {values: [0, 600]}\n");
  const std::string out = ::testing::TempDir() + "/sweep_cuda_limits_out";
  std::string log;
  EXPECT_EQ(runSweep("--config " + long_delay + " --out " + out + " --backend cuda", log), 2) << log;
  EXPECT_TRUE(log.find("the cuda backend holds delays (with a link's jitter) up to 511 samples") != std::string::npos ||
              log.find("this build has no CUDA backend") != std::string::npos) << log;
  struct stat st;
  EXPECT_NE(stat(out.c_str(), &st), 0) << "output folder created for a refused sweep: " << log;
  EXPECT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + out + " --backend cuda --block-size 2048",
                     log),
            2);
  EXPECT_NE(log.find("--block-size 2048 is invalid: CUDA blocks hold at most 1024 threads"), std::string::npos) << log;
}

// A sweep over a link runs on the cuda backend (a kernel of its own) when a
// device works; the history it needs counts the link's jitter, checked
// before anything is written and without a device.
TEST(SweepProgram, ALinkSweepOnTheCudaBackendCountsTheJitter) {
  const std::string base = test::readText(test::dataDir() + "/small_grid.yaml");
  const std::string lossy = writeTemp("cuda_link.yaml", base + "  link: links/wifi_lab.yaml\n");
  std::string log;
  const int rc = runSweep("--config " + lossy + " --out " + ::testing::TempDir() + "/sweep_cuda_link --backend cuda", log);
  EXPECT_TRUE(rc == 0 || (rc == 3 && log.find("no usable CUDA device") != std::string::npos) ||
              (rc == 3 && log.find("this build has no CUDA backend") != std::string::npos))
      << rc << " " << log;
  EXPECT_EQ(log.find("ideal links only"), std::string::npos) << log;
  std::string wide = base;
  const std::string delays = "delay: {values: [0, 3, 20, 40, 63]}";
  wide.replace(wide.find(delays), delays.size(), "delay: {values: [0, 400]}\n    uplink_jitter: 200");
  const std::string out = ::testing::TempDir() + "/sweep_cuda_wide";
  EXPECT_EQ(runSweep("--config " + writeTemp("cuda_wide.yaml", wide) + " --out " + out + " --backend cuda", log), 2) << log;
  const bool no_cuda_build = log.find("this build has no CUDA backend") != std::string::npos;
  EXPECT_TRUE(no_cuda_build || (log.find("holds delays (with a link's jitter) up to 511 samples") != std::string::npos &&
                                 log.find("this sweep reaches 600") != std::string::npos))
      << log;
}

// A sweep says up front what it costs (combinations, time at a measured
// rate, bytes) and refuses one the disk cannot hold, before anything is
// written (a 10^13 grid used to run silently until killed).
TEST(SweepProgram, SaysTheCostUpFrontAndRefusesWhatCannotFit) {
  const std::string huge = writeTemp("huge_grid.yaml", "sweep:\n  name: huge\n  parameters:\n"
                                     "    kp: {from: 0.1, to: 10, count: 100000}\n"
                                     "    kd: {from: 0.1, to: 10, count: 100000}\n"
                                     "    delay: {from: 0, to: 999, count: 1000}\n");
  const std::string out = ::testing::TempDir() + "/sweep_huge_out";
  std::string log;
  EXPECT_EQ(runSweep("--config " + huge + " --out " + out + " --backend scalar", log), 2) << log;
  EXPECT_NE(log.find("refused: "), std::string::npos) << log;
  EXPECT_NE(log.find("cannot hold this sweep (10,000,000,000,000 combinations in "), std::string::npos) << log;
  EXPECT_NE(log.find("writes about "), std::string::npos) << log;
  EXPECT_NE(log.find("--ignore-free-space"), std::string::npos) << log;
  struct stat st;
  EXPECT_NE(stat(out.c_str(), &st), 0) << "output folder created for a refused sweep: " << log;
  // A sweep that fits: the plan, then the run; counts in the singular too.
  const std::string small = ::testing::TempDir() + "/sweep_plan_out";
  ASSERT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + small + " --backend scalar --no-plots "
                     "--chunk-size 100 --overwrite", log), 0) << log;
  EXPECT_NE(log.find("sweep: plan: 80 combinations in 1 chunk: "), std::string::npos) << log;
  EXPECT_NE(log.find("sims/s (measured on the first "), std::string::npos) << log;
  EXPECT_EQ(log.find("1 chunks"), std::string::npos) << log;
  // Issue 51 (10): --output none writes no results, and counts none against the free space.
  ASSERT_EQ(runSweep("--config " + test::dataDir() + "/small_grid.yaml --out " + small + " --backend scalar --no-plots "
                     "--output none --overwrite", log), 0) << log;
  EXPECT_NE(log.find(", results 0 B); "), std::string::npos) << log;
}
#endif

// A fixed parameter may stand in `order` (it does not vary).
TEST(SweepFile, FixedValueInOrderIsAccepted) {
  const SweepSpec spec = load(writeTemp("fixed_order.yaml",
      "sweep:\n  parameters:\n    kp: {from: 0.1, to: 0.5, count: 3}\n    kd: {from: 0.2, to: 0.8, count: 2}\n"
      "    delay: 600\n  order: [kp, kd, delay]\n"));
  EXPECT_EQ(spec.size(), 6);
  EXPECT_EQ(spec.max_delay, 600);
}

TEST(RecentRate, FollowsTheRecentThroughput) {
  RecentRate r(10.0);
  double rate = 0;
  for (int t = 1; t <= 30; ++t) rate = r.add(t, 100L * t);  // 100 per s
  EXPECT_DOUBLE_EQ(rate, 100.0);
  long done = 3000;
  for (int t = 31; t <= 60; ++t) rate = r.add(t, done += 200);  // twice as fast later
  EXPECT_DOUBLE_EQ(rate, 200.0);  // the whole-run average would say 150
}

// One boolean rule for every file: a quoted "false" is a string, refused
// (the sweep used to read it as false), as is anything not a boolean.
TEST(SweepFileRefusal, BooleansMustBeUnquotedTrueOrFalse) {
  std::string msg = refusal(std::string("sweep:\n") + kGoodParams + "  clamp_commands: \"false\"\n");
  EXPECT_NE(msg.find("'sweep.clamp_commands' = 'false' is not a boolean: accepted true or false, unquoted"),
            std::string::npos) << msg;
  msg = refusal(std::string("sweep:\n") + kGoodParams + "  early_stop: yes please\n");
  EXPECT_NE(msg.find("'sweep.early_stop' = 'yes please' is not a boolean"), std::string::npos) << msg;
  EXPECT_EQ(refusal(std::string("sweep:\n") + kGoodParams + "  clamp_commands: false\n"), "");
}

// Points files as Excel and pandas write them: a UTF-8 byte order mark,
// quoted values, CRLF line ends; a quote left open is refused.
TEST(SweepFile, PointsFilesWithAByteOrderMarkAndQuotedValues) {
  const std::string csv = writeTemp("excel_points.csv", "\xEF\xBB\xBFkp,\"kd\",delay\r\n\"0.5\", 0.85 ,\"3\"\r\n\r\n0.4,0.7,0\r\n");
  const SweepSpec spec = load(writeTemp("excel_points.yaml", "sweep:\n  points: " + csv + "\n"));
  ASSERT_EQ(spec.points.size(), 6u);
  EXPECT_EQ(spec.points[0], 0.5);
  EXPECT_EQ(spec.points[1], 0.85);
  EXPECT_EQ(spec.points[2], 3.0);
  EXPECT_EQ(spec.points[5], 0.0);
  const std::string open = writeTemp("open_quote.csv", "kp,kd,delay\n\"0.5,0.85,3\n");
  const std::string msg = refusal("sweep:\n  points: " + open + "\n");
  EXPECT_NE(msg.find("is not valid CSV"), std::string::npos) << msg;
  const std::string short_row = writeTemp("short_row.csv", "kp,kd,delay\n0.5,0.85\n");
  EXPECT_NE(refusal("sweep:\n  points: " + short_row + "\n").find("row 2' has 2 columns: the header has 3"),
            std::string::npos);
}
