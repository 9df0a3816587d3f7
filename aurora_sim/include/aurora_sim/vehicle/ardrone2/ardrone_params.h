// Physical and on-board controller parameters of the Parrot AR.Drone 2.0
// model (docs/model.md, "Parameters"). Plain data, templated on the
// scalar so the float sweep converts once instead of at every use.
#pragma once

#include "aurora_common/scalar_math.h"

#include <cmath>

#include "aurora_common/host_device.h"

namespace aurora_sim {

template <typename T>
struct ArdroneParams {
  T Ts;     // robot sample time: one model step [s]
  T g;      // gravity [m/s^2]
  T m;      // mass [kg]
  T Ixx, Iyy, Izz;  // principal inertia [kg m^2]; products of inertia are 0
  T r;      // gear reduction [-]
  T Rm;     // motor resistance [Ohm]
  T Jm;     // rotor inertia (identified value)
  T Bm;     // rotor damping
  T Km;     // motor torque constant
  T Kb;     // back-EMF constant
  T Cf;     // thrust coefficient
  T Ct;     // drag-torque coefficient
  T kdp, kpp;  // on-board roll PD
  T kdt, kpt;  // on-board pitch PD
  T kdz, kpz;  // on-board climb-rate PD
  T kds, kps;  // on-board yaw-rate PD
  T k1;     // arm coefficient
  T uSat[4];  // command scaling: roll [rad], pitch [rad], climb [m/s], yaw rate [rad/s]
  T Vbat;   // battery voltage [V]

  // Derived quantities (docs/model.md: k2 = Ct/Cf, Wo, Vo, Tsm = Ts/4).
  T k2;     // yaw-moment coefficient
  T Tsm;    // motor sub-step [s]
  T Wo;     // hover rotor speed
  T Vo;     // hover voltage [V]

  // Recomputes the derived quantities from the base ones; call after any
  // change of a base parameter (YAML load, robustness sweep).
  AURORA_HD void updateDerived() {
    using std::sqrt;
    k2 = Ct / Cf;
    Tsm = Ts / T(4);
    Wo = sqrt(m * g / (T(4) * Cf));
    Vo = (Rm * Bm / Km + Kb) * Wo + Rm * Ct * Wo * Wo / (r * Km);
  }

  // Converts every field to another scalar type (double -> float sweep).
  template <typename U>
  AURORA_HD ArdroneParams<U> cast() const {
    ArdroneParams<U> p;
    p.Ts = U(Ts); p.g = U(g); p.m = U(m);
    p.Ixx = U(Ixx); p.Iyy = U(Iyy); p.Izz = U(Izz);
    p.r = U(r); p.Rm = U(Rm); p.Jm = U(Jm); p.Bm = U(Bm); p.Km = U(Km);
    p.Kb = U(Kb); p.Cf = U(Cf); p.Ct = U(Ct);
    p.kdp = U(kdp); p.kpp = U(kpp); p.kdt = U(kdt); p.kpt = U(kpt);
    p.kdz = U(kdz); p.kpz = U(kpz); p.kds = U(kds); p.kps = U(kps);
    p.k1 = U(k1);
    for (int i = 0; i < 4; ++i) p.uSat[i] = U(uSat[i]);
    p.Vbat = U(Vbat);
    p.k2 = U(k2); p.Tsm = U(Tsm); p.Wo = U(Wo); p.Vo = U(Vo);
    return p;
  }
};

// The reference parameter set of docs/model.md (Li's identification,
// g = 9.8 as in the reference code). The ROS nodes do not use this: they read
// config/vehicles/ardrone2.yaml strictly; a test checks both agree.
inline ArdroneParams<double> referenceArdrone2Params() {
  const double pi = aurora_common::kPi;
  ArdroneParams<double> p{};
  p.Ts = 1.0 / 30.0;
  p.g = 9.8;
  p.m = 0.429;
  p.Ixx = 2.237568e-3; p.Iyy = 2.985236e-3; p.Izz = 4.80374e-3;
  p.r = 8.625; p.Rm = 0.6029; p.Jm = 0.1215; p.Bm = 3.7400;
  p.Km = 130.14; p.Kb = 1.3014e-3; p.Cf = 8.048e-6; p.Ct = 2.423e-7;
  p.kdp = 0.1; p.kpp = 0.1; p.kdt = 0.1; p.kpt = 0.1;
  p.kdz = 0.05; p.kpz = 5.0; p.kds = 0.05; p.kps = 0.1;
  p.k1 = 0.1785;
  // Written as 15*pi/180 (not 15*(pi/180)) to round as the reference does.
  p.uSat[0] = 15.0 * pi / 180.0; p.uSat[1] = 15.0 * pi / 180.0;
  p.uSat[2] = 1.0; p.uSat[3] = 100.0 * pi / 180.0;
  p.Vbat = 11.1;
  p.updateDerived();
  return p;
}

}  // namespace aurora_sim
