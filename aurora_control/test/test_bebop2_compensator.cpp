// The Bebop 2's compensator (docs/bebop2.md, eq. B2) against the values the
// spec computed with AuRoRA's own code, its command hold at a slower rate,
// and the spec's waypoint scenario flown on the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "aurora_control/law/bebop2/bebop2_compensator.h"

namespace {

using aurora_control::Bebop2Compensator;
using aurora_control::Reference;
using aurora_sim::Bebop2;

Reference<double> reference(const double pos[3], double yaw, const double vel[3], double yaw_rate) {
  Reference<double> r{};
  for (int i = 0; i < 3; ++i) r.pos[i] = pos[i], r.vel[i] = vel[i], r.acc[i] = 0.0;
  r.yaw = yaw, r.yaw_rate = yaw_rate, r.yaw_acc = 0.0;
  return r;
}

void expectNear(const double* got, const double* want, int n, const char* what) {
  for (int i = 0; i < n; ++i) EXPECT_NEAR(got[i], want[i], 1e-13 * (1.0 + std::fabs(want[i]))) << what << " " << i;
}

}  // namespace

// The spec's controller call: state (1, -2, 1, yaw 3.1) with rates (0.4,
// -0.3, 0.1, 0.2); desired (0.5, -1.5, 1.5, -3.0) and (0.1, 0.2, 0, 0.1); held
// Ur (0.2, 0.1, 0.3, -0.1); default gains at 30 Hz (the yaw error -6.1 wraps).
TEST(Bebop2Compensator, OneCallAsTheOriginal) {
  double X[aurora_sim::kStateSize] = {};
  X[aurora_sim::kX] = 1.0, X[aurora_sim::kY] = -2.0, X[aurora_sim::kZ] = 1.0, X[aurora_sim::kYaw] = 3.1;
  X[aurora_sim::kVx] = 0.4, X[aurora_sim::kVy] = -0.3, X[aurora_sim::kVz] = 0.1, X[aurora_sim::kYawRate] = 0.2;
  const double pos[3] = {0.5, -1.5, 1.5}, vel[3] = {0.1, 0.2, 0.0};
  Bebop2Compensator::Memory<double> m;
  m.reset();
  const double Ur[4] = {0.2, 0.1, 0.3, -0.1};
  for (int i = 0; i < 4; ++i) m.Ur[i] = Ur[i];
  double U[4], err[3];
  Bebop2Compensator::command(aurora_sim::referenceBebop2Params(), aurora_control::CompensatorGains<double>::defaults(),
                             m, reference(pos, -3.0, vel, 0.1), X, U, err);
  const double want_Ur[4] = {-0.8242343145200195, 1.1242343145200195, 1.3863514717800292, 0.50209766583338089};
  const double want_U[4] = {40.950362701024126, -38.447201382556536, 8.9021877969250962, 2.0826720701725803};
  expectNear(m.Ur, want_Ur, 4, "Ur");
  expectNear(U, want_U, 4, "U");
  const double want_err[3] = {-0.5, 0.5, 0.5};
  expectNear(err, want_err, 3, "position error");
}

// The waypoint scenario's first step at 30 Hz, unclamped: the law, then
// one model step.
TEST(Bebop2Compensator, FirstStepOfTheWaypointScenario) {
  Bebop2::State<double> s;
  s.reset();
  Bebop2Compensator::Memory<double> m;
  m.reset();
  const double pos[3] = {0.0, 0.0, 0.5}, still[3] = {0.0, 0.0, 0.0};
  double U[4], err[3];
  const Bebop2::Params<double> p = aurora_sim::referenceBebop2Params();
  Bebop2Compensator::command(p, aurora_control::CompensatorGains<double>::defaults(), m,
                             reference(pos, 0.0, still, 0.0), s.X, U, err);
  const double want_Ur[4] = {0.0, 0.0, -0.73475598721112734, 0.0};
  const double want_U[4] = {0.0, 0.0, -5.8913868868668304, 0.0};
  expectNear(m.Ur, want_Ur, 4, "Ur");
  expectNear(U, want_U, 4, "U");
  Bebop2::step(p, s, U);
  EXPECT_NEAR(s.X[aurora_sim::kZ], 0.72403862178520684, 1e-15);
  EXPECT_NEAR(s.X[aurora_sim::kVz], -0.77884134644379499, 1e-15);
}

