// A test-only vehicle (issue 53, "proof, as tests"): a quadrotor whose
// speed on x, y, z and yaw follows its command with a first-order lag, the
// command a fraction of its top speed in the world frame (no tilt). It is
// declared here only, with its simulator profile, and joins the vehicles'
// list of a test build of the nodes (extra_vehicles.h): the sim node, the
// controller and replay fly it as they fly the shipped vehicles.
#pragma once

#include <vector>

#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/sim_profile.h"
#include "aurora_sim/vehicle/vehicle_defaults.h"
#include "aurora_sim/vehicle/vehicle_keys.h"

namespace registry {

// The axes it commands, in its command's order.
enum TestQuadAxis : int { kAxisX = 0, kAxisY = 1, kAxisZ = 2, kAxisYaw = 3, kAxes = 4 };

template <typename T>
struct TestQuadParams {
  T Ts;             // [s] model step
  T speed;          // [m/s] per unit command on x, y, z
  T yaw_rate;       // [rad/s] per unit command on yaw
  T time_constant;  // [s] of the speed's lag
  template <typename U>
  AURORA_HD TestQuadParams<U> cast() const {
    return TestQuadParams<U>{U(Ts), U(speed), U(yaw_rate), U(time_constant)};
  }
};

template <typename T>
struct TestQuadState {
  T X[aurora_sim::kStateSize];  // the 12-state (state_index.h), roll and pitch 0
  AURORA_HD void reset() {
    for (int i = 0; i < aurora_sim::kStateSize; ++i) X[i] = T(0);
  }
};

enum class TestQuadField { kSampleTime, kSpeed, kYawRate, kTimeConstant };
using TestQuadKey = aurora_sim::FileKey<TestQuadField>;

struct TestQuad : aurora_sim::VehicleDefaults {
  template <typename T>
  using Params = TestQuadParams<T>;
  template <typename T>
  using State = TestQuadState<T>;
  static constexpr int kStates = aurora_sim::kStateSize, kInputs = kAxes, kPosition = aurora_sim::kX;
  static constexpr int kFactors = 2;
  static constexpr bool kOnGround = false;
  static const char* name() { return "test_quad"; }
  static const char* inputName(int i) {
    static const char* const names[kInputs] = {"u_x [-1, 1]", "u_y [-1, 1]", "u_z [-1, 1]", "u_yaw [-1, 1]"};
    return names[i];
  }

  // Semi-implicit Euler: each rate moves toward its commanded speed, then
  // each position by its new rate.
  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    const int pos[kAxes] = {aurora_sim::kX, aurora_sim::kY, aurora_sim::kZ, aurora_sim::kYaw};
    const int rate[kAxes] = {aurora_sim::kVx, aurora_sim::kVy, aurora_sim::kVz, aurora_sim::kYawRate};
    for (int i = 0; i < kAxes; ++i) {
      const T top = i == kAxisYaw ? p.yaw_rate : p.speed;
      s.X[rate[i]] = s.X[rate[i]] + (top * U[i] - s.X[rate[i]]) * (p.Ts / p.time_constant);
      s.X[pos[i]] = s.X[pos[i]] + s.X[rate[i]] * p.Ts;
    }
  }

  static const char* factorName(int i) { return i == 0 ? "speed" : "time_constant"; }
  AURORA_HD static Params<double> scaled(Params<double> p, const double* factor) {
    p.speed *= factor[0];
    p.time_constant *= factor[1];
    return p;
  }

  static const std::vector<TestQuadKey>& fileKeys() {
    using K = TestQuadField;
    static const std::vector<TestQuadKey> keys = {
        {"sample_time", K::kSampleTime, 0, 1e-4, 1.0, "s", false},
        {"speed", K::kSpeed, 0, 1e-3, 100.0, "m/s per unit command", false},
        {"yaw_rate", K::kYawRate, 0, 1e-3, 100.0, "rad/s per unit command", false},
        {"time_constant", K::kTimeConstant, 0, 1e-3, 100.0, "s", false},
    };
    return keys;
  }
  static void setFileValue(Params<double>& p, const TestQuadKey& key, double value) {
    switch (key.field) {
      case TestQuadField::kSampleTime: p.Ts = value; break;
      case TestQuadField::kSpeed: p.speed = value; break;
      case TestQuadField::kYawRate: p.yaw_rate = value; break;
      case TestQuadField::kTimeConstant: p.time_constant = value; break;
    }
  }
  static void finishFile(Params<double>&) {}

  // Its driver takes cmd_vel's linear x, y, z and angular z as they are.
  using DriverCommand = aurora_sim::TwistCommand;
  static DriverCommand toDriver(const double U[kInputs]) {
    return DriverCommand{U[kAxisX], U[kAxisY], U[kAxisZ], U[kAxisYaw]};
  }
  static void fromDriver(const DriverCommand& msg, double U[kInputs]) {
    U[kAxisX] = msg.linear_x, U[kAxisY] = msg.linear_y, U[kAxisZ] = msg.linear_z, U[kAxisYaw] = msg.angular_z;
  }
};

}  // namespace registry

namespace aurora_sim {

// In the sim node: a drone that climbs with u_z.
template <>
struct SimProfile<registry::TestQuad> : DroneSimProfile<registry::TestQuad, registry::kAxisZ> {};

}  // namespace aurora_sim
