// The limits Controller.cfg gives dynamic_reconfigure (rqt sliders, the
// server's description) are the controller's parameters' (the live laws'
// gain rows and parameter_table.h, joined in loop/controller_parameters.h),
// which the node enforces (live_settings.h): generated from them at build
// time, checked here as the generated header has them.
#include <aurora_control/ControllerConfig.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "aurora_control/loop/controller_parameters.h"
#include "aurora_control/loop/live_settings.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/params/parameter_table.h"

using namespace aurora_control;

TEST(ReconfigureLimits, ControllerCfgEqualsTheControllersParameters) {
  const dynamic_reconfigure::ConfigDescription d = ControllerConfig::__getDescriptionMessage__();
  ASSERT_EQ(d.min.doubles.size(), d.max.doubles.size());
  for (size_t i = 0; i < d.min.doubles.size(); ++i) {
    const std::string name = d.min.doubles[i].name;
    const ParameterSpec* row = controllerLiveSetting(name);
    ASSERT_NE(row, nullptr) << name << " of Controller.cfg is not a controller parameter";
    EXPECT_EQ(d.min.doubles[i].value, row->min) << name;
    EXPECT_EQ(d.max.doubles[i].value, row->max) << name;
  }
  EXPECT_EQ(d.min.doubles.size(), 3u + 2 * kAxes + 7);  // + the link's live values
  // Every live setting the node takes is in the description, and no other.
  std::vector<std::string> described;
  for (const auto& p : ControllerConfig::__getDescriptionMessage__().groups[0].parameters) described.push_back(p.name);
  std::vector<std::string> gains{"kp", "kd"};
  for (int i = 0; i < 2 * kAxes; ++i) gains.push_back(underactuatedGainName(i));
  std::vector<std::string> live{"delay_samples", "uplink_jitter", "uplink_loss", "uplink_burst",
                                "downlink_delay", "downlink_jitter", "downlink_loss", "downlink_burst", "predictor"};
  live.insert(live.end(), gains.begin(), gains.end());
  std::sort(described.begin(), described.end());
  std::sort(live.begin(), live.end());
  EXPECT_EQ(described, live);
  // ... and the gains the node shows and takes live are those (every law with row gains: the AR.Drone's two).
  std::vector<std::string> shown;
  for (const auto& g : liveGainsShown(LawSettings<Bebop2Compensator>())) shown.push_back(g.first);
  EXPECT_EQ(shown, gains);
}

// The predictor's form is the table's word row: a string setting, its
// default the row's, its choices named in its description.
TEST(ReconfigureLimits, ThePredictorIsAWordOfTheTable) {
  const dynamic_reconfigure::ConfigDescription d = ControllerConfig::__getDescriptionMessage__();
  ASSERT_EQ(d.dflt.strs.size(), 1u);
  EXPECT_EQ(d.dflt.strs[0].name, "predictor");
  EXPECT_EQ(d.dflt.strs[0].value, "off");
  for (const auto& p : d.groups[0].parameters) {
    if (p.name == "predictor") EXPECT_NE(p.description.find("(off, resimulate, smith)"), std::string::npos);
  }
}
