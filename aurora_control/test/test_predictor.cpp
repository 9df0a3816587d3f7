// The state predictor (docs/predictor.md): with a perfect model its
// prediction is the state its command acts on, so a delayed loop flies as
// one without delay; both forms, every vehicle, over links; its file
// block's refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "aurora_control/loop/flight_setup.h"
#include "config_dir.h"

namespace {

using aurora_control::FlightFiles;
using aurora_control::LinkParams;
using aurora_control::PredictorForm;

using aurora_tests::kConfig;

struct Flown {
  std::vector<std::vector<double>> X;   // X_k, each step's state
  std::vector<std::vector<double>> xc;  // what the law flew on at step k
  std::vector<long> received;
};

// A controller file: the shipped `base` with its predictor block replaced
// (`block` "" for none), written to a temporary folder.
std::string controllerFile(const std::string& base, const std::string& block) {
  std::ifstream in(kConfig + "/controllers/" + base + ".yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("predictor:");
  if (at != std::string::npos) text.erase(at);
  const std::string path = ::testing::TempDir() + "/" + base + "_test.yaml";
  std::ofstream(path) << text << block;
  return path;
}

std::string block(const char* form, const std::string& vehicle, double horizon = 0.0) {
  return std::string("predictor:\n  form: ") + form + "\n  model: " + kConfig + "/vehicles/" + vehicle +
         ".yaml\n  horizon: " + std::to_string(horizon) + "\n";
}

// The flight of a controller file on `task` with `delay` (and a link).
Flown fly(const std::string& controller, const std::string& task, long delay, const LinkParams& link = LinkParams(),
          const std::string& vehicle = "ardrone2") {
  const FlightFiles files{controller, kConfig + "/tasks/" + task + ".yaml", kConfig + "/vehicles/" + vehicle + ".yaml",
                          "", delay};
  Flown out;
  aurora_control::withFlight(files, aurora_control::controllerFileName(controller), {0.0, "", ""}, [&](auto f) {
    using Vehicle = typename decltype(f)::Law::Vehicle;
    f.cfg.link = link;
    f.predictor = aurora_control::withPredictor(f, controller).predictor;  // again: the link changed
    aurora_control::flyLaw(f, [&](const auto& o, double) {
      out.X.emplace_back(o.X_before, o.X_before + Vehicle::kStates);
      out.xc.emplace_back(o.xc, o.xc + Vehicle::kStates);
      out.received.push_back(o.received);
    });
  });
  return out;
}

double largestDifference(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b,
                         size_t shift = 0) {
  double worst = 0.0;
  for (size_t k = 0; k + shift < b.size() && k < a.size(); ++k) {
    for (size_t i = 0; i < a[k].size(); ++i) worst = std::max(worst, std::fabs(a[k][i] - b[k + shift][i]));
  }
  return worst;
}

}  // namespace

// Issue 35, item 3: resimulate on the nominal model flies the delayed loop
// as the undelayed one, to the bit; smith to rounding (1e-9).
TEST(Predictor, APerfectModelFliesTheDelayedLoopAsTheUndelayedOne) {
  for (const char* law : {"pd_saturated", "underactuated"}) {
    const Flown plain = fly(kConfig + "/controllers/" + law + ".yaml", "lemniscate", 0);
    const Flown delayed = fly(kConfig + "/controllers/" + law + ".yaml", "lemniscate", 10);
    ASSERT_GT(largestDifference(plain.X, delayed.X), 0.01) << law << ": the delay must change the flight";
    const Flown resim = fly(controllerFile(law, block("resimulate", "ardrone2")), "lemniscate", 10);
    ASSERT_EQ(resim.X.size(), plain.X.size());
    EXPECT_EQ(largestDifference(plain.X, resim.X), 0.0) << law << ", resimulate";
    EXPECT_EQ(resim.received[100], 90) << "the law received the state 10 steps old";
    const Flown smith = fly(controllerFile(law, block("smith", "ardrone2")), "lemniscate", 10);
    EXPECT_LT(largestDifference(plain.X, smith.X), 1e-9) << law << ", smith";
  }
}

// The shipped files are the plain ones' gains with the resimulate form.
TEST(Predictor, TheShippedPredictorFilesFlyAsTheUndelayedLaw) {
  for (const char* law : {"pd_saturated", "underactuated"}) {
    const Flown plain = fly(kConfig + "/controllers/" + law + ".yaml", "mission4", 0);
    const Flown predicted = fly(kConfig + "/controllers/" + law + "_predictor.yaml", "mission4", 10);
    EXPECT_EQ(largestDifference(plain.X, predicted.X), 0.0) << law;
  }
}

// Every vehicle has it through the same seam: the Bebop's compensator and
// the Pioneer's dynamic law, each on its own model.
TEST(Predictor, EveryVehicleHasIt) {
  const struct {
    const char* law;
    const char* vehicle;
    const char* task;
  } cases[] = {{"bebop2_compensator", "bebop2", "bebop2_lemniscate"}, {"pioneer_dynamic", "pioneer3dx", "pioneer_lemniscate"}};
  for (const auto& c : cases) {
    const Flown plain = fly(kConfig + "/controllers/" + c.law + ".yaml", c.task, 0, LinkParams(), c.vehicle);
    const Flown delayed = fly(kConfig + "/controllers/" + c.law + ".yaml", c.task, 6, LinkParams(), c.vehicle);
    ASSERT_GT(largestDifference(plain.X, delayed.X), 1e-3) << c.law;
    for (const char* form : {"resimulate", "smith"}) {
      const Flown p = fly(controllerFile(c.law, block(form, c.vehicle)), c.task, 6, LinkParams(), c.vehicle);
      EXPECT_LT(largestDifference(plain.X, p.X), 1e-9) << c.law << ", " << form;
    }
  }
}

// Over a link: the prediction is the state of the step the command acts
// on, k + the downlink's delay; lost states are extended from the last one
// received (the predictor's exactness does not depend on what arrives).
TEST(Predictor, PredictsTheStepTheCommandActsOnOverALossyLink) {
  LinkParams link;
  link.uplink.loss = 0.3;
  link.uplink.burst = 3.0;
  link.uplink.jitter = aurora_control::JitterKind::kUniform;
  link.uplink.jitter_max = 2;
  link.downlink.delay = 3;
  link.cmd_timeout = 1.0;
  link.seed = 7;
  for (const char* form : {"resimulate", "smith"}) {
    const Flown f = fly(controllerFile("underactuated", block(form, "ardrone2")), "lemniscate", 4, link);
    long oldest = 0;
    for (size_t k = 0; k < f.received.size(); ++k) oldest = std::max(oldest, long(k) - f.received[k]);
    EXPECT_GT(oldest, 7) << "the losses must age the received state";
    // xc of step k is the prediction of X_(k+3): compare with the flown X.
    EXPECT_LT(largestDifference(f.xc, f.X, 3), 1e-9) << form;
    EXPECT_GT(largestDifference(f.xc, f.X, 0), 1e-3) << form << ": not the state of step k itself";
  }
}

// Model error: a plant that differs from the nominal model is not
// predicted exactly, but the predictor still beats the delay.
TEST(Predictor, WithAModelErrorItIsNotExact) {
  const std::string heavy = ::testing::TempDir() + "/ardrone2_heavy.yaml";
  {
    std::ifstream in(kConfig + "/vehicles/ardrone2.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find("\nmass:");
    ASSERT_NE(at, std::string::npos);
    const size_t end = text.find('\n', at + 1);
    text.replace(at, end - at, "\nmass: 0.5");
    std::ofstream(heavy) << text;
  }
  const std::string c = controllerFile("underactuated", block("resimulate", "ardrone2"));
  const FlightFiles plain_files{kConfig + "/controllers/underactuated.yaml", kConfig + "/tasks/lemniscate.yaml", heavy, "", 0};
  Flown plain;
  aurora_control::withFlight(plain_files, "underactuated", {0.0, "", ""}, [&](const auto& f) {
    aurora_control::flyLaw(f, [&](const auto& o, double) { plain.X.emplace_back(o.X_before, o.X_before + 12); });
  });
  const FlightFiles files{c, kConfig + "/tasks/lemniscate.yaml", heavy, "", 10};
  Flown predicted;
  aurora_control::withFlight(files, "underactuated", {0.0, "", ""}, [&](const auto& f) {
    aurora_control::flyLaw(f, [&](const auto& o, double) { predicted.X.emplace_back(o.X_before, o.X_before + 12); });
  });
  const double off = largestDifference(plain.X, predicted.X);
  EXPECT_GT(off, 1e-6) << "the model (m 0.429 kg) is not the plant (0.5 kg)";
  EXPECT_LT(off, 0.5);
}

// Issue 35, item 6: bad blocks refused naming the key.
TEST(Predictor, ABadBlockIsRefusedNamingTheKey) {
  const auto refusal = [](const std::string& law, const std::string& b, long delay = 5) -> std::string {
    try {
      fly(controllerFile(law, b), law == "pioneer_dynamic" ? "pioneer_lemniscate" : "lemniscate", delay, LinkParams(),
          law == "pioneer_dynamic" ? "pioneer3dx" : "ardrone2");
    } catch (const aurora_common::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal("pd_saturated", "predictor:\n  form: kalman\n  model: x.yaml\n").find(
                "'predictor.form' = 'kalman' is unknown: accepted 'resimulate', 'smith', 'off'"),
            std::string::npos);
  const std::string other = refusal("pd_saturated", block("resimulate", "pioneer3dx"));
  EXPECT_NE(other.find("predictor.model"), std::string::npos) << other;
  EXPECT_NE(other.find("pioneer3dx"), std::string::npos) << other;
  EXPECT_NE(refusal("pioneer_dynamic", block("smith", "ardrone2")).find("predictor.model"), std::string::npos);
  const std::string far = refusal("pd_saturated", block("resimulate", "ardrone2", 100.0));
  EXPECT_NE(far.find("'predictor.horizon' = 100 s (3000 samples) is refused"), std::string::npos) << far;
  EXPECT_NE(refusal("pd_saturated", block("resimulate", "ardrone2", -0.1)).find("predictor.horizon"),
            std::string::npos);
  EXPECT_NE(refusal("pd_saturated", "predictor:\n  form: smith\n").find("predictor.model"), std::string::npos);
  EXPECT_NE(refusal("pd_saturated", "predictor:\n  form: smith\n  model: x.yaml\n  lead: 1\n").find("lead"),
            std::string::npos);
  EXPECT_EQ(refusal("pd_saturated", "predictor:\n  form: 'off'\n"), "");
}

// A long outage (no newer state for longer than the predictor's rings):
// the prediction is the one of an endless ring, to the bit, for both forms,
// any command delay and horizon, and cycles that skip steps (the node's).
// With the rings read as they wrapped, window 16 against 4,096 differed by
// up to 1.05 (resimulate) and 0.80 (smith) after 50 steps without a state.
TEST(Predictor, ALongOutageDoesNotWrapItsRings) {
  using Vehicle = aurora_sim::Ardrone2;
  const auto model = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(kConfig + "/vehicles/ardrone2.yaml");
  for (const PredictorForm form : {PredictorForm::kResimulate, PredictorForm::kSmith}) {
    for (const long delay : {0L, 3L, 7L}) {
      const aurora_control::CommandPath path{delay, delay == 3 ? 2L : 0L, delay == 7};
      aurora_control::StatePredictor<Vehicle, double, 16> ring(form, model, path);
      aurora_control::StatePredictor<Vehicle, double, 4096> endless(form, model, path);
      Vehicle::State<double> plant;
      Vehicle::start(model, plant);
      long received = 0, compared = 0;
      for (long k = 0; k < 160; k += (k % 7 == 3) ? 2 : 1) {  // some cycles skip a step
        const bool outage = (k >= 20 && k < 75) || (k >= 90 && k < 125);
        if (!outage) received = k;
        double a[aurora_sim::kStateSize], b[aurora_sim::kStateSize];
        ring.predict(k, received, plant.X, a);
        endless.predict(k, received, plant.X, b);
        for (int i = 0; i < aurora_sim::kStateSize; ++i) {
          ASSERT_EQ(a[i], b[i]) << predictorFormName(form) << " delay " << delay << " step " << k << " state " << i;
        }
        compared += outage;
        const double U[4] = {0.3 * std::sin(0.1 * k), 0.2 * std::cos(0.07 * k), 0.4, 0.1};
        ring.sent(k, U);
        endless.sent(k, U);
        if (!outage) Vehicle::step(model, plant, U);
      }
      EXPECT_GT(compared, 60);
    }
  }
}
