// The Pioneer P3-DX as a vehicle (docs/pioneer3dx.md; the members every
// vehicle gives: ardrone2.h's comment): its dynamic or kinematic model
// (pioneer3dx_model.h) of the control point a ahead of the axle, the
// identified parameters as a sweep's factors, its vehicle file's keys and
// RosAria's cmd_vel (linear.x = u_ref [m/s], angular.z = omega_ref [rad/s]).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx_model.h"
#include "aurora_sim/vehicle/vehicle_defaults.h"
#include "aurora_sim/vehicle/vehicle_keys.h"

namespace aurora_sim {

// The Pioneer's vehicle file sets the sample time, the control point, one
// of theta (index: 0-based), or one of the model's two options (flags).
enum class PioneerField { kSampleTime, kControlPoint, kTheta, kKinematic, kOmegaGainBug };
using PioneerKey = FileKey<PioneerField>;

struct Pioneer3dx : VehicleDefaults {  // its own start, state names and limitInput
  template <typename T>
  using Params = PioneerParams<T>;
  template <typename T>
  using State = PioneerState<T>;

  static constexpr int kStates = kPioneerStateSize;  // the control point's 12-state, then u, omega
  static constexpr int kInputs = kPioneerInputs;     // u_ref [m/s], omega_ref [rad/s]
  static constexpr int kPosition = kX;
  static constexpr int kFactors = 6;                 // theta1 .. theta6
  static constexpr bool kOnGround = true;
  static constexpr int kSpeedInput = kPioneerURef;         // a ground robot's commands, by name
  static constexpr int kTurnRateInput = kPioneerOmegaRef;  // (config/safety/real_ground.yaml limits them)

  static const char* stateName(int i) { return i < kStateSize ? stateName12(i) : i == kPioneerU ? "u" : "omega"; }
  static const char* inputName(int i) { return i == kPioneerURef ? "u_ref [m/s]" : "omega_ref [rad/s]"; }  // RosAria's cmd_vel

  // AuRoRA's rSetPose([0 0 0 0]) on a new robot: the control point a ahead
  // of the centre (docs/pioneer3dx.md, "Standard scenario").
  template <typename T>
  AURORA_HD static void start(const Params<T>& p, State<T>& s) {
    s.reset();
    pioneerSetPose(p, s, T(0), T(0), T(0), T(0));
  }

  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    pioneerStep(p, s, U);
  }

  // RosAria passes cmd_vel on as it is (ARIA's own limits are the robot's
  // firmware's, not modelled); the controllers saturate their commands.
  template <typename T>
  AURORA_HD static T limitInput(const Params<T>&, int, const T& u) {
    return u;
  }

  // What its vehicle file says beyond its constants, which a formation file
  // may change (the robot's vehicle file formation_robot writes): its model.
  static std::vector<std::pair<std::string, std::string>> fileChoices(const Params<double>& p) {
    return {{"kinematic_model", p.kinematic != 0.0 ? "true" : "false"}};
  }

  static const char* factorName(int i) {
    static const char* const names[kFactors] = {"theta1", "theta2", "theta3", "theta4", "theta5", "theta6"};
    return names[i];
  }
  AURORA_HD static Params<double> scaled(Params<double> p, const double* factor) {
    for (int i = 0; i < kFactors; ++i) p.theta[i] *= factor[i];
    return p;
  }

  static const char* name() { return "pioneer3dx"; }
  // The stem of its robots' ROS namespaces (pioneer1, pioneer2, ...: a formation's
  // robots where its file names none, robot_namespace.h).
  static const char* namespaceStem() { return "pioneer"; }

  // config/vehicles/pioneer3dx.yaml: every key required. theta1 and theta2
  // divide the model: they must be positive.
  static const std::vector<PioneerKey>& fileKeys() {
    using K = PioneerField;
    static const std::vector<PioneerKey> keys = {
        {"sample_time", K::kSampleTime, 0, 1e-4, 1.0, "s", false},
        {"control_point", K::kControlPoint, 0, 1e-3, 2.0, "m", false},
        {"dynamics/theta1", K::kTheta, 0, 1e-6, 100.0, "s", false},
        {"dynamics/theta2", K::kTheta, 1, 1e-6, 100.0, "s", false},
        {"dynamics/theta3", K::kTheta, 2, -100.0, 100.0, "s m/rad^2", false},
        {"dynamics/theta4", K::kTheta, 3, -100.0, 100.0, "-", false},
        {"dynamics/theta5", K::kTheta, 4, -100.0, 100.0, "s/m", false},
        {"dynamics/theta6", K::kTheta, 5, -100.0, 100.0, "-", false},
        {"kinematic_model", K::kKinematic, 0, 0.0, 1.0, "true or false", true},
        {"model_bug_omega_gain", K::kOmegaGainBug, 0, 0.0, 1.0, "true or false", true},
    };
    return keys;
  }
  static void setFileValue(Params<double>& p, const PioneerKey& key, double value) {
    switch (key.field) {
      case PioneerField::kSampleTime: p.Ts = value; break;
      case PioneerField::kControlPoint: p.a = value; break;
      case PioneerField::kTheta: p.theta[key.index] = value; break;
      case PioneerField::kKinematic: p.kinematic = value != 0.0 ? 1.0 : 0.0; break;
      case PioneerField::kOmegaGainBug: p.omega_gain_bug = value != 0.0 ? 1.0 : 0.0; break;
    }
  }
  static void finishFile(Params<double>&) {}

  // RosAria's cmd_vel: linear.x [m/s], angular.z [rad/s]; the rest 0.
  using DriverCommand = TwistCommand;
  static DriverCommand toDriver(const double U[kInputs]) {
    return TwistCommand{U[kPioneerURef], 0.0, 0.0, U[kPioneerOmegaRef]};
  }
  static void fromDriver(const DriverCommand& msg, double U[kInputs]) {
    U[kPioneerURef] = msg.linear_x, U[kPioneerOmegaRef] = msg.angular_z;
  }
};

}  // namespace aurora_sim
