// The Parrot Bebop 2 as a vehicle (docs/bebop2.md; the members every
// vehicle gives: ardrone2.h's comment): its identified velocity model
// (bebop2_model.h), the clamp bebop_autonomy applies to cmd_vel, the
// model's gains as a sweep's factors, its vehicle file's keys and its
// driver's command message (cmd_vel taken as it is: no sign change).
#pragma once

#include <string>
#include <vector>

#include "aurora_sim/vehicle/bebop2/bebop2_model.h"
#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/vehicle_defaults.h"
#include "aurora_sim/vehicle/vehicle_keys.h"

namespace aurora_sim {

// The Bebop 2's vehicle file sets the sample time, one channel's input gain
// or damping (index: its Bebop2Axis), or the drag option (a flag).
enum class Bebop2Field { kSampleTime, kInputGain, kDamping, kRotatedDrag };
using Bebop2Key = FileKey<Bebop2Field>;

struct Bebop2 : VehicleDefaults {
  template <typename T>
  using Params = Bebop2Params<T>;
  template <typename T>
  using State = Bebop2State<T>;

  static constexpr int kStates = kStateSize;  // StateIndex order (state_index.h)
  static constexpr int kInputs = kBebopAxes;  // u_x u_y u_z u_yaw, cmd_vel fractions
  static constexpr int kPosition = kX;
  static constexpr int kFactors = 2 * kBebopAxes;
  static constexpr bool kOnGround = false;

  static const char* inputName(int i) {  // bebop_autonomy's cmd_vel components
    static const char* const names[kInputs] = {"cmd_vel x (forward) [-1, 1]", "cmd_vel y (left) [-1, 1]",
                                               "cmd_vel z (up) [-1, 1]", "cmd_vel yaw (left turn) [-1, 1]"};
    return names[i];
  }

  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    bebop2Step(p, s, U);
  }

  // stateName, start and limitInput (bebop_autonomy clamps each cmd_vel
  // component to [-1, 1]): VehicleDefaults'.

  static const char* factorName(int i) {
    static const char* const names[kFactors] = {"Ku_x", "Ku_y", "Ku_z", "Ku_yaw", "Kv_x", "Kv_y", "Kv_z", "Kv_yaw"};
    return names[i];
  }
  AURORA_HD static Params<double> scaled(Params<double> p, const double* factor) {
    for (int i = 0; i < kBebopAxes; ++i) p.Ku[i] *= factor[i], p.Kv[i] *= factor[kBebopAxes + i];
    return p;
  }

  static const char* name() { return "bebop2"; }
  // The stem of its robots' ROS namespaces (bebop1, bebop2, ...: a formation's
  // robots where its file names none, robot_namespace.h).
  static const char* namespaceStem() { return "bebop"; }

  // config/vehicles/bebop2.yaml: every key required.
  static const std::vector<Bebop2Key>& fileKeys() {
    using K = Bebop2Field;
    static const std::vector<Bebop2Key> keys = {
        {"sample_time", K::kSampleTime, 0, 1e-4, 1.0, "s", false},
        {"input_gain/x", K::kInputGain, kBebopX, 1e-6, 1e3, "m/s^2 per unit command", false},
        {"input_gain/y", K::kInputGain, kBebopY, 1e-6, 1e3, "m/s^2 per unit command", false},
        {"input_gain/z", K::kInputGain, kBebopZ, 1e-6, 1e3, "m/s^2 per unit command", false},
        {"input_gain/yaw", K::kInputGain, kBebopYaw, 1e-6, 1e3, "rad/s^2 per unit command", false},
        {"damping/x", K::kDamping, kBebopX, 0.0, 1e3, "1/s", false},
        {"damping/y", K::kDamping, kBebopY, 0.0, 1e3, "1/s", false},
        {"damping/z", K::kDamping, kBebopZ, 0.0, 1e3, "1/s", false},
        {"damping/yaw", K::kDamping, kBebopYaw, 0.0, 1e3, "1/s", false},
        {"model_bug_rotated_drag", K::kRotatedDrag, 0, 0.0, 1.0, "true or false", true},
    };
    return keys;
  }
  static void setFileValue(Params<double>& p, const Bebop2Key& key, double value) {
    switch (key.field) {
      case Bebop2Field::kSampleTime: p.Ts = value; break;
      case Bebop2Field::kInputGain: p.Ku[key.index] = value; break;
      case Bebop2Field::kDamping: p.Kv[key.index] = value; break;
      case Bebop2Field::kRotatedDrag: p.rotated_drag = value != 0.0 ? 1.0 : 0.0; break;
    }
  }
  static void finishFile(Params<double>&) {}

  // bebop_autonomy's cmd_vel: linear.x, linear.y, linear.z, angular.z are
  // the model's commands as they are.
  using DriverCommand = TwistCommand;
  static DriverCommand toDriver(const double U[kInputs]) {
    return TwistCommand{U[kBebopX], U[kBebopY], U[kBebopZ], U[kBebopYaw]};
  }
  static void fromDriver(const DriverCommand& msg, double U[kInputs]) {
    U[kBebopX] = msg.linear_x, U[kBebopY] = msg.linear_y, U[kBebopZ] = msg.linear_z, U[kBebopYaw] = msg.angular_z;
  }
};

}  // namespace aurora_sim
