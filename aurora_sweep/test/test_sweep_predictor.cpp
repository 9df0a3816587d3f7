// Sweeps with the state predictor (issue 35, docs/predictor.md, "In a
// sweep"): with the nominal model as plant every delay of a grid flies as
// no delay (the same record to the byte); the scalar loop, the SIMD lanes
// and the kernel's per-thread entry (on the host) agree, over an ideal link
// and a congested one, for both forms; the shipped studies load; bad input
// is refused naming the key (the cuda backend's refusal: test_sweep_cuda).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/kernel_entry.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

using PdLaw = aurora_control::ArdroneLaw<aurora_control::LawType::kPdSaturated>;

// A small grid of the thesis's study (4 Kp x 3 Kd x `delays`), with
// `extra` lines in the sweep block.
SweepSpec grid(const std::string& extra, const std::string& delays = "{from: 0, to: 30, count: 4}") {
  static int n = 0;
  const std::string text = "sweep:\n  name: p\n  controller: pd_saturated\n  task: tasks/positioning.yaml\n"
                           "  parameters:\n    kp: {from: 0.1, to: 0.75, count: 4}\n"
                           "    kd: {from: 0.2, to: 1.0, count: 3}\n    delay: " + delays + "\n"
                           "  order: [kp, kd, delay]\n" + extra;
  return loadSweepFile(test::writeTemp("predictor_" + std::to_string(n++) + ".yaml", text), test::configDir());
}

void expectSameRecord(const SimResult& a, const SimResult& b, const std::string& what) {
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(SimResult)), 0) << what;
}

std::vector<SimResult> onKernelThreads(const SweepSpec& spec, bool linked) {
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  const GridView view = spec.view();
  const long n = spec.size();
  return test::launchOnHost(n, 32, [&](unsigned b, unsigned block, unsigned t, SimResult* out) {
    if (linked) {
      sweepThread<PdLaw, double, aurora_control::kShortHistory, true, true>(setup, view, 0, n, out, b, block, t);
    } else {
      sweepThread<PdLaw, double, aurora_control::kShortHistory, false, true>(setup, view, 0, n, out, b, block, t);
    }
  });
}

}  // namespace

TEST(SweepPredictor, APerfectModelFliesEveryDelayAsNone) {
  for (const char* form : {"resimulate", "smith"}) {
    const SweepSpec spec = grid(std::string("  predictor: {form: ") + form + "}\n");
    ASSERT_TRUE(spec.predicting());
    const std::vector<SimResult> r = test::runOn("scalar", spec);
    const std::vector<SimResult> plain = test::runOn("scalar", grid(""));
    const long gains = 12;
    long differ = 0;
    for (long i = 0; i < spec.size(); ++i) {
      const long at_zero = i % gains;  // the same gains, delay 0
      if (std::string(form) == "resimulate") expectSameRecord(r[i], r[at_zero], std::string(form) + " " + std::to_string(i));
      EXPECT_NEAR(r[i].iae, r[at_zero].iae, 1e-9) << form << " " << i;
      EXPECT_EQ(feasible(r[i]), feasible(r[at_zero])) << form << " " << i;
      differ += std::memcmp(&plain[i], &plain[at_zero], sizeof(SimResult)) != 0;
    }
    EXPECT_GT(differ, 30) << "without the predictor the delays change the runs";
    for (long i = 0; i < gains; ++i) EXPECT_NEAR(r[i].iae, plain[i].iae, 1e-9) << "delay 0 is the plain run";
  }
}

TEST(SweepPredictor, EveryBackendAgrees) {
  for (const char* form : {"resimulate", "smith"}) {
    for (const char* link : {"", "  link: links/wifi_congested.yaml\n"}) {
      const SweepSpec spec = grid(std::string("  predictor: {form: ") + form + "}\n" + link);
      const std::vector<SimResult> scalar = test::runOn("scalar", spec);
      test::expectRunsAgree(scalar, test::runOn("cpu", spec), 0.0);
      const std::vector<SimResult> threads = onKernelThreads(spec, *link != '\0');
      for (long i = 0; i < spec.size(); ++i) expectSameRecord(scalar[i], threads[i], std::string(form) + " " + link);
    }
  }
}

TEST(SweepPredictor, TheShippedStudiesLoadAndNameIt) {
  const std::string c = test::configDir() + "/sweeps/";
  for (const char* name : {"positioning_delay_predictor", "positioning_delay_wifi_congested_predictor",
                           "predictor_robustness"}) {
    const SweepSpec s = loadSweepFile(c + name + ".yaml", test::configDir());
    EXPECT_EQ(s.predictor, aurora_control::PredictorForm::kResimulate) << name;
    EXPECT_EQ(s.predictor_model_file, test::configDir() + "/vehicles/ardrone2.yaml") << name;
  }
  const SweepSpec with = loadSweepFile(c + "positioning_delay_predictor.yaml", test::configDir());
  const SweepSpec without = loadSweepFile(c + "positioning_delay.yaml", test::configDir());
  EXPECT_EQ(with.size(), without.size());
  EXPECT_NE(definitionHash(with), definitionHash(without)) << "their chunks must not be mixed";
}