// At 5 Hz (period 6 model steps) the law runs on calls 0, 6, 12, ... with
// dt = 6 Ts and holds its command in between, as the driver holds cmd_vel.
TEST(Bebop2Compensator, ASlowerRateHoldsTheCommand) {
  auto g = aurora_control::CompensatorGains<double>::defaults();
  g.period_steps = 6;
  Bebop2::Params<double> p = aurora_sim::referenceBebop2Params();
  Bebop2::State<double> s;
  s.reset();
  Bebop2Compensator::Memory<double> m;
  m.reset();
  const double pos[3] = {0.5, 0.5, 1.5}, still[3] = {0.0, 0.0, 0.0};
  double first[4], U[4], err[3];
  for (int k = 0; k < 7; ++k) {
    Bebop2Compensator::command(p, g, m, reference(pos, 0.0, still, 0.0), s.X, U, err);
    if (k == 0) for (int i = 0; i < 4; ++i) first[i] = U[i];
    if (k > 0 && k < 6) for (int i = 0; i < 4; ++i) EXPECT_EQ(U[i], first[i]) << k << " " << i;
    if (k == 6) EXPECT_NE(U[0], first[0]);
    Bebop2::step(p, s, U);
  }
  // Call 0 as one call of period 0.2 s: dUcw = Ucw / 0.2.
  const double Ucw_z = 3.0 * std::tanh(1.0 * (1.5 - 0.75));
  EXPECT_NEAR(first[aurora_sim::kBebopZ], (Ucw_z / (6.0 * p.Ts) + 1.8 * Ucw_z) / p.Ku[aurora_sim::kBebopZ], 1e-12);
}

// The spec's waypoints with yaw targets (through the +-pi wrap), each 4 s,
// at 30 Hz and 5 Hz, unclamped and clamped: the drone reaches each one.
TEST(Bebop2Compensator, FliesTheWaypointScenario) {
  const double pi = aurora_common::kPi;
  const double wp[6][4] = {{0, 0, 0.5, 0},          {0.5, 0.5, 1.5, pi / 2}, {-0.5, 0.5, 1.5, pi},
                           {-0.5, -0.5, 1.5, -pi / 2}, {0.5, -0.5, 1.5, 0},   {0, 0, 1.5, 0}};
  const Bebop2::Params<double> p = aurora_sim::referenceBebop2Params();
  for (double period : {1.0, 6.0}) {
    for (bool clamp : {false, true}) {
      auto g = aurora_control::CompensatorGains<double>::defaults();
      g.period_steps = period;
      Bebop2::State<double> s;
      s.reset();
      Bebop2Compensator::Memory<double> m;
      m.reset();
      for (long k = 0; k < 900; ++k) {
        const double* w = wp[std::min<long>(k / 120, 5)];
        const double still[3] = {0, 0, 0};
        double U[4], err[3];
        Bebop2Compensator::command(p, g, m, reference(w, w[3], still, 0.0), s.X, U, err);
        for (int i = 0; i < 4; ++i) U[i] = clamp ? Bebop2::limitInput(p, i, U[i]) : U[i];
        Bebop2::step(p, s, U);
        if (k % 120 == 119) {  // the end of a waypoint's 4 s
          const double d = std::hypot(std::hypot(s.X[0] - w[0], s.X[1] - w[1]), s.X[2] - w[2]);
          const double yaw = std::remainder(s.X[aurora_sim::kYaw] - w[3], 2 * pi);
          EXPECT_LT(d, 0.1) << "period " << period << " clamp " << clamp << " waypoint " << k / 120;
          EXPECT_LT(std::fabs(yaw), 0.05) << "period " << period << " clamp " << clamp << " waypoint " << k / 120;
        }
      }
    }
  }
}
