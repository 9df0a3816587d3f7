// The AR.Drone 2.0's vehicle file keys (config/vehicles/ardrone2.yaml),
// their meaning and accepted ranges: Ardrone2::fileKeys().
#pragma once

#include <vector>

#include "aurora_common/scalar_math.h"
#include "aurora_sim/vehicle/ardrone2/ardrone_params.h"
#include "aurora_sim/vehicle/vehicle_keys.h"

namespace aurora_sim {

struct VehicleKey {
  const char* name;      // key under the vehicle namespace, e.g. "mass"
  double ArdroneParams<double>::*field;  // nullptr for the uSat entries
  int usat_index;        // 0..3 for command scaling entries, -1 otherwise
  double min, max;       // accepted range, inclusive
  const char* unit;
  bool flag = false;     // true / false in the file (none of the AR.Drone's)
};

inline const std::vector<VehicleKey>& vehicleKeys() {
  using P = ArdroneParams<double>;
  static const std::vector<VehicleKey> keys = {
      {"sample_time", &P::Ts, -1, 1e-4, 1.0, "s"},
      {"gravity", &P::g, -1, 1.0, 20.0, "m/s^2"},
      {"mass", &P::m, -1, 1e-3, 100.0, "kg"},
      {"inertia/xx", &P::Ixx, -1, 1e-7, 10.0, "kg m^2"},
      {"inertia/yy", &P::Iyy, -1, 1e-7, 10.0, "kg m^2"},
      {"inertia/zz", &P::Izz, -1, 1e-7, 10.0, "kg m^2"},
      {"motor/gear_reduction", &P::r, -1, 1e-3, 1e3, "-"},
      {"motor/resistance", &P::Rm, -1, 1e-6, 1e3, "Ohm"},
      {"motor/rotor_inertia", &P::Jm, -1, 1e-9, 1e3, "-"},
      {"motor/damping", &P::Bm, -1, 0.0, 1e3, "-"},
      {"motor/torque_constant", &P::Km, -1, 1e-9, 1e6, "-"},
      {"motor/back_emf_constant", &P::Kb, -1, 0.0, 1e3, "-"},
      {"rotor/thrust_coefficient", &P::Cf, -1, 1e-12, 1.0, "N s^2"},
      {"rotor/drag_coefficient", &P::Ct, -1, 0.0, 1.0, "N m s^2"},
      {"rotor/arm_coefficient", &P::k1, -1, 1e-6, 10.0, "m"},
      {"battery_voltage", &P::Vbat, -1, 0.1, 100.0, "V"},
      {"onboard/roll_kd", &P::kdp, -1, 0.0, 1e3, "-"},
      {"onboard/roll_kp", &P::kpp, -1, 0.0, 1e3, "-"},
      {"onboard/pitch_kd", &P::kdt, -1, 0.0, 1e3, "-"},
      {"onboard/pitch_kp", &P::kpt, -1, 0.0, 1e3, "-"},
      {"onboard/climb_kd", &P::kdz, -1, 0.0, 1e3, "-"},
      {"onboard/climb_kp", &P::kpz, -1, 0.0, 1e3, "-"},
      {"onboard/yaw_rate_kd", &P::kds, -1, 0.0, 1e3, "-"},
      {"onboard/yaw_rate_kp", &P::kps, -1, 0.0, 1e3, "-"},
      {"command_scale/roll_deg", nullptr, 0, 0.1, 90.0, "deg"},
      {"command_scale/pitch_deg", nullptr, 1, 0.1, 90.0, "deg"},
      {"command_scale/climb_rate", nullptr, 2, 0.01, 10.0, "m/s"},
      {"command_scale/yaw_rate_deg", nullptr, 3, 1.0, 1000.0, "deg/s"},
  };
  return keys;
}

// Stores a value read for `key`; angles in the file are in degrees and are
// converted as deg * pi / 180 (the reference's rounding).
inline void setVehicleValue(ArdroneParams<double>& p, const VehicleKey& key, double value) {
  if (key.field != nullptr) {
    p.*(key.field) = value;
  } else if (key.usat_index == 2) {
    p.uSat[2] = value;
  } else {
    p.uSat[key.usat_index] = value * aurora_common::kPi / 180.0;
  }
}

}  // namespace aurora_sim
