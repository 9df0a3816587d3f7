// Conversions between the controller core's types and its messages, written
// once for the node (publishing) and replay (reading a bag back).
#pragma once

#include <aurora_msgs/Control.h>
#include <aurora_msgs/DroneState.h>

#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/task/task.h"
#include "aurora_sim/ros/conversions.h"

namespace aurora_control {

inline StateSample sampleFromMsg(const aurora_msgs::DroneState& msg) {
  StateSample sample;
  sample.step = static_cast<long>(msg.step);
  sample.stamp_ns = static_cast<int64_t>(msg.header.stamp.toNSec());
  aurora_sim::stateFromMsg(msg, sample.X, aurora_sim::kMaxStates);  // a vehicle's further states from extra
  return sample;
}

// The reference of a cycle into Control's desired_* fields, and back.
inline void referenceToMsg(const Reference<double>& ref, aurora_msgs::Control& c) {
  c.desired_position.x = ref.pos[0], c.desired_position.y = ref.pos[1], c.desired_position.z = ref.pos[2];
  c.desired_velocity.x = ref.vel[0], c.desired_velocity.y = ref.vel[1], c.desired_velocity.z = ref.vel[2];
  c.desired_acceleration.x = ref.acc[0], c.desired_acceleration.y = ref.acc[1], c.desired_acceleration.z = ref.acc[2];
  c.desired_yaw = ref.yaw;
  c.desired_yaw_rate = ref.yaw_rate;
  c.desired_yaw_acceleration = ref.yaw_acc;
}

inline Reference<double> referenceFromMsg(const aurora_msgs::Control& c) {
  Reference<double> r;
  r.pos[0] = c.desired_position.x, r.pos[1] = c.desired_position.y, r.pos[2] = c.desired_position.z;
  r.vel[0] = c.desired_velocity.x, r.vel[1] = c.desired_velocity.y, r.vel[2] = c.desired_velocity.z;
  r.acc[0] = c.desired_acceleration.x, r.acc[1] = c.desired_acceleration.y, r.acc[2] = c.desired_acceleration.z;
  r.yaw = c.desired_yaw;
  r.yaw_rate = c.desired_yaw_rate;
  r.yaw_acc = c.desired_yaw_acceleration;
  return r;
}

}  // namespace aurora_control
