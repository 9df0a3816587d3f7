// Live changes meet the start-up rules: refused with the value as given,
// never clamped; a refusal names the key and the accepted range.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "aurora_control/loop/live_settings.h"
#include "aurora_control/task/tracking.h"

using namespace aurora_control;

// The AR.Drone's laws' settings and controller core (their family, other_laws.h).
using ControllerSettings = aurora_control::LawSettings<aurora_control::ArdroneLawData>;
template <int Capacity>
using ArdroneController = aurora_control::DelayedController<Capacity, ControllerSettings>;

namespace {

ControllerSettings pd() {
  ControllerSettings s;
  s.gains.pd = {0.5, 0.85};
  s.delay = 10;
  return s;
}

const long kMission = taskStepCount(60.0, 1.0 / 30.0);  // 1801

std::string check(const ControllerSettings& s, const std::string& name, double v) {
  return checkLiveChange(s, LiveChange{name, v}, kMission);
}

}  // namespace

TEST(LiveSettings, AcceptsWhatStartUpAccepts) {
  ControllerSettings s = pd();
  EXPECT_EQ(check(s, "kp", 0.6), "");
  EXPECT_EQ(check(s, "delay_samples", 1800), "");
  applyLiveChange(s, LiveChange{"kp", 0.6});
  applyLiveChange(s, LiveChange{"delay_samples", 6});
  EXPECT_EQ(s.gains.pd.kp, 0.6);
  EXPECT_EQ(s.delay, 6);
}

TEST(LiveSettings, RefusesWithTheValueGiven) {
  const ControllerSettings s = pd();
  EXPECT_EQ(check(s, "kp", std::nan("")), "kp = nan is refused: accepted a gain in [0, 10]");
  EXPECT_EQ(check(s, "kp", -3), "kp = -3 is refused: accepted a gain in [0, 10]");
  EXPECT_EQ(check(s, "kp", 50), "kp = 50 is refused: accepted a gain in [0, 10]");
  EXPECT_NE(check(s, "kd", std::numeric_limits<double>::infinity()).find("kd = inf is refused"), std::string::npos);
  EXPECT_NE(check(s, "delay_samples", -1).find("delay_samples = -1 is refused"), std::string::npos);
  EXPECT_EQ(check(s, "delay_samples", 2.5), "delay_samples = 2.5 is refused: accepted integer samples in [0, 2047]");
  EXPECT_NE(check(s, "delay_samples", 5000).find("delay_samples = 5000 is refused"), std::string::npos);
  EXPECT_NE(check(s, "delay_samples", 1801).find("accepted delays up to 1800 samples"), std::string::npos);
  EXPECT_EQ(check(s, "kpp", 0.6), "'kpp' is not a live setting: accepted delay_samples, kp, kd (the pd_saturated "
                                   "law's gains), the link's uplink_jitter, uplink_loss, uplink_burst, "
                                   "downlink_delay, downlink_jitter, downlink_loss, downlink_burst, predictor");
}

// Issue 35: the predictor switches live by its form's word.
TEST(LiveSettings, ThePredictorSwitchesByItsWord) {
  ControllerSettings s = pd();
  const LiveChange on{"predictor", std::nan(""), "smith"}, bad{"predictor", std::nan(""), "kalman"};
  EXPECT_EQ(checkLiveChange(s, on, 1801), "");
  EXPECT_EQ(checkLiveChange(s, bad, 1801), "predictor = 'kalman' is refused: accepted 'resimulate', 'smith', 'off'");
  applyLiveChange(s, on);
  EXPECT_EQ(s.predictor, PredictorForm::kSmith);
  applyLiveChange(s, LiveChange{"predictor", std::nan(""), "off"});
  EXPECT_EQ(s.predictor, PredictorForm::kOff);
}

