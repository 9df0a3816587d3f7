// The laws sharing a Data are one family (other_laws.h): one loop type
// (LawSettings<Data>) flies any of them, chosen by name at start-up; every
// law's mapping, gains by name and live changes go through the same calls,
// the AR.Drone's two laws as any other.
#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "aurora_control/loop/flight_setup.h"
#include "aurora_control/loop/law_settings_yaml.h"
#include "aurora_control/loop/live_settings.h"
#include "aurora_control/task/tracking.h"
#include "edited_file.h"

using namespace aurora_control;

namespace {

using Ardrone = LawSettings<ArdroneLawData>;
using Bebop = LawSettings<Bebop2Compensator>;

template <class Data>
LawSettings<Data> readMapping(const std::string& yaml) {
  LawSettings<Data> set;
  readLawMapping(YamlReader("test: "), YAML::Load(yaml), "controller", set);
  return set;
}

template <class Data>
std::string mappingRefusal(const std::string& yaml) {
  return aurora_tests::configRefusal([&] { readMapping<Data>(yaml); });
}

std::string check(const LawSettings<Bebop2Compensator>& s, const std::string& name, double v) {
  return checkLiveChange(s, LiveChange{name, v}, taskStepCount(30.0, 1.0 / 30.0));
}

}  // namespace

TEST(LawFamily, EachLawOfTheListBelongsToItsDatasFamilyInTheListsOrder) {
  EXPECT_EQ(lawCountOf<ArdroneLawData>(), 2);
  EXPECT_EQ(lawCountOf<Bebop2Compensator>(), 1);
  EXPECT_EQ(lawCountOf<PioneerDynamic>(), 1);
  EXPECT_EQ(familyIndex<ArdroneLaw<LawType::kUnderactuated>>(), 1);
  EXPECT_EQ(familyIndex<PioneerKinematic>(), 0);
  EXPECT_EQ(lawIndexOf<ArdroneLawData>("underactuated"), 1);
  EXPECT_EQ(lawIndexOf<ArdroneLawData>("bebop2_compensator"), -1);
  std::string walked;
  forEachLawOf<ArdroneLawData>([&](auto law) { walked += std::string(walked.empty() ? "" : ",") + law.name(); });
  EXPECT_EQ(walked, "pd_saturated,underactuated");
  EXPECT_STREQ(lawNameOf(Ardrone::flying<ArdroneLaw<LawType::kUnderactuated>>()), "underactuated");
  EXPECT_STREQ(lawNameOf(Bebop()), "bebop2_compensator");
}

// The mapping's name picks the law of the family; its gains are read by
// the law's rows (the AR.Drone's) or its own reader (the compensator's).
TEST(LawFamily, AMappingChoosesItsLawAndReadsItsGainsByItsRows) {
  const Ardrone ua = readMapping<ArdroneLawData>(
      "{name: underactuated, k1_x: 1, k2_x: 2, k1_y: 1, k2_y: 2, k1_z: 1, k2_z: 2, k1_phi: 1, k2_phi: 2, "
      "k1_theta: 1, k2_theta: 2, k1_psi: 1, k2_psi: 3}");
  EXPECT_EQ(ua.law, 1);
  const auto gains = gainsInForce(ua);
  ASSERT_EQ(gains.size(), 12u);
  EXPECT_EQ(gains.back().first, "k2_psi");
  EXPECT_EQ(gains.back().second, 3.0);
  EXPECT_EQ(ua.gains.underactuated.k2[kAxisPsi], 3.0);
  const Ardrone pd = readMapping<ArdroneLawData>("{name: pd_saturated, kp: 0.5, kd: 0.85}");
  EXPECT_EQ(pd.law, 0);
  EXPECT_EQ(pd.gains.pd.kd, 0.85);
  EXPECT_NE(mappingRefusal<ArdroneLawData>("{name: pd_saturated, kp: 11, kd: 0.85}")
                .find("test: 'controller.kp' = 11 is outside the accepted range [0, 10]"),
            std::string::npos);
  EXPECT_EQ(mappingRefusal<ArdroneLawData>("{name: pd_saturated, kp: 1, kd: 0.85, k1_x: 1}"),
            "test: 'controller.k1_x' is not a known key: accepted name, kp, kd");
  // A law of another family: refused naming the vehicle it flies and this loop's laws.
  EXPECT_EQ(mappingRefusal<ArdroneLawData>("{name: bebop2_compensator}"),
            "test: 'controller.name' = 'bebop2_compensator' is refused here: it flies the bebop2; "
            "accepted: pd_saturated, underactuated (the ardrone2's)");
  EXPECT_NE(mappingRefusal<ArdroneLawData>("{name: nosuch}").find("= 'nosuch' is unknown: accepted controllers: "
                                                                  "pd_saturated, underactuated, bebop2_compensator"),
            std::string::npos);
}

