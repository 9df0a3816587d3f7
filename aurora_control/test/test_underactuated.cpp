// The templated underactuated law (underactuated_law.h) against the spec's
// self-check table and against the direct Eigen/SVD version of the spec's
// steps (underactuated_svd_reference.h, test-only).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "aurora_control/law/ardrone2/underactuated_law.h"
#include "underactuated_svd_reference.h"

using namespace aurora_control;
using aurora_sim::kStateSize;

namespace {

// Desired position and yaw of a scenario at time t.
struct Target {
  double x, y, z, yaw;
};
using Scenario = Target (*)(double t);

// The spec's: (0,0,1) while t <= 10, (1,0,1) while 10 < t <= 20, then (0,0,1).
Target specScenario(double t) { return {t > 10.0 && t <= 20.0 ? 1.0 : 0.0, 0.0, 1.0, 0.0}; }

// Every axis and the yaw error wrap: a lateral move, a climb and yaw steps
// across +-pi (the desired yaw jumps from 3 to -3 rad).
Target allAxesScenario(double t) {
  if (t <= 8.0) return {0.5, -0.8, 1.4, 0.6};
  if (t <= 20.0) return {-0.6, 0.7, 0.9, 3.0};
  return {0.2, 0.3, 1.2, -3.0};
}

struct Run {
  aurora_sim::ArdroneState<double> s;
  double U[4];
};

void desired(Scenario f, double t, double Xd[kStateSize]) {
  for (int i = 0; i < kStateSize; ++i) Xd[i] = 0.0;
  const Target g = f(t);
  Xd[aurora_sim::kX] = g.x, Xd[aurora_sim::kY] = g.y, Xd[aurora_sim::kZ] = g.z;
  Xd[aurora_sim::kYaw] = g.yaw;
}

double relDiff(double a, double b) { return std::fabs(a - b) / std::max(1.0, std::fabs(b)); }

}  // namespace

TEST(UnderactuatedLaw, ReproducesTheSpecTable) {
  const auto p = aurora_sim::referenceArdrone2Params();
  const auto g = UnderactuatedGains<double>::defaults();
  UnderactuatedMemory<double> mem;
  mem.reset();
  aurora_sim::ArdroneState<double> s;
  s.reset();
  struct Row {
    int step;
    double x, z, theta, vx, vz;
  } rows[] = {{600, 0.986309038461, 1.00000052301, 0.00173531590712, -0.00561991011557, -8.35828503772e-08},
              {1200, 0.000264175953617, 1.00000001003, 2.68299708593e-05, -0.00192469883673, -1.85686813483e-08}};
  double t = 0.0;  // time at the start of the iteration, by repeated addition of Ts
  int row = 0;
  const double acc[6] = {0, 0, 0, 0, 0, 0};
  for (int k = 1; k <= 1200; ++k) {
    double Xd[kStateSize], U[4];
    desired(specScenario, t, Xd);
    underactuatedCommand(p, g, mem, Xd, acc, s.X, U);
    aurora_sim::ardroneStep(p, s, U, aurora_sim::Disturbance<double>::zero());
    t += p.Ts;
    if (k != rows[row].step) continue;
    const Row& r = rows[row++];
    // 1e-10 relative for every entry of at least 1e-3 (m, m/s, rad); below
    // that, 1e-13 absolute. Entries such as vz ~ 1e-8 m/s are residuals of
    // a computation at the 1 m scale: their trailing digits are rounding
    // noise, and the direct SVD version differs from them by 5e-9 relative.
    const auto tol = [](double ref) { return 1e-10 * std::max(std::fabs(ref), 1e-3); };
    EXPECT_NEAR(s.X[aurora_sim::kX], r.x, tol(r.x)) << "step " << k;
    EXPECT_NEAR(s.X[aurora_sim::kY], 0.0, 1e-13) << "step " << k;
    EXPECT_NEAR(s.X[aurora_sim::kZ], r.z, tol(r.z)) << "step " << k;
    EXPECT_NEAR(s.X[aurora_sim::kPitch], r.theta, tol(r.theta)) << "step " << k;
    EXPECT_NEAR(s.X[aurora_sim::kVx], r.vx, tol(r.vx)) << "step " << k;
    EXPECT_NEAR(s.X[aurora_sim::kVz], r.vz, tol(r.vz)) << "step " << k;
  }
  EXPECT_EQ(row, 2);
}

