// A sweep over a link (sweep file 'link:', the link parameters, repeats;
// docs/links.md): an ideal link file changes nothing; over a lossy link the
// threads and the kernel's per-thread entry give the scalar loop's bits and
// the SIMD lanes agree with it; a combination's run is the offline runner's
// over its link; the draws follow the combination (not the chunk); the link
// is part of the sweep's definition; mistakes are refused naming the key.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_sweep/chunk_store.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_sweep/kernel_entry.h"
#include "sweep_test_support.h"
#ifdef AURORA_SWEEP_LANES  // xsimd >= 8
#include "../src/lanes/lane_history.h"
#include "../src/lanes/lane_links.h"
#endif

using namespace aurora_sweep;
using namespace aurora_sweep::test;

namespace {

// The small grid of the backend tests (80 combinations), over links/NAME.yaml.
SweepSpec smallGrid(const std::string& link) {
  std::string text = readText(std::string(AURORA_SWEEP_TEST_DIR) + "/data/small_grid.yaml");
  if (!link.empty()) text += "  link: links/" + link + ".yaml\n";
  return loadSweepFile(writeTemp("small_grid_link_" + link + ".yaml", text), configDir());
}

}  // namespace

TEST(SweepLink, AnIdealLinkFileChangesNothing) {
  const SweepSpec plain = smallGrid(""), ideal = smallGrid("ideal");
  EXPECT_TRUE(ideal.link.ideal());
  EXPECT_EQ(definitionHash(plain), definitionHash(ideal));
  EXPECT_EQ(differing(runOn("scalar", plain), runOn("scalar", ideal)), 0);
}

TEST(SweepLink, EveryCpuBackendAgreesOverALossyLink) {
  const SweepSpec lossy = smallGrid("wifi_congested");
  ASSERT_FALSE(lossy.linkIdeal());
  const std::vector<SimResult> scalar = runOn("scalar", lossy);
  // One simulation per thread: the scalar loop's bits.
  EXPECT_EQ(differing(scalar, runOn("none", lossy)), 0);
  // SIMD lanes, each with its own link: the same draws, so the same flags
  // and steps; the metrics to xsimd's sin and cos.
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported && isa.key != "none") test::expectAgreement(isa.key, lossy, 1e-9, 10);
  }
  SweepSpec single = lossy;
  single.precision = Precision::kFloat;
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported && isa.key != "none") test::expectAgreement(isa.key, single, 2e-3, 10);
  }
  // Not vacuous: the link changed most runs.
  EXPECT_GT(differing(scalar, runOn("scalar", smallGrid(""))), 40);
  EXPECT_NE(definitionHash(lossy), definitionHash(smallGrid("")));
  EXPECT_NE(definitionHash(lossy), definitionHash(smallGrid("wifi_lab")));
}

#ifdef AURORA_SWEEP_LANES
// The SIMD lanes' own link models (lane_links.h: links without a geometric
// jitter): the same draws and decisions as ModelLink, so the same flags and
// steps as the scalar loop; with link values varied per lane and repeats.
TEST(SweepLink, LaneLinksAgreeWithTheScalarLoop) {
  const SweepSpec lab = smallGrid("wifi_lab");
  ASSERT_TRUE(laneLinksApply(lab.link));
  const SweepSpec varied = loadSweepFile(writeTemp("lane_links.yaml",
      "sweep:\n  repeats: 4\n  early_stop: false\n  link: links/wifi_lab.yaml\n  parameters:\n"
      "    kp: {values: [0.3, 0.5]}\n    kd: 0.85\n    delay: {values: [0, 4, 9]}\n    uplink_jitter: {values: [0, 3]}\n"
      "    uplink_loss: {values: [0, 0.2]}\n    uplink_burst: {values: [1, 4]}\n    downlink_delay: {values: [0, 2]}\n"
      "    downlink_jitter: 2\n    downlink_loss: 0.1\n"), configDir());
  for (const SweepSpec* spec : {&lab, &varied}) {
    for (const CpuIsa& isa : cpuBatchIsas()) {
      if (!isa.supported || isa.key == "none") continue;
      test::expectAgreement(isa.key, *spec, 1e-9, 10);
      SweepSpec single = *spec;
      single.precision = Precision::kFloat;
      test::expectAgreement(isa.key, single, 2e-3, 10);
    }
  }
}

