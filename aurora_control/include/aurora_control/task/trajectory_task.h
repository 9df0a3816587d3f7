// Tasks that move: a circle and a figure-eight (lemniscate of Gerono), each
// giving the desired position, velocity, acceleration and yaw at any time,
// in closed form (no numerical differentiation). The PD law uses position,
// velocity and acceleration (a = xdd_d + Kd tanh(xd_dot - x_dot) + Kp
// tanh(xd - x)); the underactuated law takes velocity and acceleration as its
// feed-forward. Templated and branch-free in t (t may be a SIMD batch of
// lanes at different times); the kind is the same for every lane.
//
// With w = 2 pi / period and phase s = w t:
//   circle:      p = c + r [cos s, sin s, 0]
//   lemniscate:  p = c + [ax sin s, ay sin 2s, 0]  (fast_x: [ax sin 2s, ay sin s, 0])
// at the height c_z; yaw fixed, or along the path: psi = atan2(vy, vx).
// After laps * period the reference holds the end point at rest.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

enum class TrajectoryKind : int { kCircle = 0, kLemniscate = 1 };

// What a task asks for at one time (world frame).
template <typename T>
struct Reference {
  T pos[3];    // [m]
  T vel[3];    // [m/s]
  T acc[3];    // [m/s^2]
  T yaw;       // [rad], in [-pi, pi]
  T yaw_rate;  // [rad/s]
  T yaw_acc;   // [rad/s^2]
};

template <typename T>
struct TrajectoryTask {
  TrajectoryKind kind = TrajectoryKind::kCircle;
  T centre[3];         // [m]: x, y of the centre and the flight height
  T size[2];           // circle: radius in size[0]; lemniscate: amplitudes ax, ay [m]
  bool fast_x = false;  // lemniscate: x, not y, goes twice per lap (the Bebop 2's figure-eight)
  T period;            // [s] per lap
  int laps = 1;
  bool yaw_along_path = false;
  T yaw;               // [rad] when not along the path

  AURORA_HD T duration() const { return period * T(laps); }

  // The reference at task time t [s] (t >= 0).
  template <typename Time>
  AURORA_HD Reference<Time> at(const Time& t) const {
    using aurora_common::select;
    using std::atan2;
    const Time w = Time(T(2.0 * aurora_common::kPi) / period);
    const auto moving = t < Time(duration());
    // Past the end: the end point (a whole number of laps: the phase is 0).
    const Time s = select(moving, w * t, Time(0));
    const Time on = select(moving, Time(1), Time(0));  // 0: at rest
    Time d[4][2];  // derivatives 0..3 of the in-plane offset (x, y)
    offsetDerivatives(s, w, d);
    Reference<Time> r;
    for (int i = 0; i < 2; ++i) {
      r.pos[i] = Time(centre[i]) + d[0][i];
      r.vel[i] = on * d[1][i];
      r.acc[i] = on * d[2][i];
    }
    r.pos[2] = Time(centre[2]);
    r.vel[2] = r.acc[2] = Time(0);
    if (!yaw_along_path) {
      r.yaw = Time(yaw);
      r.yaw_rate = r.yaw_acc = Time(0);
      return r;
    }
    // psi = atan2(vy, vx); its rate and acceleration from the derivatives
    // (the path's speed never vanishes while moving). At rest: the last heading.
    const Time vx = d[1][0], vy = d[1][1], ax = d[2][0], ay = d[2][1];
    const Time v2 = vx * vx + vy * vy;
    const Time cross = vx * ay - vy * ax;
    r.yaw = atan2(vy, vx);
    r.yaw_rate = on * (cross / v2);
    r.yaw_acc = on * ((vx * d[3][1] - vy * d[3][0]) / v2 -
                      Time(2) * cross * (vx * ax + vy * ay) / (v2 * v2));
    return r;
  }

 private:
  template <typename Time>
  AURORA_HD void offsetDerivatives(const Time& s, const Time& w, Time d[4][2]) const {
    Time s1, c1, s2, c2;
    aurora_common::sinCos(s, s1, c1);
    aurora_common::sinCos(Time(2) * s, s2, c2);
    const Time w2 = w * w, w3 = w2 * w;
    if (kind == TrajectoryKind::kCircle) {
      const Time r = Time(size[0]);
      d[0][0] = r * c1, d[0][1] = r * s1;
      d[1][0] = -r * w * s1, d[1][1] = r * w * c1;
      d[2][0] = -r * w2 * c1, d[2][1] = -r * w2 * s1;
      d[3][0] = r * w3 * s1, d[3][1] = -r * w3 * c1;
    } else {
      // The slow axis goes once per lap, the fast one twice.
      const Time a_slow = Time(size[fast_x ? 1 : 0]), a_fast = Time(size[fast_x ? 0 : 1]);
      const Time slow[4] = {a_slow * s1, a_slow * w * c1, -a_slow * w2 * s1, -a_slow * w3 * c1};
      const Time fast[4] = {a_fast * s2, Time(2) * a_fast * w * c2, -Time(4) * a_fast * w2 * s2,
                            -Time(8) * a_fast * w3 * c2};
      for (int n = 0; n < 4; ++n) d[n][0] = fast_x ? fast[n] : slow[n], d[n][1] = fast_x ? slow[n] : fast[n];
    }
  }
};

}  // namespace aurora_control
