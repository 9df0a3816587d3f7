// Delivery of take-off / land / reset (driver_command.h): held until the
// driver listens, re-sent until shown, one attempt for reset, timeout.
#include <gtest/gtest.h>

#include "aurora_control/robot/driver_command.h"

using namespace aurora_control;

namespace {

DeliveryPolicy resend(double period, double timeout) {
  DeliveryPolicy p;
  p.resend_period = period;
  p.timeout = timeout;
  return p;
}

}  // namespace

TEST(DriverCommand, HeldUntilTheDriverListens) {
  DriverCommand c(resend(1.0, 0.0));
  c.request(0.0);
  for (double t = 0.0; t < 3.0; t += 0.1) EXPECT_FALSE(c.update(t, false, false)) << t;
  EXPECT_EQ(c.state(), Delivery::kWaitingForDriver);
  EXPECT_EQ(c.attempts(), 0);
  EXPECT_TRUE(c.update(3.0, true, false));  // the first cycle the driver listens
  EXPECT_EQ(c.attempts(), 1);
  EXPECT_DOUBLE_EQ(c.firstAttemptAt(), 3.0);
}

TEST(DriverCommand, ResentAtThePeriodUntilShown) {
  DriverCommand c(resend(1.0, 0.0));
  c.request(0.0);
  int sent = 0;
  // 30 Hz cycles; the state shows the effect from t = 2.5 s on.
  for (int k = 0; k <= 150; ++k) {
    const double t = k / 30.0;
    if (c.update(t, true, t >= 2.5)) ++sent;
  }
  EXPECT_EQ(sent, 3);  // t = 0, 1, 2
  EXPECT_EQ(c.attempts(), 3);
  EXPECT_EQ(c.state(), Delivery::kShown);
}

TEST(DriverCommand, LandGivesUpAfterTheTimeoutAndSaysSo) {
  DriverCommand c(resend(1.0, 5.0));
  c.request(0.0);
  int sent = 0;
  for (int k = 0; k <= 300; ++k) {
    if (c.update(k / 30.0, true, false)) ++sent;
  }
  EXPECT_EQ(sent, 5);  // t = 0 .. 4; at 5 s the timeout
  EXPECT_EQ(c.state(), Delivery::kTimedOut);
  EXPECT_FALSE(c.pending());
}

TEST(DriverCommand, ResetIsSentOnceNeverRepeated) {
  DriverCommand c;  // one attempt: ardrone_autonomy's reset toggles the emergency state
  c.request(0.0);
  EXPECT_FALSE(c.update(0.0, false, false));
  int sent = 0;
  for (int k = 1; k <= 300; ++k) {
    if (c.update(k / 30.0, true, false)) ++sent;
  }
  EXPECT_EQ(sent, 1);
  EXPECT_EQ(c.state(), Delivery::kSent);
}

TEST(DriverCommand, ShownBeforeAnyAttemptStillSendsOnce) {
  // A take-off requested while the drone already climbs (a pilot's): the
  // driver ignores it, and nothing is re-sent.
  DriverCommand c(resend(1.0, 0.0));
  c.request(0.0);
  EXPECT_TRUE(c.update(0.0, true, true));
  EXPECT_FALSE(c.update(1.5, true, true));
  EXPECT_EQ(c.state(), Delivery::kShown);
  EXPECT_EQ(c.attempts(), 1);
}

TEST(DriverCommand, CancelAndRequestAgain) {
  DriverCommand c(resend(1.0, 0.0));
  c.request(0.0, 0.2);
  EXPECT_TRUE(c.update(0.0, true, false));
  c.cancel();
  EXPECT_EQ(c.state(), Delivery::kIdle);
  EXPECT_FALSE(c.update(2.0, true, false));
  c.request(3.0, 0.4);
  EXPECT_EQ(c.attempts(), 0);
  EXPECT_DOUBLE_EQ(c.reference(), 0.4);
  EXPECT_TRUE(c.update(3.0, true, false));
}

TEST(DriverCommand, Evidence) {
  double X[aurora_sim::kStateSize] = {};
  X[aurora_sim::kZ] = 0.05;
  EXPECT_FALSE(climbShown(X, 0.0, 0.1));
  X[aurora_sim::kZ] = 0.1;
  EXPECT_TRUE(climbShown(X, 0.0, 0.1));
  X[aurora_sim::kZ] = 0.75;
  X[aurora_sim::kVz] = -0.05;
  EXPECT_FALSE(descentShown(X, 0.1, 0.1));  // hover noise is not a descent
  X[aurora_sim::kVz] = -0.2;
  EXPECT_TRUE(descentShown(X, 0.1, 0.1));
  X[aurora_sim::kVz] = 0.0;
  X[aurora_sim::kZ] = 0.05;
  EXPECT_TRUE(descentShown(X, 0.1, 0.1));  // already down
}