// LanePhilox is Random123's philox4x32 block, word for word, on the
// instruction set this test is built for (xsimd's default) and on plain
// scalar lanes.
template <class Arch>
void expectLanePhiloxIsRandom123s() {
  constexpr int L = 16;
  uint64_t ctr[4][L], key[2][L], out[4][L];
  for (int trial = 0; trial < 1000; ++trial) {
    for (int l = 0; l < L; ++l) {
      const aurora_control::StepDraws d = aurora_control::stepDraws(uint32_t(trial), uint64_t(l) << 33, uint64_t(l) * 977);
      ctr[0][l] = d.uplink.jitter_w, ctr[1][l] = d.uplink.loss_w, ctr[2][l] = d.downlink.jitter_w;
      ctr[3][l] = d.downlink.loss_w, key[0][l] = uint32_t(ctr[3][l] * 3u + 1u), key[1][l] = ctr[0][l] ^ 0x5555u;
    }
    LanePhilox<L, Arch>::blocks(ctr, key, out);
    for (int l = 0; l < L; ++l) {
      r123::Philox4x32 philox;
      const r123::Philox4x32::ctr_type c = {{uint32_t(ctr[0][l]), uint32_t(ctr[1][l]), uint32_t(ctr[2][l]), uint32_t(ctr[3][l])}};
      const r123::Philox4x32::key_type k = {{uint32_t(key[0][l]), uint32_t(key[1][l])}};
      const r123::Philox4x32::ctr_type r = philox(c, k);
      for (int w = 0; w < 4; ++w) ASSERT_EQ(out[w][l], r.v[w]) << trial << " " << l << " " << w;
    }
  }
}

TEST(SweepLink, LanePhiloxIsRandom123s) {
  expectLanePhiloxIsRandom123s<xsimd::default_arch>();
}

// The SIMD engine's history gives each lane the state of its own step,
// whether the lanes read one slot (a plain load: a drone whose delay the
// batch shares) or several (a gather); a step read again is the one latched.
TEST(SweepLink, ALaneHistoryReadsEachLanesStepFromOneSlotOrMany) {
  using Law = aurora_control::ArdroneLaw<aurora_control::LawType::kUnderactuated>;
  using History = LaneHistory<Law, float, xsimd::default_arch>;
  using B = History::B;
  using I = History::I;
  constexpr int L = History::L, S = Law::Vehicle::kStates;
  History history;
  history.allocate(16);
  for (int l = 0; l < L; ++l) history.startLane(l);
  // State k of lane l: component i is 1000 k + 10 i + l.
  auto value = [](int k, int i, int l) { return float(1000 * k + 10 * i + l); };
  for (int k = 0; k < 12; ++k) {
    B X[S];
    for (int i = 0; i < S; ++i) {
      alignas(64) float lanes[L];
      for (int l = 0; l < L; ++l) lanes[l] = value(k, i, l);
      X[i] = B::load_aligned(lanes);
    }
    history.push(X);
  }
  auto expectSteps = [&](const int (&steps)[L]) {
    alignas(64) int32_t at[L];
    for (int l = 0; l < L; ++l) at[l] = steps[l];
    B X[S];
    history.read(I::load_aligned(at), X);
    aurora_control::LawSample<float, Law> mask;
    for (int j = 0; j < Law::Input::kWidth; ++j) mask.v[j] = 1.0f;
    float read[S];
    mask.toState(read);  // 1 where the law reads a component
    for (int i = 0; i < S; ++i) {
      alignas(64) float got[L];
      X[i].store_aligned(got);
      for (int l = 0; l < L; ++l) {
        EXPECT_EQ(got[l], read[i] == 1.0f ? value(steps[l], i, l) : 0.0f) << "component " << i << " lane " << l;
      }
    }
  };
  int same[L], mixed[L], again[L];
  for (int l = 0; l < L; ++l) same[l] = 7, mixed[l] = 11 - l % 5, again[l] = l % 2 ? 7 : 11 - l % 5;
  expectSteps(same);
  expectSteps(mixed);
  expectSteps(again);
  expectSteps(same);
}
#endif

// Each CUDA thread's body over a link (kernel_entry.h), on the host.
TEST(SweepLink, TheKernelsPerThreadEntryOverALinkIsTheScalarLoop) {
  SweepSpec lossy = smallGrid("wifi_lab");
  lossy.range_begin = 5;
  std::vector<SimResult> scalar;
  Progress progress{0};
  runScalar(lossy, scalar, progress);
  ASSERT_LT(lossy.historyNeeded(), aurora_control::kMediumHistory);
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(lossy);
  ASSERT_FALSE(setup.ideal_link);
  const GridView grid = lossy.view();
  const long n = lossy.rangeSize();
  std::vector<SimResult> out(static_cast<size_t>(n));
  for (unsigned b = 0; b < blocksFor(n, 32); ++b) {
    for (unsigned t = 0; t < 32; ++t) {
      sweepThread<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>, double, aurora_control::kMediumHistory, true>(
          setup, grid, lossy.rangeBegin(), n, out.data(), b, 32, t);
    }
  }
  EXPECT_EQ(differing(scalar, out), 0);
}

