// The limits Controller.cfg gives dynamic_reconfigure (rqt sliders, the
// server's description) equal the limits the node enforces (limits.h, the
// rules of live_settings.h): one table, two files, kept equal by this test.
#include <aurora_control/ControllerConfig.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "aurora_control/law_yaml.h"
#include "aurora_control/limits.h"
#include "controller_params.h"  // readUnderactuatedGains

using namespace aurora_control;

TEST(ReconfigureLimits, ControllerCfgEqualsLimitsH) {
  const ControllerConfig lo = ControllerConfig::__getMin__(), hi = ControllerConfig::__getMax__();
  EXPECT_EQ(lo.kp, kPdGainMin);
  EXPECT_EQ(hi.kp, kPdGainMax);
  EXPECT_EQ(lo.kd, kPdGainMin);
  EXPECT_EQ(hi.kd, kPdGainMax);
  EXPECT_EQ(lo.delay_samples, 0);
  EXPECT_EQ(hi.delay_samples, kMaxDelaySamples);
  ControllerConfig los = lo, his = hi;
  UnderactuatedGains<double> gmin{}, gmax{};
  readUnderactuatedGains(los, gmin);
  readUnderactuatedGains(his, gmax);
  for (int i = 0; i < 2 * kAxes; ++i) {
    EXPECT_EQ(underactuatedGain(gmin, i), kUnderactuatedGainMin) << underactuatedGainName(i);
    EXPECT_EQ(underactuatedGain(gmax, i), kUnderactuatedGainMax) << underactuatedGainName(i);
  }
  // Every live setting the node takes is in the description, and no other.
  std::vector<std::string> described;
  for (const auto& p : ControllerConfig::__getDescriptionMessage__().groups[0].parameters) described.push_back(p.name);
  std::vector<std::string> live{"kp", "kd", "delay_samples"};
  for (const std::string& g : lawGainNames(LawType::kUnderactuated)) live.push_back(g);
  std::sort(described.begin(), described.end());
  std::sort(live.begin(), live.end());
  EXPECT_EQ(described, live);
}
