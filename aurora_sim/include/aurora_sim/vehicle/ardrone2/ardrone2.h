// The AR.Drone 2.0 as a vehicle (docs/architecture.md, "Vehicles"): the
// type every generic loop, the sweep's engines and the kernel are
// instantiated on. A vehicle gives, as static members:
// - Params<T>, State<T>: its parameters (a struct of T only, with the robot
//   sample time Ts [s]) and its state (X[kStates], reset() to the study's
//   start), templated on the scalar (double, float, SIMD batches, CUDA);
// - kStates, kInputs, kPosition: the state's size, the command's size, and
//   where x y z [m, world frame] sit in X; stateName(i): X's names;
//   inputName(i): U's, with units;
// - kOnGround: a ground robot (its tasks lie on the floor, z = 0); a
//   ground robot also names its forward speed and turn rate commands
//   (kSpeedInput, kTurnRateInput: what a real one's safety layer limits);
// - start(p, s): a new robot at rest with its centre at the world origin,
//   heading 0 (every loop's first state);
// - step(p, s, U): one model step of Ts with command U;
// - limitInput(p, i, u): the vehicle's own clamp of command component i
//   (what its driver does with what it receives; a vehicle's limits may be
//   its parameters);
// - kFactors, scaled(p, factor): the model parameters a sweep may scale
//   (factor i multiplies parameter i of factorName order), derived values
//   recomputed;
// - name(): its name, as a vehicle file's `type:` gives it;
// - fileKeys(), setFileValue(p, key, v), finishFile(p): its vehicle file's
//   keys (name, accepted range, unit; vehicle_file.h reads them);
// - toDriver(U), fromDriver(msg, U): how its commands map to its driver's
//   command message (host only).
// Only the files of a vehicle name it; the rest chooses it by name.
#pragma once

#include <vector>

#include "aurora_sim/vehicle/ardrone2/ardrone_model.h"
#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/vehicle_defaults.h"
#include "aurora_sim/vehicle/ardrone2/ardrone_keys.h"

namespace aurora_sim {

struct Ardrone2 : VehicleDefaults {
  template <typename T>
  using Params = ArdroneParams<T>;
  template <typename T>
  using State = ArdroneState<T>;

  static constexpr int kStates = kStateSize;    // StateIndex order (state_index.h)
  static constexpr int kInputs = kCommandSize;  // CommandIndex order, each in [-1, 1]
  static constexpr int kPosition = kX;
  static constexpr int kFactors = 8;
  static constexpr bool kOnGround = false;

  // Its commands with their units (Control.command_names, a report's labels).
  static const char* inputName(int i) {
    static const char* const names[kInputs] = {"u_phi (roll) [-1, 1]", "u_theta (pitch, + = negative theta) [-1, 1]",
                                               "u_zdot (climb) [-1, 1]", "u_psidot (yaw rate, + = negative) [-1, 1]"};
    return names[i];
  }

  // One step of docs/model.md, "One model step", without disturbances.
  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    ardroneStep(p, s, U, Disturbance<T>::zero());
  }

  // stateName, start and limitInput (the driver and the sim node clamp
  // each command to [-1, 1]): VehicleDefaults'.

  // Its simulation clamps what it receives in every flight (a flight's
  // --no-clamp leaves the law's commands unclamped, not the drone's).
  static constexpr bool kAlwaysClamps = true;

  // The factors' parameters, in factor order (the sweep's m_factor ...).
  static const char* factorName(int i) {
    static const char* const names[kFactors] = {"m", "Ixx", "Iyy", "Izz", "Cf", "Ct", "Km", "Jm"};
    return names[i];
  }

  // Factor i multiplies parameter factorName(i); then the derived quantities
  // follow (k2 = Ct/Cf, hover speed and voltage). In double, as the vehicle
  // file is loaded, then converted: every backend and precision scales alike.
  AURORA_HD static Params<double> scaled(Params<double> p, const double* factor) {
    p.m *= factor[0];
    p.Ixx *= factor[1];
    p.Iyy *= factor[2];
    p.Izz *= factor[3];
    p.Cf *= factor[4];
    p.Ct *= factor[5];
    p.Km *= factor[6];
    p.Jm *= factor[7];
    p.updateDerived();
    return p;
  }

  static const char* name() { return "ardrone2"; }
  // The stem of its robots' ROS namespaces (ardrone1, ardrone2, ...: a formation's
  // robots where its file names none, robot_namespace.h).
  static const char* namespaceStem() { return "ardrone"; }

  // The vehicle file (config/vehicles/ardrone2.yaml): every key of
  // ardrone_keys.h, required; angles in degrees there.
  static const std::vector<VehicleKey>& fileKeys() { return vehicleKeys(); }
  static void setFileValue(Params<double>& p, const VehicleKey& key, double value) { setVehicleValue(p, key, value); }
  static void finishFile(Params<double>& p) { p.updateDerived(); }

  // ardrone_autonomy's cmd_vel (command_mapping.h).
  using DriverCommand = TwistCommand;
  static DriverCommand toDriver(const double U[kInputs]) { return twistFromModelCommand(U); }
  static void fromDriver(const DriverCommand& msg, double U[kInputs]) { modelCommandFromTwist(msg, U); }
};

}  // namespace aurora_sim