// Replay reads a recorded law's gains back by name, for any law alike.
TEST(LawFamily, RecordedGainsAreSetByName) {
  Ardrone set = Ardrone::flying<ArdroneLaw<LawType::kPdSaturated>>();
  EXPECT_EQ(setGainsNamed(set, {"kd", "kp"}, {0.85, 0.5}), "");
  EXPECT_EQ(set.gains.pd.kp, 0.5);
  EXPECT_EQ(set.gains.pd.kd, 0.85);
  EXPECT_EQ(setGainsNamed(set, {"kp"}, {0.5}), "kd");
  Bebop bebop;
  const auto named = gainsInForce(bebop);
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& g : named) names.push_back(g.first), values.push_back(g.second + 1.0);
  EXPECT_EQ(setGainsNamed(bebop, names, values), "");
  EXPECT_EQ(gainsInForce(bebop).front().second, named.front().second + 1.0);
}

// A law whose gains come from its controller file takes only its loop's
// settings live; the AR.Drone's gains the server shows (their presets) load
// back unchanged, any other value is refused.
TEST(LawFamily, ALawWithoutLiveGainsTakesOnlyTheLoopsSettingsLive) {
  Bebop s;
  s.delay = 3;
  EXPECT_EQ(check(s, "delay_samples", 5), "");
  EXPECT_EQ(check(s, "kp", 0.0), "");  // the server's kp for a law without one
  EXPECT_EQ(check(s, "k1_x", UnderactuatedGains<double>::defaults().k1[kAxisX]), "");
  EXPECT_NE(check(s, "kp", 0.5).find("'kp' = 0.5 is refused: this node flies the bebop2_compensator law, whose gains "
                                      "come from its controller file"),
            std::string::npos)
      << check(s, "kp", 0.5);
  const auto shown = liveGainsShown(s);
  ASSERT_EQ(shown.size(), 14u);  // the AR.Drone's kp, kd and 12 underactuated gains
  EXPECT_EQ(shown[0].first, "kp");
  EXPECT_EQ(shown[0].second, 0.0);
  // An AR.Drone node shows its own gains.
  Ardrone pd = readMapping<ArdroneLawData>("{name: pd_saturated, kp: 0.5, kd: 0.85}");
  EXPECT_EQ(liveGainsShown(pd)[0].second, 0.5);
  applyLiveChange(pd, LiveChange{"kd", 0.9});
  EXPECT_EQ(liveGainsShown(pd)[1].second, 0.9);
}

// A flight of any law from its file: the AR.Drone's laws as the others
// (loadLawFlight), the file's clamp_commands in force, and --no-clamp
// reaching the sim except where the vehicle clamps anyway (kAlwaysClamps).
TEST(LawFamily, AnArdroneFlightIsAnyLawsFlight) {
  const std::string c = AURORA_CONFIG_DIR;
  FlightFiles f{c + "/controllers/pd_saturated.yaml", c + "/tasks/mission4.yaml", c + "/vehicles/ardrone2.yaml", ""};
  const auto clamped = loadLawFlight<ArdroneLaw<LawType::kPdSaturated>>(f);
  EXPECT_TRUE(clamped.cfg.clamp_commands);
  EXPECT_TRUE(clamped.cfg.clamp_at_drone);
  EXPECT_EQ(clamped.run.gains.pd.kp, 0.5);
  f.no_clamp = true;
  const auto unclamped = loadLawFlight<ArdroneLaw<LawType::kPdSaturated>>(f);
  EXPECT_FALSE(unclamped.cfg.clamp_commands);
  EXPECT_TRUE(unclamped.cfg.clamp_at_drone);  // the AR.Drone's sim clamps, as its driver does
  const std::string path = aurora_tests::editedConfigFile("controllers/pd_saturated.yaml", "clamp_commands: true",
                                                           "clamp_commands: false");
  ASSERT_FALSE(path.empty());
  f.no_clamp = false, f.controller = path;
  EXPECT_FALSE(loadLawFlight<ArdroneLaw<LawType::kPdSaturated>>(f).cfg.clamp_commands);
}

// A law with a rate of its own (lawHasRate) flies at its file's rate or the
// one given, as its period in model steps; refused when it does not divide
// the vehicle's.
TEST(LawFamily, ALawWithARateFliesAtTheFilesOrTheGivenRate) {
  const std::string c = AURORA_CONFIG_DIR;
  const FlightFiles f{c + "/controllers/bebop2_compensator.yaml", c + "/tasks/bebop2_waypoints.yaml",
                      c + "/vehicles/bebop2.yaml", ""};
  const auto file_rate = loadLawFlight<Bebop2Compensator>(f);
  EXPECT_EQ(file_rate.rate, 30.0);
  EXPECT_EQ(file_rate.run.gains.period_steps, 1.0);
  FlightOptionNames o;
  o.rate = 10.0;
  const auto given = loadLawFlight<Bebop2Compensator>(f, o);
  EXPECT_EQ(given.rate, 10.0);
  EXPECT_EQ(given.run.gains.period_steps, 3.0);
  o.rate = 7.0, o.rate_option = "rate=";
  EXPECT_NE(aurora_tests::configRefusal([&] { loadLawFlight<Bebop2Compensator>(f, o); })
                .find("rate=7 Hz does not divide the vehicle's 30 Hz"),
            std::string::npos);
  EXPECT_EQ(loadLawFlight<ArdroneLaw<LawType::kPdSaturated>>(
                FlightFiles{c + "/controllers/pd_saturated.yaml", c + "/tasks/mission4.yaml", c + "/vehicles/ardrone2.yaml", ""})
                .rate,
            0.0);  // no rate of its own
}