TEST(SweepPredictor, BadInputIsRefusedNamingTheKey) {
  const std::string head = "sweep:\n  controller: pd_saturated\n  task: tasks/positioning.yaml\n"
                           "  parameters:\n    kp: 0.5\n    kd: 0.85\n    delay: {from: 0, to: 3, count: 4}\n";
  EXPECT_NE(test::refusal(head + "  predictor: {form: kalman}\n")
                .find("'sweep.predictor.form' = 'kalman' is unknown: accepted 'resimulate', 'smith', 'off'"),
            std::string::npos);
  const std::string other = test::refusal(head + "  predictor: {form: smith, model: vehicles/pioneer3dx.yaml}\n");
  EXPECT_NE(other.find("sweep.predictor.model"), std::string::npos) << other;
  EXPECT_NE(other.find("give a vehicle file of type 'ardrone2'"), std::string::npos) << other;
  EXPECT_NE(test::refusal(head + "  predictor: {form: smith, horizon: 1}\n").find("horizon"), std::string::npos);
  const std::string formation = test::refusal(
      "sweep:\n  formation: formations/line_lemniscate.yaml\n  parameters:\n    delay_1: 0\n    delay_2: 0\n"
      "  predictor: {form: resimulate}\n");
  EXPECT_NE(formation.find("'sweep.predictor' is refused for a formation sweep: its robots fly the predictor their "
                           "controller files give"), std::string::npos) << formation;
  // A formation robot's horizon stands for a real robot's latency: a sweep's robots' is their links'.
  const std::string controller = test::writeTemp(
      "horizon_controller.yaml", test::readText(test::configDir() + "/controllers/underactuated_predictor.yaml"));
  std::string text = test::readText(controller);
  text.replace(text.find("horizon: 0.0"), 12, "horizon: 0.1");
  text.replace(text.find("../vehicles/ardrone2.yaml"), 25, test::configDir() + "/vehicles/ardrone2.yaml");
  test::writeTemp("horizon_controller.yaml", text);
  std::string triangle = test::readText(test::configDir() + "/formations/triangle_ardrones.yaml");
  triangle.replace(triangle.find("controllers/underactuated.yaml"), 30, controller);
  const std::string horizon = test::refusal("sweep:\n  formation: " + test::writeTemp("horizon_triangle.yaml", triangle) +
                                            "\n  parameters:\n    delay_1: {values: [0, 3]}\n");
  EXPECT_NE(horizon.find("robot 1's controller file gives 'predictor.horizon' (3 samples), refused in a sweep"),
            std::string::npos) << horizon;
  EXPECT_EQ(test::refusal(head + "  predictor: {form: 'off'}\n"), "");
}

#ifdef AURORA_SWEEP_LANES  // xsimd >= 8
#include <cmath>

#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "../src/lanes/lane_predictor.h"

// The lanes' predictor across long outages (no newer state for longer
// than its rings), each lane its own: the prediction of rings of 16 slots
// is the one of 4,096, to the bit, both forms (StatePredictor's test on
// the lanes).
TEST(SweepPredictor, ALongOutageDoesNotWrapTheLanesRings) {
  using Vehicle = aurora_sim::Ardrone2;
  using Lanes = LanePredictor<Vehicle, double, xsimd::default_arch>;
  using B = Lanes::B;
  using I = Lanes::I;
  constexpr int L = Lanes::L, S = Vehicle::kStates;
  const auto model = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(std::string(AURORA_CONFIG_DIR) + "/vehicles/ardrone2.yaml");
  Vehicle::State<double> start;
  Vehicle::start(model, start);
  for (const auto form : {aurora_control::PredictorForm::kResimulate, aurora_control::PredictorForm::kSmith}) {
    Lanes ring(form, model, start, false, 16), endless(form, model, start, false, 4096);
    std::vector<Vehicle::State<double>> plant(L, start);
    alignas(64) int64_t received[L] = {};
    for (int l = 0; l < L; ++l) ring.startLane(l, l % 3), endless.startLane(l, l % 3);
    long compared = 0;
    for (long k = 0; k < 160; ++k) {
      ring.pushed(), endless.pushed();
      alignas(64) double xc[S][L];
      for (int l = 0; l < L; ++l) {
        const bool outage = k >= 20 + 5 * l && k < 80 + 7 * l;  // each lane its own
        if (!outage) received[l] = k;
        compared += outage;
        for (int i = 0; i < S; ++i) xc[i][l] = plant[l].X[i];
      }
      B x[S], a[S], b[S];
      for (int i = 0; i < S; ++i) x[i] = B::load_aligned(xc[i]);
      const I r = I::load_aligned(received);
      ring.predict(I(k), r, x, a);
      endless.predict(I(k), r, x, b);
      for (int i = 0; i < S; ++i) {
        alignas(64) double got[L], want[L];
        a[i].store_aligned(got), b[i].store_aligned(want);
        for (int l = 0; l < L; ++l) {
          ASSERT_EQ(got[l], want[l]) << aurora_control::predictorFormName(form) << " lane " << l << " step " << k;
        }
      }
      double U[Vehicle::kInputs] = {0.3 * std::sin(0.1 * k), 0.2 * std::cos(0.07 * k), 0.4, 0.1};
      B Ub[Vehicle::kInputs];
      for (int i = 0; i < Vehicle::kInputs; ++i) Ub[i] = B(U[i]);
      ring.sent(Ub), endless.sent(Ub);
      for (int l = 0; l < L; ++l) {
        if (received[l] == k) Vehicle::step(model, plant[l], U);
      }
    }
    EXPECT_GT(compared, 60 * L);
  }
}
#endif
