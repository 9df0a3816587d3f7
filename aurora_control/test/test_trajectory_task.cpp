// Trajectory tasks: velocity, acceleration, yaw rate and yaw acceleration
// equal the central differences of position, velocity, yaw and yaw rate.
// Central differences with h = 1e-4 s err by about h^2/6 times the next
// derivative (here below 1e-6); the tolerance is 1e-6 in the same units.
#include <gtest/gtest.h>

#include <cmath>

#include "aurora_control/task/trajectory_task.h"

using namespace aurora_control;

namespace {

TrajectoryTask<double> circle(bool along) {
  TrajectoryTask<double> t;
  t.kind = TrajectoryKind::kCircle;
  t.centre[0] = 0.5, t.centre[1] = -0.2, t.centre[2] = 1.5;
  t.size[0] = 1.2;
  t.period = 12.0;
  t.laps = 2;
  t.yaw_along_path = along;
  t.yaw = 0.3;
  return t;
}

TrajectoryTask<double> lemniscate(bool along) {
  TrajectoryTask<double> t = circle(along);
  t.kind = TrajectoryKind::kLemniscate;
  t.size[0] = 1.5, t.size[1] = 0.6;
  return t;
}

double yawDiff(double a, double b) { return std::remainder(a - b, 2 * aurora_common::kPi); }

void expectConsistentDerivatives(const TrajectoryTask<double>& task) {
  const double h = 1e-4, tol = 1e-6;
  for (double t = 0.05; t < task.duration() - 0.05; t += 0.37) {
    const Reference<double> r = task.at(t), a = task.at(t - h), b = task.at(t + h);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r.vel[i], (b.pos[i] - a.pos[i]) / (2 * h), tol) << "t " << t << " axis " << i;
      EXPECT_NEAR(r.acc[i], (b.vel[i] - a.vel[i]) / (2 * h), tol) << "t " << t << " axis " << i;
    }
    EXPECT_NEAR(r.yaw_rate, yawDiff(b.yaw, a.yaw) / (2 * h), tol) << "t " << t;
    EXPECT_NEAR(r.yaw_acc, (b.yaw_rate - a.yaw_rate) / (2 * h), tol) << "t " << t;
  }
}

}  // namespace

TEST(TrajectoryTask, CircleDerivatives) {
  expectConsistentDerivatives(circle(false));
  expectConsistentDerivatives(circle(true));
}

TEST(TrajectoryTask, LemniscateDerivatives) {
  expectConsistentDerivatives(lemniscate(false));
  expectConsistentDerivatives(lemniscate(true));
  TrajectoryTask<double> fast_x = lemniscate(false);
  fast_x.fast_x = true;
  expectConsistentDerivatives(fast_x);
}

// The Bebop 2's figure-eight (docs/bebop2.md): x goes twice per lap.
TEST(TrajectoryTask, ALemniscateWhoseXGoesTwicePerLap) {
  TrajectoryTask<double> t = lemniscate(false);
  t.size[0] = 0.75, t.size[1] = 1.25, t.fast_x = true;
  const double w = 2 * aurora_common::kPi / t.period;
  for (double s : {0.0, 1.3, 4.7, 11.0}) {
    const Reference<double> r = t.at(s);
    EXPECT_NEAR(r.pos[0], t.centre[0] + 0.75 * std::sin(2 * w * s), 1e-15) << s;
    EXPECT_NEAR(r.pos[1], t.centre[1] + 1.25 * std::sin(w * s), 1e-15) << s;
    EXPECT_NEAR(r.vel[0], 1.5 * w * std::cos(2 * w * s), 1e-15) << s;
    EXPECT_NEAR(r.vel[1], 1.25 * w * std::cos(w * s), 1e-15) << s;
  }
}

TEST(TrajectoryTask, ShapeAndEnd) {
  const auto c = circle(true);
  const Reference<double> start = c.at(0.0), quarter = c.at(3.0);
  EXPECT_NEAR(start.pos[0], 0.5 + 1.2, 1e-12);
  EXPECT_NEAR(quarter.pos[1], -0.2 + 1.2, 1e-12);
  EXPECT_NEAR(quarter.pos[2], 1.5, 0.0);
  EXPECT_NEAR(start.yaw, aurora_common::kPi / 2, 1e-12);  // heading along +y at the start
  EXPECT_NEAR(start.yaw_rate, 2 * aurora_common::kPi / 12.0, 1e-12);
  // After two laps: the start point, at rest.
  const Reference<double> after = c.at(30.0);
  EXPECT_NEAR(after.pos[0], 0.5 + 1.2, 1e-12);
  EXPECT_NEAR(after.pos[1], -0.2, 1e-12);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(after.vel[i], 0.0);
    EXPECT_EQ(after.acc[i], 0.0);
  }
  EXPECT_EQ(after.yaw_rate, 0.0);
  const auto l = lemniscate(false);
  EXPECT_NEAR(l.at(3.0).pos[0], 0.5 + 1.5, 1e-12);  // a quarter period: the x extreme
  EXPECT_NEAR(l.at(1.5).pos[1], -0.2 + 0.6, 1e-12);  // an eighth: the y extreme
  EXPECT_EQ(l.at(4.0).yaw, 0.3);
}

TEST(TrajectoryTask, FloatInstantiation) {
  TrajectoryTask<float> t;
  t.kind = TrajectoryKind::kLemniscate;
  t.centre[0] = t.centre[1] = 0.0f, t.centre[2] = 1.0f;
  t.size[0] = 1.0f, t.size[1] = 0.5f;
  t.period = 10.0f;
  t.laps = 1;
  t.yaw_along_path = true;
  t.yaw = 0.0f;
  const Reference<float> r = t.at(2.5f);
  EXPECT_NEAR(r.pos[0], 1.0f, 1e-5f);
}