// A loss burst longer than the history: the controller holds the newest
// state it received (it arrived young, long ago), whatever the ring's size.
// The histories latch what they read (closed_loop.h StateHistory,
// lane_history.h): before, a held step older than the ring read a newer,
// wrapped slot: the short tier (the scalar loop's here) and the medium one
// (the kernel's per-thread entry, forced) differed, and the SIMD lanes (one
// ring for all lanes) wrapped elsewhere: 8 of these 16 runs feasible on
// `cpu`, 7 on `scalar`.
TEST(SweepLink, ALossBurstLongerThanTheHistoryDoesNotDependOnItsSize) {
  const SweepSpec spec = loadSweepFile(writeTemp("long_burst.yaml",
      "sweep:\n  early_stop: false\n  repeats: 4\n  parameters:\n    kp: {values: [0.3, 0.5]}\n    kd: 0.85\n"
      "    delay: {values: [3, 20]}\n    uplink_loss: 0.3\n    uplink_burst: 80\n"), configDir());
  ASSERT_LT(spec.historyNeeded(), aurora_control::kShortHistory) << "the sweep's loops take the short tier";
  const std::vector<SimResult> scalar = runOn("scalar", spec);
  expectRunsAgree(scalar, runOn("cpu", spec), 0.0);  // the lanes' flags equal, sums to rounding
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  const GridView grid = spec.view();
  const long n = spec.size();
  const std::vector<SimResult> medium = launchOnHost(n, 8, [&](unsigned b, unsigned block, unsigned t, SimResult* out) {
    sweepThread<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>, double, aurora_control::kMediumHistory, true>(
        setup, grid, 0, n, out, b, block, t);
  });
  EXPECT_EQ(differing(scalar, medium), 0);
}

// A combination's run is the offline runner's (flight's) over the link the
// combination names, with its draws keyed by the combination; repeat r
// draws with the link's seed + r.
TEST(SweepLink, ACombinationIsTheRunnersRunOverItsLink) {
  const SweepSpec spec = loadSweepFile(writeTemp("link_values.yaml",
      "sweep:\n  repeats: 3\n  early_stop: false\n  link: links/wifi_lab.yaml\n  parameters:\n"
      "    kp: 0.5\n    kd: 0.85\n    delay: {values: [0, 9]}\n    uplink_jitter: {values: [0, 4]}\n"
      "    uplink_loss: {values: [0, 0.3]}\n    downlink_burst: 3\n"), configDir());
  ASSERT_EQ(spec.combinations(), 8);
  ASSERT_EQ(spec.size(), 24);
  const std::vector<SimResult> sweep = runOn("scalar", spec);
  const aurora_control::LinkParams file = aurora_control::readLinkFile(configDir() + "/links/wifi_lab.yaml");
  const GridView grid = spec.view();
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  long changed_by_seed = 0;
  for (long i = 0; i < spec.size(); ++i) {
    const Combination c = grid.decode(i);
    EXPECT_EQ(c.key, i / 3);
    EXPECT_EQ(c.repeat(), i % 3);
    aurora_control::RunnerConfig<double> cfg = setup.config;
    cfg.link = file;  // what a user would write in a link file for this combination
    cfg.link.uplink.jitter_max = static_cast<long>(c.v[kParamFirstLinkValue + aurora_control::kLinkUplinkJitter]);
    if (cfg.link.uplink.jitter_max > 0 && cfg.link.uplink.jitter == aurora_control::JitterKind::kNone) {
      cfg.link.uplink.jitter = aurora_control::JitterKind::kUniform;
    }
    cfg.link.uplink.loss = c.v[kParamFirstLinkValue + aurora_control::kLinkUplinkLoss];
    cfg.link.downlink.burst = 3;
    cfg.link.seed = file.seed + static_cast<uint32_t>(i % 3);
    aurora_control::NoObserver none;
    const SimResult r = compactResult(aurora_control::runOverModelLink<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>, double, 64>(
        studyRun<aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>>(setup, c), cfg, setup.iterations, none, static_cast<uint64_t>(i / 3)));
    EXPECT_EQ(differing({r}, {sweep[static_cast<size_t>(i)]}), 0) << "run " << i;
    if (i % 3 > 0) changed_by_seed += differing({sweep[static_cast<size_t>(i)]}, {sweep[static_cast<size_t>(i - 1)]});
  }
  EXPECT_GT(changed_by_seed, 8);  // the repeats drew differently
}

