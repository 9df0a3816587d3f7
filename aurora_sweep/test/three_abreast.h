// A test-only shape of three robots (issue 32's shape seam): formation
// variables Q = (x1, y1, z1, dx2, dy2, dz2, dx3, dy3, dz3), robot 1's
// position and robots 2 and 3's offsets from it. Linear, so its inverse
// and its velocities are exact at every configuration; every law moves
// robot 1 with the position part and each other robot with it plus its
// offset's rate (inverse kinematics). Defined here only: the formation
// layer, the runner, the checks and every sweep backend fly it through
// the shape interface that LineFormation implements.
#pragma once

#include "aurora_control/formation/line/line_formation.h"

namespace three_abreast {

template <typename T>
struct ThreeAbreast {
  using Law = aurora_control::FormationLaw;
  static constexpr Law kDefaultLaw = aurora_control::FormationLaw::kInverseKinematics;
  static constexpr int kDrones = 3;
  static constexpr int kVariables = 9;
  static const char* variableName(int i) {
    static const char* const names[kVariables] = {"x1", "y1", "z1", "dx2", "dy2", "dz2", "dx3", "dy3", "dz3"};
    return names[i];
  }

  AURORA_HD static void defaultGains(T k1[9], T k2[9]) {
    for (int i = 0; i < 9; ++i) k1[i] = T(0.5), k2[i] = T(0.5);
  }
  AURORA_HD static void variables(const T X[9], T Q[9]) {
    for (int i = 0; i < 3; ++i) {
      Q[i] = X[i];
      Q[3 + i] = X[3 + i] - X[i];
      Q[6 + i] = X[6 + i] - X[i];
    }
  }
  AURORA_HD static void error(const T[9], const T Qd[9], const T Q[9], T e[9]) {
    for (int i = 0; i < 9; ++i) e[i] = Qd[i] - Q[i];
  }
  AURORA_HD static void formationPosition(const T X[9], T p[3]) {
    for (int i = 0; i < 3; ++i) p[i] = X[i];
  }
  AURORA_HD static void positions(const T Q[9], T X[9]) {
    for (int i = 0; i < 3; ++i) {
      X[i] = Q[i];
      X[3 + i] = Q[i] + Q[3 + i];
      X[6 + i] = Q[i] + Q[6 + i];
    }
  }
  AURORA_HD static void velocities(aurora_control::FormationLaw, const T[9], const T v[9], T dX[9]) {
    for (int i = 0; i < 3; ++i) {
      dX[i] = v[i];
      dX[3 + i] = v[i] + v[3 + i];
      dX[6 + i] = v[i] + v[6 + i];
    }
  }
};

}  // namespace three_abreast
