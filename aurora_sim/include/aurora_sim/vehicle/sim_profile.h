// What the simulator node does with a vehicle beyond its model
// (docs/simulation.md, "Vehicles"): how it takes off and lands (the input
// that climbs; none for a ground robot), where it starts, which odometry
// topic its real driver publishes, and where its body is (a Pioneer's
// centre lies a behind the control point its state gives). ROS-free. The
// concept and a drone's default; each vehicle's profile lives in its folder.
#pragma once

#include <algorithm>
#include <cmath>

#include "aurora_common/rotation.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

// A drone: climbs with its vertical input, starts in the air above its
// start point, publishes odometry as its driver does on `odom`, its body at
// its state's position.
template <class Vehicle, int ClimbInput>
struct DroneSimProfile {
  static constexpr int kClimbInput = ClimbInput;
  static constexpr bool kFlies = true;
  static const char* odomTopic() { return "odom"; }  // the drones' drivers' odometry (docs/simulation.md, "Vehicles")
  static void limitSpeed(double*, double, double) {}  // a ground robot's limits (a drone's are its clamp)

  // At rest at (x, y, z) [m], heading 0 (z = 0: landed).
  static void place(const typename Vehicle::template Params<double>& p, typename Vehicle::template State<double>& s,
                    const double at[3]) {
    Vehicle::start(p, s);
    for (int i = 0; i < 3; ++i) s.X[kX + i] = at[i];
  }
  static void bodyPosition(const typename Vehicle::template Params<double>&, const double* X, double out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = X[kX + i];
  }
  // The state from a motion-capture estimate of the body: the same 12.
  static void stateFromBody(const typename Vehicle::template Params<double>&, const double body[kStateSize],
                            double* X) {
    for (int i = 0; i < kStateSize; ++i) X[i] = body[i];
  }
  // nav_msgs/Odometry's twist, in the body frame: v_body = R^T v_world;
  // body rates from the Euler-angle rates.
  static void bodyTwist(const typename Vehicle::template Params<double>&, const double* X, double linear[3],
                        double angular[3]) {
    const double sphi = std::sin(X[kRoll]), cphi = std::cos(X[kRoll]);
    const double sth = std::sin(X[kPitch]), cth = std::cos(X[kPitch]);
    const double spsi = std::sin(X[kYaw]), cpsi = std::cos(X[kYaw]);
    double R[3][3];
    aurora_common::rotationMatrix(sphi, cphi, sth, cth, spsi, cpsi, R);  // the model's own (rotation.h)
    for (int i = 0; i < 3; ++i) linear[i] = R[0][i] * X[kVx] + R[1][i] * X[kVy] + R[2][i] * X[kVz];
    angular[0] = X[kRollRate] - sth * X[kYawRate];
    angular[1] = cphi * X[kPitchRate] + sphi * cth * X[kYawRate];
    angular[2] = -sphi * X[kPitchRate] + cphi * cth * X[kYawRate];
  }
};

// A vehicle's profile: SimProfile<Vehicle>, specialized in the vehicle's
// own folder (vehicle/<name>/<name>_profile.h; a drone's derives from
// DroneSimProfile above), each listed with its vehicle in vehicle_type.h.
template <class Vehicle>
struct SimProfile;

}  // namespace aurora_sim