TEST(SweepLink, DrawsFollowTheCombinationNotTheChunk) {
  const SweepSpec full = smallGrid("wifi_lab");
  SweepSpec part = full;
  part.range_begin = 37, part.range_end = 61;
  const std::vector<SimResult> all = runOn("scalar", full);
  std::vector<SimResult> some;
  Progress progress{0};
  runScalar(part, some, progress);
  ASSERT_EQ(some.size(), 24u);
  EXPECT_EQ(differing(std::vector<SimResult>(all.begin() + 37, all.begin() + 61), some), 0);
}

TEST(SweepLink, MistakesAreRefusedNamingTheKey) {
  const std::string grid = "sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.85\n    delay: {values: [0, 1790]}\n";
  const std::string wide = writeTemp("wide_link.yaml", "link:\n  uplink: {jitter: {kind: uniform, max: 300}}\n");
  EXPECT_NE(refusal(grid + "  link: " + wide + "\n").find("'sweep.link' needs 2090 samples of history (the largest "
                                                          "delay 1790 plus the link's jitter): accepted up to 2047"),
            std::string::npos)
      << refusal(grid + "  link: " + wide + "\n");
  EXPECT_NE(refusal(grid + "  link: links/nowhere.yaml\n").find("link file"), std::string::npos);
  const std::string pd = "sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.85\n    delay: 10\n";
  const auto says = [&](const std::string& extra, const std::string& text) {
    const std::string why = refusal(pd + extra);
    EXPECT_NE(why.find(text), std::string::npos) << extra << " -> " << why;
  };
  says("    uplink_jitter: 2040\n", "'sweep.parameters' needs 2050 samples of history");
  says("    uplink_jitter: 2.5\n", "'sweep.parameters.uplink_jitter' = 2.5 is refused: uplink_jitter takes whole samples");
  says("    downlink_delay: {values: [-1]}\n", "'sweep.parameters.downlink_delay' = -1 is outside the accepted range [0, 2047]");
  says("    uplink_loss: 1\n", "'sweep.parameters.uplink_loss' = 1 is outside the accepted range [0, 0.99]");
  says("    downlink_burst: 0.5\n", "'sweep.parameters.downlink_burst' = 0.5 is outside the accepted range [1, 1000]");
  says("    uplink_loss: 0.8\n    uplink_burst: {values: [1, 2]}\n",
       "'sweep.parameters.uplink_loss' = 0.8 (its largest) is refused with burst 2: accepted up to burst / (burst + 1)");
  says("    repeat: 2\n", "'sweep.parameters.repeat' is not a parameter of the pd_saturated controller");
  says("  repeats: 4\n", "'sweep.repeats' = 4 draws nothing: without jitter or loss on either direction");
  says("  repeats: 4\n  link: links/tum_ardrone.yaml\n", "'sweep.repeats' = 4 draws nothing");  // delays only
  EXPECT_EQ(refusal(pd + "    uplink_loss: 0.1\n  repeats: 4\n"), "");
  says("  repeats: 0\n  link: links/wifi_lab.yaml\n", "'sweep.repeats' = 0 is refused: accepted [1, 100000]");
}

TEST(SweepLink, TheShippedLinkStudyIsTheThesisGridOverACongestedLink) {
  const SweepSpec s = loadSweepFile(configDir() + "/sweeps/positioning_delay_wifi_congested.yaml", configDir());
  EXPECT_EQ(s.size(), 65536);
  EXPECT_FALSE(s.link.ideal());
  EXPECT_NE(s.link_file.find("links/wifi_congested.yaml"), std::string::npos);
  EXPECT_EQ(s.max_delay, 63);
}

// The link margin studies: delay x uplink jitter x uplink loss, 16 seeds
// each; without delay every seed flies, at 20 samples none does.
TEST(SweepLink, TheLinkMarginStudiesSpanTheMargin) {
  for (const std::string name : {"link_margin", "link_margin_underactuated"}) {
    SweepSpec s = loadSweepFile(configDir() + "/sweeps/" + name + ".yaml", configDir());
    EXPECT_EQ(s.combinations(), 21 * 8 * 8) << name;
    EXPECT_EQ(s.size(), 21 * 8 * 8 * 16) << name;
    EXPECT_FALSE(s.linkIdeal()) << name;
    for (const long combination : {0L, 20L}) {
      s.range_begin = combination * 16, s.range_end = s.range_begin + 16;
      std::vector<SimResult> out;
      Progress progress{0};
      runCpuBatch(s, 2, out, progress);
      long flew = 0;
      for (const SimResult& r : out) flew += feasible(r);
      EXPECT_EQ(flew, combination == 0 ? 16 : 0) << name << " delay " << s.view().decode(s.range_begin).delay();
    }
  }
}