// Both versions fly their own model for 40 s (1200 steps); every command and
// every state agree to 1e-12 (relative, absolute below 1).
void expectSameAsSvd(Scenario scenario, const double acc[6]) {
  const auto p = aurora_sim::referenceArdrone2Params();
  const auto g = UnderactuatedGains<double>::defaults();
  UnderactuatedMemory<double> mem;
  mem.reset();
  UnderactuatedSvdReference svd(p);
  Run law, ref;
  law.s.reset();
  ref.s.reset();
  double worst_u = 0.0, worst_x = 0.0, t = 0.0;
  for (int k = 1; k <= 1200; ++k, t += p.Ts) {
    double Xd[kStateSize];
    desired(scenario, t, Xd);
    underactuatedCommand(p, g, mem, Xd, acc, law.s.X, law.U);
    svd.compute(Xd, acc, ref.s.X, ref.U);
    for (int i = 0; i < 4; ++i) worst_u = std::max(worst_u, relDiff(law.U[i], ref.U[i]));
    aurora_sim::ardroneStep(p, law.s, law.U, aurora_sim::Disturbance<double>::zero());
    aurora_sim::ardroneStep(p, ref.s, ref.U, aurora_sim::Disturbance<double>::zero());
    for (int i = 0; i < kStateSize; ++i) worst_x = std::max(worst_x, relDiff(law.s.X[i], ref.s.X[i]));
  }
  std::printf("closed-form vs SVD pinv over 40 s: largest command difference %.3g, state %.3g\n",
              worst_u, worst_x);
  EXPECT_LE(worst_u, 1e-12);
  EXPECT_LE(worst_x, 1e-12);
  // The flight went somewhere (the comparison is not of two hovering drones).
  const Target end = scenario(t);
  EXPECT_NEAR(law.s.X[aurora_sim::kZ], end.z, 0.05);
}

TEST(UnderactuatedLaw, AgreesWithTheSvdVersionOnTheSpecFlight) {
  const double acc[6] = {0, 0, 0, 0, 0, 0};
  expectSameAsSvd(specScenario, acc);
}

TEST(UnderactuatedLaw, AgreesWithTheSvdVersionOnAllAxesAndFeedForward) {
  const double acc[6] = {0.05, -0.04, 0.02, 0.0, 0.0, 0.01};
  expectSameAsSvd(allAxesScenario, acc);
}

TEST(UnderactuatedLaw, ErrorWrapFollowsTheReference) {
  using aurora_common::kPi;
  using aurora_common::wrapErrorAsReference;
  EXPECT_DOUBLE_EQ(wrapErrorAsReference(0.5), 0.5);
  EXPECT_DOUBLE_EQ(wrapErrorAsReference(6.0), 6.0 - 2 * kPi);
  // Below -pi the reference subtracts 2 pi, then adds it back.
  EXPECT_EQ(wrapErrorAsReference(-6.0), (-6.0 - 2 * kPi) + 2 * kPi);
}

TEST(UnderactuatedLaw, FloatInstantiationFliesTheSpecFlight) {
  // The same template in single precision (the sweep's float backend).
  const auto pd = aurora_sim::referenceArdrone2Params();
  const auto p = pd.cast<float>();
  const auto g = UnderactuatedGains<float>::defaults();
  UnderactuatedMemory<float> mem;
  mem.reset();
  aurora_sim::ArdroneState<float> s;
  s.reset();
  const float acc[6] = {0, 0, 0, 0, 0, 0};
  double t = 0.0;
  for (int k = 1; k <= 600; ++k, t += pd.Ts) {
    float Xd[kStateSize] = {};
    Xd[aurora_sim::kZ] = 1.0f;
    if (t > 10.0) Xd[aurora_sim::kX] = 1.0f;
    float U[4];
    underactuatedCommand(p, g, mem, Xd, acc, s.X, U);
    aurora_sim::ardroneStep(p, s, U, aurora_sim::Disturbance<float>::zero());
  }
  EXPECT_NEAR(s.X[aurora_sim::kX], 0.986309038461, 1e-3);
  EXPECT_NEAR(s.X[aurora_sim::kZ], 1.0, 1e-3);
}
