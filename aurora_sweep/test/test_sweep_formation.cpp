// Formation sweeps (docs/formation.md, "Formation sweeps"): a combination
// is the flight tool's formation run with the combination's delays, gains
// and link values; every CPU backend and the CUDA kernel's per-thread entry
// agree with the scalar loop; mistakes are refused naming the key; the
// shipped study spans its margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/line/line_yaml.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/kernel_entry.h"
#include "aurora_sweep/results.h"
#include "aurora_sweep/result_columns.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;
using namespace aurora_sweep::test;
using aurora_control::LawType;

namespace {

using Line = aurora_control::LineFormation<double>;

SweepSpec formationSweep(const std::string& name, const std::string& body) {
  return loadSweepFile(writeTemp(name + ".yaml", "sweep:\n  name: " + name + "\n" + body), configDir());
}

// delay_1 x delay_2 around the margin, with formation gains varied.
const char* kGrid =
    "  early_stop: false\n"
    "  parameters:\n"
    "    delay_1: {values: [0, 9, 18, 21]}\n"
    "    delay_2: {values: [0, 12, 24]}\n"
    "    formation_k1_rho: {values: [0.75, 1.5]}\n";

// The flight tool's run of the file with drone delays d1, d2 and the
// formation's K1 of rho, judged as a sweep judges it: its record.
SimResult flightToolRecord(const std::string& file, long d1, long d2, double k1_rho, long ticks) {
  const auto vehicle = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(configDir() + "/vehicles/ardrone2.yaml");
  auto run = aurora_control::formationRun(aurora_control::readFormationFile(file, configDir()), vehicle);
  run.drone[0].delay = d1, run.drone[1].delay = d2;
  run.gains.k1[3] = k1_rho;
  aurora_control::LineJudge judge{aurora_control::FormationCriteria<double>::study(), false,
                                               vehicle.Ts, {}, {}};
  judge.metrics.reset();
  double end = 0;
  auto observe = [&](const aurora_control::LineObservation& o) {
    double X[6];
    for (int d = 0; d < 2; ++d) {
      for (int i = 0; i < 3; ++i) X[3 * d + i] = o.drones[d].model.X[i];
    }
    end = aurora_control::closestPair<Line>(X);
    judge(o);
  };
  const long ran = aurora_control::runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(run, ticks, observe);
  return formationResult(judge.metrics, ran, end);
}

}  // namespace

// Each combination is the flight tool's run (formation_runner.h with the
// judge), bit for bit, in the grid's order (delay_1 fastest).
TEST(FormationSweep, ACombinationIsTheFlightToolsRun) {
  const SweepSpec spec = formationSweep("formation_grid", "  formation: formations/line_lemniscate_ik.yaml\n" + std::string(kGrid));
  ASSERT_EQ(spec.size(), 24);
  EXPECT_EQ(spec.iterations(), 2700);
  const std::vector<SimResult> scalar = runOn("scalar", spec);
  const long d1[4] = {0, 9, 18, 21}, d2[3] = {0, 12, 24};
  const double k[2] = {0.75, 1.5};
  int feasible_runs = 0;
  for (long i = 0; i < spec.size(); ++i) {
    const SimResult want = flightToolRecord(configDir() + "/formations/line_lemniscate_ik.yaml", d1[i % 4],
                                            d2[i / 4 % 3], k[i / 12], spec.iterations());
    EXPECT_EQ(std::memcmp(&want, &scalar[i], sizeof want), 0) << "combination " << i;
    feasible_runs += feasible(scalar[i]);
  }
  // The grid spans the margin: some fly, some do not.
  EXPECT_GT(feasible_runs, 0);
  EXPECT_LT(feasible_runs, 24);
}

