// Conversions between the ROS messages and the model's plain arrays. The only
// header of aurora_sim/include that needs ROS; the core headers do not.
#pragma once

#include <aurora_msgs/DroneState.h>
#include <geometry_msgs/Twist.h>

#include "aurora_sim/command_mapping.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

inline void stateToMsg(const double X[kStateSize], aurora_msgs::DroneState& msg) {
  msg.position.x = X[kX]; msg.position.y = X[kY]; msg.position.z = X[kZ];
  msg.attitude.x = X[kRoll]; msg.attitude.y = X[kPitch]; msg.attitude.z = X[kYaw];
  msg.velocity.x = X[kVx]; msg.velocity.y = X[kVy]; msg.velocity.z = X[kVz];
  msg.attitude_rate.x = X[kRollRate]; msg.attitude_rate.y = X[kPitchRate];
  msg.attitude_rate.z = X[kYawRate];
}

inline void stateFromMsg(const aurora_msgs::DroneState& msg, double X[kStateSize]) {
  X[kX] = msg.position.x; X[kY] = msg.position.y; X[kZ] = msg.position.z;
  X[kRoll] = msg.attitude.x; X[kPitch] = msg.attitude.y; X[kYaw] = msg.attitude.z;
  X[kVx] = msg.velocity.x; X[kVy] = msg.velocity.y; X[kVz] = msg.velocity.z;
  X[kRollRate] = msg.attitude_rate.x; X[kPitchRate] = msg.attitude_rate.y;
  X[kYawRate] = msg.attitude_rate.z;
}

// A state of `states` entries (a vehicle's kStates, >= 12): the 12 in
// their fields, the rest in `extra`; and back (missing extras read 0: a
// source that does not know them, such as motion capture).
inline void stateToMsg(const double* X, int states, aurora_msgs::DroneState& msg) {
  stateToMsg(X, msg);
  msg.extra.assign(X + kStateSize, X + states);
}

inline void stateFromMsg(const aurora_msgs::DroneState& msg, double* X, int states) {
  stateFromMsg(msg, X);
  for (int i = kStateSize; i < states; ++i) {
    const size_t j = static_cast<size_t>(i - kStateSize);
    X[i] = j < msg.extra.size() ? msg.extra[j] : 0.0;
  }
}

inline TwistCommand twistCommandFromMsg(const geometry_msgs::Twist& t) {
  return TwistCommand{t.linear.x, t.linear.y, t.linear.z, t.angular.z};
}

inline geometry_msgs::Twist twistMsgOf(const TwistCommand& c) {
  geometry_msgs::Twist t;
  t.linear.x = c.linear_x; t.linear.y = c.linear_y; t.linear.z = c.linear_z;
  t.angular.z = c.angular_z;
  return t;
}

// Vehicle's command U as its driver's cmd_vel (Vehicle::toDriver).
template <class Vehicle>
geometry_msgs::Twist twistMsgFromModelCommand(const double U[Vehicle::kInputs]) {
  return twistMsgOf(Vehicle::toDriver(U));
}

}  // namespace aurora_sim
