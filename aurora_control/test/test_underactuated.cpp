// The underactuated 12-gain controller against the spec's self-check table
// (default gains, Xd = (0,0,1) while t <= 10, (1,0,1) while 10 < t <= 20,
// then (0,0,1); controller on the current state, then one model step).
#include <gtest/gtest.h>

#include <cmath>

#include "aurora_control/underactuated_controller.h"

using namespace aurora_control;

TEST(UnderactuatedController, ReproducesTheSpecTable) {
  const auto p = aurora_sim::referenceArdrone2Params();
  UnderactuatedController controller(p);
  aurora_sim::ArdroneState<double> s;
  s.reset();
  struct Row {
    int step;
    double x, z, theta, vx, vz;
  } rows[] = {{600, 0.986309038461, 1.00000052301, 0.00173531590712, -0.00561991011557, -8.35828503772e-08},
              {1200, 0.000264175953617, 1.00000001003, 2.68299708593e-05, -0.00192469883673, -1.85686813483e-08}};
  double t = 0.0;  // time at the start of the iteration, by repeated addition of Ts
  int row = 0;
  for (int k = 1; k <= 1200; ++k) {
    double Xd[aurora_sim::kStateSize] = {};
    Xd[aurora_sim::kZ] = 1.0;
    if (t > 10.0 && t <= 20.0) Xd[aurora_sim::kX] = 1.0;
    const double acc[6] = {0, 0, 0, 0, 0, 0};
    double U[4];
    controller.compute(Xd, acc, s.X, U);
    aurora_sim::ardroneStep(p, s, U, aurora_sim::Disturbance<double>::zero());
    t += p.Ts;
    if (k == rows[row].step) {
      const Row& r = rows[row++];
      // The spec prints 12 significant digits; ours agree to about 1e-10.
      EXPECT_NEAR(s.X[aurora_sim::kX], r.x, 1e-8 * std::fabs(r.x)) << "step " << k;
      EXPECT_NEAR(s.X[aurora_sim::kY], 0.0, 1e-12) << "step " << k;
      EXPECT_NEAR(s.X[aurora_sim::kZ], r.z, 1e-8 * r.z) << "step " << k;
      EXPECT_NEAR(s.X[aurora_sim::kPitch], r.theta, 1e-8 * std::fabs(r.theta)) << "step " << k;
      EXPECT_NEAR(s.X[aurora_sim::kVx], r.vx, 1e-8 * std::fabs(r.vx)) << "step " << k;
      EXPECT_NEAR(s.X[aurora_sim::kVz], r.vz, 1e-14) << "step " << k;  // ~1e-8 m/s: absolute
    }
  }
  EXPECT_EQ(row, 2);
}