// Threads = scalar bit for bit; every SIMD build agrees (flags and ticks
// equal, metrics close), ideal and over lossy links with repeats, both laws.
// Delays up to 15 samples: beyond, the flights swing so hard that the last
// bits of xsimd's sin against libm's grow into other outcomes.
TEST(FormationSweep, EveryCpuBackendAgreesWithTheScalarLoop) {
  const std::string ideal =
      "  early_stop: false\n  parameters:\n    delay_1: {values: [0, 9, 15]}\n    delay_2: {values: [0, 15]}\n"
      "    formation_k1_rho: {values: [0.75, 1.5]}\n";
  const std::string lossy =
      "  repeats: 3\n  parameters:\n    delay_1: {values: [0, 12]}\n    delay_2: {values: [0, 15]}\n"
      "    uplink_jitter: 2\n    uplink_loss: 0.1\n    downlink_loss: 0.05\n";
  for (const char* file : {"line_lemniscate", "line_lemniscate_ik"}) {
    for (const std::string& body : {ideal, lossy}) {
      SweepSpec spec = formationSweep(std::string("agree_") + file, std::string("  formation: formations/") + file + ".yaml\n" + body);
      EXPECT_EQ(differing(runOn("scalar", spec), runOn("none", spec)), 0) << file;
      for (const CpuIsa& isa : cpuBatchIsas()) {
        if (!isa.supported || isa.key == "none") continue;
        expectAgreement(isa.key, spec, 1e-9, 8);
        spec.precision = Precision::kFloat;
        expectAgreement(isa.key, spec, 2e-3, 8);
        spec.precision = Precision::kDouble;
      }
    }
  }
}

// A lane whose formation ended early (a failed check, early stop) takes the
// next combination at once (formation_lanes.h): on every build each record
// is the one the lane engine gives its combination run alone, bit for bit,
// and the generic build's the scalar loop's; most of the triangle's runs
// stop early at these delays, some fly to the end.
TEST(FormationSweep, ALaneWhoseRunStoppedTakesTheNextCombination) {
  SweepSpec spec = formationSweep("triangle_refill",
                                  "  formation: formations/triangle_ardrones.yaml\n  early_stop: true\n  parameters:\n"
                                  "    delay_1: {from: 0, to: 14, count: 8}\n    delay_2: {values: [0, 6, 15]}\n"
                                  "    delay_3: {values: [0, 15]}\n");
  const std::vector<SimResult> scalar = runOn("scalar", spec);
  int stopped = 0;
  for (const SimResult& r : scalar) stopped += r.steps < spec.iterations();
  EXPECT_GT(stopped, 8);
  EXPECT_LT(stopped, int(scalar.size()) - 4);
  EXPECT_EQ(differing(scalar, runOn("none", spec, 1)), 0);
  for (Precision precision : {Precision::kDouble, Precision::kFloat}) {
    spec.precision = precision;
    for (const CpuIsa& isa : cpuBatchIsas()) {
      if (!isa.supported) continue;
      const std::vector<SimResult> all = runOn(isa.key, spec, 1);
      for (long i = 0; i < spec.size(); ++i) {
        SweepSpec one = spec;
        one.range_begin = i, one.range_end = i + 1;
        const SimResult alone = runOn(isa.key, one, 1).at(0);
        EXPECT_EQ(std::memcmp(&alone, &all[size_t(i)], sizeof alone), 0) << isa.key << " combination " << i;
      }
    }
  }
}

// The CUDA kernel's per-thread entry (formationThread), called for every
// (block, thread) of a launch of a range, is the scalar loop, ideal and
// over links.
TEST(FormationSweep, TheKernelsPerThreadEntryIsTheScalarLoop) {
  const std::string lossy = "  repeats: 2\n  parameters:\n    delay_1: {values: [3, 15]}\n    delay_2: {values: [0, 21]}\n"
                            "    uplink_loss: 0.2\n    downlink_jitter: 2\n";
  for (const std::string& body : {std::string(kGrid), lossy}) {
    SweepSpec spec = formationSweep("kernel_entry", "  formation: formations/line_lemniscate.yaml\n" + body);
    spec.range_begin = 3;
    std::vector<SimResult> scalar;
    Progress progress{0};
    runScalar(spec, scalar, progress);
    const FormationSetup<double, aurora_control::LineFormation, aurora_control::ArdroneLawData> setup = makeFormationSetup<double>(spec, spec.run<aurora_control::LineShapeEntry>());
    const GridView grid = spec.view();
    const long n = spec.rangeSize();
    std::vector<SimResult> out(static_cast<size_t>(n));
    for (unsigned b = 0; b < blocksFor(n, 4); ++b) {
      for (unsigned t = 0; t < 4; ++t) {
        if (setup.ideal_link) {
          formationThread<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, aurora_control::kShortHistory, false>(setup, grid, 3, n, out.data(), b, 4, t);
        } else {
          formationThread<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, aurora_control::kShortHistory, true>(setup, grid, 3, n, out.data(), b, 4, t);
        }
      }
    }
    EXPECT_EQ(differing(scalar, out), 0);
  }
}

