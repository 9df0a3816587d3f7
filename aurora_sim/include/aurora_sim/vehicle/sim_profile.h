// What the simulator node does with a vehicle beyond its model
// (docs/simulation.md, "Vehicles"): how it takes off and lands (the input
// that climbs; none for a ground robot), where it starts, which odometry
// topic its real driver publishes, and where its body is (a Pioneer's
// centre lies a behind the control point its state gives). ROS-free.
#pragma once

#include <algorithm>
#include <cmath>

#include "aurora_common/rotation.h"
#include "aurora_sim/state_index.h"
#include "aurora_sim/vehicle/ardrone2/ardrone2.h"
#include "aurora_sim/vehicle/bebop2/bebop2.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx.h"

namespace aurora_sim {

// A drone: climbs with its vertical input, starts in the air above its
// start point, publishes odometry as its driver does on `odom`, its body at
// its state's position.
template <class Vehicle, int ClimbInput>
struct DroneSimProfile {
  static constexpr int kClimbInput = ClimbInput;
  static constexpr bool kFlies = true;
  static const char* odomTopic() { return "odom"; }  // ardrone_autonomy's ardrone/odometry remapped, bebop_autonomy's odom
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

template <class Vehicle>
struct SimProfile;

template <>
struct SimProfile<Ardrone2> : DroneSimProfile<Ardrone2, kUClimb> {};
template <>
struct SimProfile<Bebop2> : DroneSimProfile<Bebop2, kBebopZ> {};

// The Pioneer P3-DX: on the floor, driving from the first state; RosAria's
// `pose` topic; its body (the centre between the wheels) a behind the
// control point the state and the laws use.
template <>
struct SimProfile<Pioneer3dx> {
  static constexpr int kClimbInput = -1;
  static constexpr bool kFlies = false;
  static const char* odomTopic() { return "pose"; }

  // The safety layer's limits on what is sent (0: none): |u_ref| <= max_speed
  // [m/s], |omega_ref| <= max_turn_rate [rad/s].
  static void limitSpeed(double U[Pioneer3dx::kInputs], double max_speed, double max_turn_rate) {
    if (max_speed > 0.0) U[kPioneerURef] = std::max(-max_speed, std::min(max_speed, U[kPioneerURef]));
    if (max_turn_rate > 0.0) U[kPioneerOmegaRef] = std::max(-max_turn_rate, std::min(max_turn_rate, U[kPioneerOmegaRef]));
  }

  // The state the laws read from a motion-capture estimate of the body
  // (`body`: its 12-state, the centre's position and velocity, attitude and
  // Euler rates): the control point a ahead (eq. P3's velocity), on the
  // floor, then u and omega (the forward speed of the centre, the yaw rate).
  static void stateFromBody(const Pioneer3dx::Params<double>& p, const double body[kStateSize],
                            double X[Pioneer3dx::kStates]) {
    for (int i = 0; i < Pioneer3dx::kStates; ++i) X[i] = 0.0;
    const double psi = body[kYaw], c = std::cos(psi), s = std::sin(psi), w = body[kYawRate];
    X[kX] = body[kX] + p.a * c, X[kY] = body[kY] + p.a * s, X[kYaw] = psi;
    X[kVx] = body[kVx] - p.a * s * w, X[kVy] = body[kVy] + p.a * c * w, X[kYawRate] = w;
    X[kPioneerU] = body[kVx] * c + body[kVy] * s;
    X[kPioneerOmega] = w;
  }

  // At rest with its centre at (x, y) (at[2] must be 0), heading 0.
  static void place(const Pioneer3dx::Params<double>& p, Pioneer3dx::State<double>& s, const double at[3]) {
    s.reset();
    pioneerSetPose(p, s, at[0], at[1], at[2], 0.0);
  }
  static void bodyPosition(const Pioneer3dx::Params<double>& p, const double* X, double out[3]) {
    out[0] = X[kX] - p.a * std::cos(X[kYaw]);
    out[1] = X[kY] - p.a * std::sin(X[kYaw]);
    out[2] = X[kZ];
  }
  // RosAria's twist: forward speed and yaw rate of the body.
  static void bodyTwist(const Pioneer3dx::Params<double>&, const double* X, double linear[3], double angular[3]) {
    linear[0] = X[kPioneerU], linear[1] = linear[2] = 0.0;
    angular[0] = angular[1] = 0.0, angular[2] = X[kPioneerOmega];
  }
};

}  // namespace aurora_sim