TEST(LiveSettings, AGainOfTheOtherLawIsRefusedUnlessUnchanged) {
  ControllerSettings s = pd();
  EXPECT_NE(check(s, "k1_x", 0.7).find("a gain of the underactuated law, but this node flies the pd_saturated"),
            std::string::npos);
  // Issue 31: the list of what is accepted named the gains and the delay, not the link's settings.
  EXPECT_NE(check(s, "k1_x", 0.7).find("(accepted: kp, kd, delay_samples, the link's uplink_jitter, uplink_loss"),
            std::string::npos) << check(s, "k1_x", 0.7);
  // dynparam load of a dump sends every key: the unchanged ones pass.
  EXPECT_EQ(check(s, "k1_x", s.gains.underactuated.k1[kAxisX]), "");
  applyLiveChange(s, LiveChange{"k1_x", s.gains.underactuated.k1[kAxisX]});
  EXPECT_EQ(s.gains.pd.kp, 0.5);
  s.law = int(LawType::kUnderactuated);
  EXPECT_NE(check(s, "kp", 0.9).find("a gain of the pd_saturated law"), std::string::npos);
  EXPECT_EQ(check(s, "k2_z", 100.0), "");
  EXPECT_NE(check(s, "k2_z", 0.0).find("accepted a gain in [0.001, 100]"), std::string::npos);
}

// The link's live values (docs/links.md) meet the link files' rules: the
// table's ranges, whole samples, the burst's bound on the loss, the history.
TEST(LiveSettings, TheLinkChangesLiveWithTheFilesRules) {
  ControllerSettings s = pd();
  EXPECT_EQ(check(s, "uplink_loss", 0.05), "");
  EXPECT_EQ(check(s, "uplink_loss", 1.0), "uplink_loss = 1 is refused: accepted a value in [0, 0.99]");
  EXPECT_EQ(check(s, "downlink_burst", 0.5), "downlink_burst = 0.5 is refused: accepted samples in [1, 1000]");
  EXPECT_EQ(check(s, "downlink_delay", 2.5), "downlink_delay = 2.5 is refused: accepted whole samples");
  EXPECT_NE(check(s, "uplink_jitter", 2040).find("would exceed the history of 2047 samples"), std::string::npos);
  applyLiveChange(s, LiveChange{"downlink_burst", 2.0});
  EXPECT_NE(check(s, "downlink_loss", 0.9).find("accepted up to burst / (burst + 1) = 0.666667"), std::string::npos);
  // Issue 31: a burst refused for the loss in force did not say that loss.
  ControllerSettings lossy = pd();
  applyLiveChange(lossy, LiveChange{"downlink_loss", 0.9});
  EXPECT_EQ(check(lossy, "downlink_burst", 2.0),
            "downlink_burst = 2: the loss 0.9 is refused with burst 2: accepted up to burst / (burst + 1) = 0.666667");
  applyLiveChange(s, LiveChange{"uplink_jitter", 3});
  applyLiveChange(s, LiveChange{"downlink_loss", 0.1});
  EXPECT_EQ(s.link.uplink.jitter, JitterKind::kUniform);  // a jitter on a link without a kind: uniform
  EXPECT_EQ(s.link.uplink.jitter_max, 3);
  EXPECT_EQ(s.link.downlink.loss, 0.1);
  EXPECT_FALSE(s.link.ideal());
}

// One definition of a task's steps and of the tracking error (the flight
// tool and report use it): steps 0..round(D / Ts), state k against reference k.
TEST(Tracking, StepsAndError) {
  EXPECT_EQ(taskStepCount(40.0, 1.0 / 30.0), 1201);
  EXPECT_EQ(taskStepCount(60.0, 1.0 / 30.0), 1801);
  Reference<double> ref;
  ref.pos[0] = 1, ref.pos[1] = 2, ref.pos[2] = 2;
  double X[aurora_sim::kStateSize] = {};
  X[aurora_sim::kX] = 1, X[aurora_sim::kY] = -1, X[aurora_sim::kZ] = 6;
  EXPECT_EQ(trackingError(ref, X), 5.0);
}