// Each drone's own link values (uplink_loss_2, downlink_jitter_1) apply to
// that drone only, after the drones' common ones (uplink_loss); the
// results name them; every CPU backend and the kernel's per-thread entry
// agree with the scalar loop over them.
TEST(FormationSweep, EachDroneFliesItsOwnLinkValues) {
  SweepSpec spec = formationSweep("own_links",
                                  "  formation: formations/line_lemniscate_ik.yaml\n  repeats: 2\n  early_stop: false\n"
                                  "  parameters:\n    delay_1: 3\n    delay_2: {values: [0, 9]}\n    uplink_loss: 0.05\n"
                                  "    uplink_loss_2: {values: [0.0, 0.3]}\n    downlink_jitter_1: 2\n"
                                  "  order: [delay_2, uplink_loss_2]\n");
  ASSERT_EQ(spec.size(), 8);
  std::vector<std::string> names;
  for (int id : spec.columns()) names.push_back(spec.paramNameOf(id));
  for (const char* want : {"delay_1", "delay_2", "uplink_loss", "uplink_loss_2", "downlink_jitter_1"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
  EXPECT_EQ(std::find(names.begin(), names.end(), "uplink_loss_1"), names.end());
  const FormationSetup<double, aurora_control::LineFormation, aurora_control::ArdroneLawData> setup = makeFormationSetup<double>(spec, spec.run<aurora_control::LineShapeEntry>());
  EXPECT_FALSE(setup.ideal_link);
  const GridView grid = spec.view();
  for (long i = 0; i < spec.size(); ++i) {
    const Combination c = grid.decode(i);
    const auto run = formationCombination<aurora_control::ArdroneLaw<aurora_control::LawType::kUnderactuated>>(setup, c);
    EXPECT_EQ(run.drone[0].link.uplink.loss, 0.05);
    EXPECT_EQ(run.drone[0].link.downlink.jitter_max, 2);
    EXPECT_EQ(run.drone[1].link.uplink.loss, i / 4 % 2 == 0 ? 0.0 : 0.3) << i;  // its own, over the common 0.05
    EXPECT_EQ(run.drone[1].link.downlink.jitter_max, 0);  // the file's
    EXPECT_EQ(run.drone[1].delay, i / 2 % 2 == 0 ? 0 : 9);
  }
  const std::vector<SimResult> scalar = runOn("scalar", spec);
  EXPECT_EQ(differing(scalar, runOn("none", spec)), 0);
  EXPECT_NE(std::memcmp(&scalar[0], &scalar[4], sizeof(SimResult)), 0) << "drone 2's loss changed nothing";
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported && isa.key != "none") expectAgreement(isa.key, spec, 1e-9, 8);
  }
  std::vector<SimResult> out(static_cast<size_t>(spec.size()));
  for (unsigned t = 0; t < 8; ++t) {
    formationThread<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, aurora_control::kShortHistory, true>(setup, grid, 0, spec.size(),
                                                                                         out.data(), 0, 8, t);
  }
  EXPECT_EQ(differing(scalar, out), 0);
}

