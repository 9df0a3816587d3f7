// Joystick mapping, deadman, button edges and the slew-limited resume.
#include <gtest/gtest.h>

#include <cmath>

#include "aurora_control/robot/joystick.h"

using namespace aurora_control;

TEST(Joystick, DeadmanAndSticksXboxDefaults) {
  JoystickMapper m;
  std::vector<float> axes(8, 0.0f);
  std::vector<int> buttons(11, 0);
  axes[4] = 0.5f;   // right stick up
  axes[0] = -0.25f; // left stick right
  JoystickInput in = m.map(axes, buttons);
  EXPECT_FALSE(in.deadman);
  buttons[4] = 1;
  in = m.map(axes, buttons);
  EXPECT_TRUE(in.deadman);
  EXPECT_DOUBLE_EQ(in.sticks.linear_x, 0.5);
  EXPECT_DOUBLE_EQ(in.sticks.angular_z, -0.25);
  axes[1] = 3.0f;  // out of range is clamped
  EXPECT_EQ(m.map(axes, buttons).sticks.linear_z, 1.0);
}

TEST(Joystick, ButtonsFireOncePerPress) {
  JoystickMapper m;
  std::vector<float> axes(8, 0.0f);
  std::vector<int> buttons(11, 0);
  buttons[3] = 1;
  EXPECT_TRUE(m.map(axes, buttons).takeoff);
  EXPECT_FALSE(m.map(axes, buttons).takeoff);  // still held
  buttons[3] = 0;
  m.map(axes, buttons);
  buttons[3] = 1;
  EXPECT_TRUE(m.map(axes, buttons).takeoff);
}

TEST(Joystick, ShortMessagesAreSafe) {
  JoystickMapper m;
  const JoystickInput in = m.map({}, {});
  EXPECT_FALSE(in.deadman);
  EXPECT_EQ(in.sticks.linear_x, 0.0);
}

TEST(ResumeSlew, LimitsEachStepUntilReached) {
  ResumeSlew slew(0.05, 0);
  const double from[4] = {0.8, 0, 0, 0};
  slew.start(from);
  double prev = 0.8;
  int cycles = 0;
  while (slew.active() && cycles < 100) {
    double U[4] = {0.1, 0, 0, 0};
    slew.apply(U);
    EXPECT_LE(std::fabs(U[0] - prev), 0.05 + 1e-12);
    prev = U[0];
    ++cycles;
  }
  EXPECT_EQ(prev, 0.1);
  EXPECT_EQ(cycles, 14);  // 0.7 / 0.05
  double U[4] = {0.3, 0, 0, 0};
  slew.apply(U);
  EXPECT_EQ(U[0], 0.3);  // inactive: passes through
}

TEST(ResumeSlew, StaysActiveForTheMinimumCycles) {
  ResumeSlew slew(0.05, 30);
  const double from[4] = {0, 0, 0, 0};
  slew.start(from);
  for (int k = 0; k < 29; ++k) {
    double U[4] = {0, 0, 0, 0};
    slew.apply(U);
    EXPECT_TRUE(slew.active());
  }
  double jump[4] = {0.5, 0, 0, 0};  // the law jumps within the hand-back: still limited
  slew.apply(jump);
  EXPECT_DOUBLE_EQ(jump[0], 0.05);
}
