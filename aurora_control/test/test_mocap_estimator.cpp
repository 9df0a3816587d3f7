// The mocap estimator: velocity of a known trajectory from noisy poses,
// robustness to zero/negative time steps, yaw wrapping and gaps.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "aurora_control/robot/mocap_estimator.h"

using aurora_control::MocapEstimator;

namespace {
using aurora_common::kPi;
}

TEST(MocapEstimator, VelocityOfKnownTrajectoryWithNoise) {
  // x = 0.5 sin(t), y = 0.3 t, z = 1 + 0.2 cos(2t), yaw = 0.4 t; 120 Hz poses
  // with 0.5 mm / 0.05 deg noise (a lab mocap system), 5 % dropped. Stated
  // tolerance after 2 s of settling, against the true derivative delayed by
  // the filter's time constant: 0.1 m/s on each velocity axis, 0.2 rad/s on
  // the yaw rate (4 Hz cut-off: about 0.03 m/s and 0.05 rad/s of noise, 1 sigma).
  std::mt19937 rng(7);  // seed from the test, not the clock
  std::normal_distribution<double> pos_noise(0.0, 0.0005), ang_noise(0.0, 0.05 * kPi / 180);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MocapEstimator est;
  double worst_v = 0.0, worst_r = 0.0;
  for (int i = 0; i < 120 * 10; ++i) {
    const double t = i / 120.0;
    if (i > 0 && u(rng) < 0.05) continue;  // dropout
    const double pos[3] = {0.5 * std::sin(t) + pos_noise(rng), 0.3 * t + pos_noise(rng),
                           1.0 + 0.2 * std::cos(2 * t) + pos_noise(rng)};
    const double rpy[3] = {ang_noise(rng), ang_noise(rng), 0.4 * t + ang_noise(rng)};
    est.update(t, pos, rpy);
    if (t > 2.0) {
      double X[12];
      est.state(X);
      // The low-pass lags the true derivative by about tau; compare with it.
      const double lag = 1.0 / (2 * kPi * 4.0);
      const double v_true[3] = {0.5 * std::cos(t - lag), 0.3, -0.4 * std::sin(2 * (t - lag))};
      for (int k = 0; k < 3; ++k) worst_v = std::max(worst_v, std::fabs(X[6 + k] - v_true[k]));
      worst_r = std::max(worst_r, std::fabs(X[11] - 0.4));
    }
  }
  EXPECT_LT(worst_v, 0.1);
  EXPECT_LT(worst_r, 0.2);
}

TEST(MocapEstimator, ZeroAndNegativeTimeStepsNeverGiveNaN) {
  MocapEstimator est;
  const double a[3] = {0, 0, 1}, b[3] = {0.1, 0, 1}, rpy[3] = {0, 0, 0};
  est.update(1.0, a, rpy);
  EXPECT_EQ(est.update(1.0, b, rpy), MocapEstimator::Result::kNotNewer);   // duplicate stamp
  EXPECT_EQ(est.update(0.99, b, rpy), MocapEstimator::Result::kNotNewer);  // out of order
  EXPECT_EQ(est.update(1.01, b, rpy), MocapEstimator::Result::kAccepted);
  double X[12];
  est.state(X);
  for (double v : X) EXPECT_TRUE(std::isfinite(v));
  EXPECT_GT(X[6], 0.0);
}

TEST(MocapEstimator, YawCrossingPiGivesNoRateSpike) {
  MocapEstimator est;
  const double pos[3] = {0, 0, 1};
  double worst = 0.0;
  for (int i = 0; i < 240; ++i) {
    const double t = i / 120.0;
    double yaw = 3.0 + 0.5 * t;  // crosses +pi at t = 0.28 s
    if (yaw > kPi) yaw -= 2 * kPi;
    const double rpy[3] = {0, 0, yaw};
    est.update(t, pos, rpy);
    double X[12];
    est.state(X);
    if (t > 0.1) worst = std::max(worst, std::fabs(X[11] - 0.5));
  }
  EXPECT_LT(worst, 0.35);  // only the filter's start-up transient, no 2 pi / dt spike
}

TEST(MocapEstimator, LongGapRestartsTheDerivative) {
  MocapEstimator est;
  const double a[3] = {0, 0, 1}, b[3] = {3, 0, 1}, rpy[3] = {0, 0, 0};
  est.update(0.0, a, rpy);
  EXPECT_EQ(est.update(2.0, b, rpy), MocapEstimator::Result::kRestarted);
  double X[12];
  est.state(X);
  EXPECT_EQ(X[6], 0.0);
  EXPECT_EQ(X[0], 3.0);
}