// Results name the formation's columns; the summary the formation file and
// its criteria; the definition hash tells formation files apart.
TEST(FormationSweep, ResultsNameTheFormationsColumns) {
  const SweepSpec p = formationSweep("cols_p", "  formation: formations/line_lemniscate.yaml\n" + std::string(kGrid));
  const SweepSpec ik = formationSweep("cols_ik", "  formation: formations/line_lemniscate_ik.yaml\n" + std::string(kGrid));
  const std::string csv = ::testing::TempDir() + "/formation_results.csv";
  writeResultsCsv(csv, p, runOn("cpu", p));
  const std::string text = readText(csv);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "index,delay_1,delay_2,formation_k1_rho,ok1,ok2,ok3,ok4,ok5,feasible,iae_position,iae_shape,min_distance,"
            "steps,max_position_error,max_shape_error,end_distance,ground_command");
  // Two drones: no ground robot, check 5 holds and no command share is used.
  size_t rows = 0;
  for (size_t at = text.find('\n'); at + 1 < text.size(); at = text.find('\n', at + 1), ++rows) {
    const std::string row = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
    EXPECT_EQ(row.substr(row.rfind(',')), ",0") << row;
  }
  EXPECT_EQ(static_cast<long>(rows), p.size());
  EXPECT_NE(definitionHash(p), definitionHash(ik));
  const std::string summary = ::testing::TempDir() + "/formation_summary.json";
  const std::vector<SimResult> results = runOn("cpu", p);
  for (const SimResult& r : results) EXPECT_TRUE(checkHeld(r, 4));
  writeSummaryJson(summary, p, RunInfo(), countResults(results, p.iterations(), checkCount(true)));
  const nlohmann::json j = nlohmann::json::parse(readText(summary));
  EXPECT_EQ(j["formation_file"], configDir() + "/formations/line_lemniscate.yaml");
  EXPECT_EQ(j["formation_criteria"]["min_distance"], 0.6);
  EXPECT_EQ(j["formation_criteria"]["max_ground_speed"], 0.5);
  EXPECT_EQ(j["result_columns"][8]["name"], "min_distance");
  EXPECT_EQ(j["checks"]["failed"].size(), 5u);
  EXPECT_EQ(j["checks"]["failed"][4], 0);
  EXPECT_EQ(j["controller"], "underactuated");
}

TEST(FormationSweep, MistakesAreRefusedNamingTheKey) {
  const std::string f = "sweep:\n  formation: formations/line_lemniscate.yaml\n";
  const std::string grid = "  parameters:\n    delay_1: {values: [0, 3]}\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {f + "  controller: pd_saturated\n" + grid, "'sweep.controller' is refused in a formation sweep"},
      {f + "  task: tasks/positioning.yaml\n" + grid, "'sweep.task' is refused in a formation sweep"},
      {f + "  link: links/wifi_lab.yaml\n" + grid, "'sweep.link' is refused in a formation sweep"},
      {f + "  parameters:\n    delay: 3\n", "'sweep.parameters.delay' is not a parameter of a formation sweep"},
      {f + "  parameters:\n    k1_x: 0.5\n", "'sweep.parameters.k1_x' is not a parameter of a formation sweep"},
      {f + "  parameters:\n    delay_1: {values: [0, 3000]}\n", "'sweep.parameters.delay_1' = 3000 is outside"},
      {f + "  parameters:\n    delay_2: 2.5\n", "'sweep.parameters.delay_2' = 2.5 is refused: delay_2 takes whole samples"},
      {f + "  parameters:\n    formation_k2_beta: -1\n", "'sweep.parameters.formation_k2_beta' = -1 is outside"},
      {f + "  repeats: 4\n" + grid, "'sweep.repeats' = 4 draws nothing"},
      {f + "  criteria: {max_shape: 1}\n" + grid, "'sweep.criteria.max_shape' is not a known key"},
      {f + "  criteria: {min_distance: -1}\n" + grid, "'sweep.criteria.min_distance' = -1 is outside"},
      {f + "  parameters:\n    uplink_loss: 0.9\n    uplink_burst: 2\n", "'sweep.parameters.uplink_loss' = 0.9"},
      {f + "  parameters:\n    uplink_loss_2: 0.9\n    uplink_burst_2: 2\n", "'sweep.parameters.uplink_loss_2' = 0.9"},
      {f + "  parameters:\n    downlink_delay_1: {values: [0, 3000]}\n", "'sweep.parameters.downlink_delay_1' = 3000 is outside"},
      {"sweep:\n  formation: formations/none.yaml\n" + grid, "none.yaml"},
      {"sweep:\n  parameters:\n    delay_1: 3\n    kp: 1\n    kd: 1\n    delay: 0\n",
       "'sweep.parameters.delay_1' is not a parameter of the pd_saturated controller"},
      {"sweep:\n  parameters:\n    uplink_loss_2: 0.1\n    kp: 1\n    kd: 1\n    delay: 0\n",
       "'sweep.parameters.uplink_loss_2' is not a parameter of the pd_saturated controller"},
  };
  for (const auto& c : cases) {
    const std::string got = refusal(c.first);
    EXPECT_NE(got.find(c.second), std::string::npos) << "file:\n" << c.first << "\ngot: " << got;
  }
}

