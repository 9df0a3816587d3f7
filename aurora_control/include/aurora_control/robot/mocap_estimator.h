// State estimate from motion-capture poses (ROS-free): position and attitude
// from the pose; velocities and Euler-angle rates by filtered
// differentiation.
//
// Filter (documented for users comparing with their own): for each accepted
// pose at time t with dt = t - t_prev > 0, the raw derivative
// r = (p - p_prev) / dt (angles: the difference wrapped into (-pi, pi], so a
// yaw crossing +-pi gives no spike) is passed through a first-order low-pass
//     v <- v + a (r - v),   a = dt / (dt + tau),   tau = 1 / (2 pi f_c),
// the discrete form of an RC filter with cutoff f_c that stays correct for
// irregular dt (dropped samples just make one dt longer). A pose whose stamp
// is not newer than the last accepted one (duplicate or out of order) is
// ignored, so dt is never zero and no NaN can appear. After a gap longer
// than `max_gap` the derivative restarts from zero rather than differencing
// across the gap.
#pragma once

#include <angles/angles.h>

#include <cmath>

#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_control {

struct MocapFilterConfig {
  double velocity_cutoff_hz = 4.0;  // f_c of the linear-velocity filter
  double rate_cutoff_hz = 4.0;      // f_c of the Euler-rate filter
  double max_gap = 0.5;             // [s] longer gaps restart the derivative
};

class MocapEstimator {
 public:
  explicit MocapEstimator(const MocapFilterConfig& cfg = MocapFilterConfig()) : cfg_(cfg) {}

  enum class Result { kAccepted, kFirst, kNotNewer, kRestarted };

  // pose: position [m] and roll, pitch, yaw [rad] in the world frame at time t [s].
  Result update(double t, const double pos[3], const double rpy[3]) {
    if (!initialized_) {
      store(t, pos, rpy);
      initialized_ = true;
      return Result::kFirst;
    }
    const double dt = t - t_;
    if (!(dt > 0.0)) return Result::kNotNewer;  // duplicate or reordered stamp (or NaN)
    if (dt > cfg_.max_gap) {
      for (int i = 0; i < 3; ++i) vel_[i] = rate_[i] = 0.0;
      store(t, pos, rpy);
      return Result::kRestarted;
    }
    const double av = dt / (dt + 1.0 / (2.0 * aurora_common::kPi * cfg_.velocity_cutoff_hz));
    const double ar = dt / (dt + 1.0 / (2.0 * aurora_common::kPi * cfg_.rate_cutoff_hz));
    for (int i = 0; i < 3; ++i) {
      vel_[i] += av * ((pos[i] - pos_[i]) / dt - vel_[i]);
      rate_[i] += ar * (angles::normalize_angle(rpy[i] - rpy_[i]) / dt - rate_[i]);
    }
    store(t, pos, rpy);
    return Result::kAccepted;
  }

  bool initialized() const { return initialized_; }
  double stamp() const { return t_; }

  // X = [x y z phi theta psi xdot ydot zdot phidot thetadot psidot].
  void state(double X[aurora_sim::kStateSize]) const {
    for (int i = 0; i < 3; ++i) {
      X[aurora_sim::kX + i] = pos_[i];
      X[aurora_sim::kRoll + i] = rpy_[i];
      X[aurora_sim::kVx + i] = vel_[i];
      X[aurora_sim::kRollRate + i] = rate_[i];
    }
  }

 private:
  void store(double t, const double pos[3], const double rpy[3]) {
    t_ = t;
    for (int i = 0; i < 3; ++i) {
      pos_[i] = pos[i];
      rpy_[i] = rpy[i];
    }
  }

  MocapFilterConfig cfg_;
  bool initialized_ = false;
  double t_ = 0.0;
  double pos_[3] = {0, 0, 0}, rpy_[3] = {0, 0, 0};
  double vel_[3] = {0, 0, 0}, rate_[3] = {0, 0, 0};
};

}  // namespace aurora_control
