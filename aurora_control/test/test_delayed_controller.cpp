// The controller node's core: delay, re-sent states, source resets, clamping
// and metrics once per state step.
#include <gtest/gtest.h>

#include "aurora_control/loop/delayed_controller.h"

using namespace aurora_control;

// The AR.Drone's laws' settings and controller core (their family, other_laws.h).
using ControllerSettings = aurora_control::LawSettings<aurora_control::ArdroneLawData>;
template <int Capacity>
using ArdroneController = aurora_control::DelayedController<Capacity, ControllerSettings>;

namespace {
StateSample sample(long step, double x) {
  StateSample s;
  s.step = step;
  s.stamp_ns = step * 1000;
  s.X[aurora_sim::kX] = x;
  return s;
}
const double kDesired[3] = {2.0, 1.0, 2.0};
}  // namespace

TEST(DelayedController, UsesTheStateDSamplesOld) {
  ArdroneController<16> c;
  c.settings.gains.pd = {0.5, 0.85};
  c.settings.delay = 3;
  for (long k = 0; k < 10; ++k) {
    ASSERT_TRUE(c.push(sample(k, 0.1 * k)));
    const ControlOutput out = c.compute(kDesired);
    const long expected = k + 1 > 3 ? k - 3 : k;  // spec: H(k - d) if k > d (1-based)
    EXPECT_EQ(out.used->step, expected);
    EXPECT_EQ(out.delay_in_force, k + 1 > 3 ? 3 : 0);
    EXPECT_DOUBLE_EQ(out.position_error[0], 2.0 - 0.1 * expected);
  }
}

TEST(DelayedController, ResentStateIsNotAddedAndMetricsCountOnce) {
  ArdroneController<16> c;
  c.settings.gains.pd = {0.5, 0.85};
  c.push(sample(0, 0.0));
  const ControlOutput a = c.compute(kDesired);
  EXPECT_FALSE(c.push(sample(0, 0.0)));
  const ControlOutput b = c.compute(kDesired);  // a timer cycle without a new state
  EXPECT_EQ(a.iae, b.iae);
  EXPECT_GT(a.iae, 0.0);
  c.push(sample(1, 0.0));
  EXPECT_GT(c.compute(kDesired).iae, a.iae);
}

TEST(DelayedController, StepGoingBackRestarts) {
  ArdroneController<16> c;
  c.settings.delay = 2;
  for (long k = 0; k < 5; ++k) c.push(sample(k, 0.0)), c.compute(kDesired);
  c.push(sample(0, 0.5));
  const ControlOutput out = c.compute(kDesired);
  EXPECT_EQ(out.used->step, 0);
  EXPECT_EQ(out.delay_in_force, 0);
}

TEST(DelayedController, ClampsWhenConfigured) {
  ArdroneController<16> c;
  c.settings.gains.pd = {5.0, 5.0};
  c.push(sample(0, -10.0));
  c.settings.clamp_commands = true;
  ControlOutput out = c.compute(kDesired);
  EXPECT_EQ(out.U[1], -1.0);  // u_theta = -a_x, a_x > 1
  EXPECT_LT(out.U_unclamped[1], -1.0);
  c.settings.clamp_commands = false;
  out = c.compute(kDesired);
  EXPECT_EQ(out.U[1], out.U_unclamped[1]);
}

TEST(DelayedController, HoverCommandsZero) {
  ArdroneController<16> c;
  c.settings.gains.pd = {0.5, 0.85};
  c.push(sample(0, 0.0));
  const ControlOutput out = c.hover();
  for (double u : out.U) EXPECT_EQ(u, 0.0);
}