// The shipped studies (config/sweeps/formation_delay*.yaml), at their
// corners and cut to 4 link seeds: every seed flies with no delay, none
// with both drones 31 samples late.
TEST(FormationSweep, TheFormationDelayStudiesSpanTheMargin) {
  for (const char* name : {"formation_delay", "formation_delay_ik"}) {
    std::string text = readText(configDir() + "/sweeps/" + name + ".yaml");
    const std::string from = "repeats: 64", grid = "{from: 0, to: 31, count: 32}";
    ASSERT_NE(text.find(from), std::string::npos) << name;
    text.replace(text.find(from), from.size(), "repeats: 4");
    for (size_t at; (at = text.find(grid)) != std::string::npos;) text.replace(at, grid.size(), "{values: [0, 31]}");
    const SweepSpec spec = loadSweepFile(writeTemp(std::string(name) + "_corners.yaml", text), configDir());
    EXPECT_EQ(spec.precision, Precision::kFloat);
    ASSERT_EQ(spec.size(), 16);
    const std::vector<SimResult> r = runOn("cpu", spec);
    int at_zero = 0, at_31 = 0;
    for (int s = 0; s < 4; ++s) at_zero += feasible(r[s]), at_31 += feasible(r[12 + s]);
    EXPECT_EQ(at_zero, 4) << name;
    EXPECT_EQ(at_31, 0) << name;
  }
}

#ifdef AURORA_SWEEP_LANES  // xsimd >= 8
#include <xsimd/xsimd.hpp>
// The formation checks' smallest distance on SIMD lanes (this program's
// baseline instruction set): NaN on the lane of a NaN robot, whichever robot
// it is, and the other lanes' own distances. (smallerDistance tests NaN as
// !(r == r): xsimd's != on AVX and AVX-512 is ordered, false for NaN, which passed a
// NaN over on the engine's lanes; the equality is false for NaN everywhere.)
template <typename T>
void expectLaneClosestPairs() {
  using B = xsimd::batch<T>;
  constexpr int L = static_cast<int>(B::size);
  struct Three {
    enum : int { kDrones = 3, kVariables = 9 };
  };
  for (int nan_robot = 0; nan_robot < 3; ++nan_robot) {
    const T start[9] = {0, 0, 1, 2, 0, 1, 0, 3, 1};  // closest: robots 1 and 2, 2 m apart
    B X[9];
    for (int i = 0; i < 9; ++i) {
      alignas(64) T lanes[L];
      for (int l = 0; l < L; ++l) lanes[l] = start[i] * T(1 + l);  // lane l: 2 (l + 1) m
      if (i == 3 * nan_robot + 1) lanes[0] = std::numeric_limits<T>::quiet_NaN();
      X[i] = B::load_aligned(lanes);
    }
    alignas(64) T got[L];
    aurora_control::closestPair<Three>(X).store_aligned(got);
    EXPECT_TRUE(std::isnan(got[0])) << "robot " << nan_robot + 1 << ": " << got[0];
    for (int l = 1; l < L; ++l) EXPECT_EQ(got[l], T(2 * (l + 1))) << "lane " << l;
  }
}

TEST(FormationSweep, TheClosestPairOnLanesIsNaNWhereARobotIsNaN) {
  expectLaneClosestPairs<float>();
  expectLaneClosestPairs<double>();
}
#endif
