// The triangle's kinematic robots (docs/formation.md, "The triangle";
// AuRoRA's kinematic simulations put each robot at its reference every
// period): a vehicle whose state is its position (3 states) and whose input
// is the position it is put at (step: X = U), and the law that puts it at
// its reference. So a kinematic triangle flies the one formation loop
// (formation_runner.h), one robot step per layer period, its delays in
// periods. Host and device; ROS-free.
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_control/task/task.h"

namespace aurora_control {

namespace kinematic_robot {

template <typename T>
struct Params {
  T Ts;  // [s] its step: the layer's period
  template <typename U>
  AURORA_HD Params<U> cast() const {
    return Params<U>{U(Ts)};
  }
};

template <typename T>
struct State {
  T X[3];  // x y z [m], world frame
  AURORA_HD void reset() {
    for (int i = 0; i < 3; ++i) X[i] = T(0);
  }
};

template <typename T>
struct Gains {};  // none: it is where it is told
template <typename T, typename U>
void castGains(const Gains<U>&, Gains<T>&) {}

template <typename T>
struct Memory {
  AURORA_HD void reset() {}
};

}  // namespace kinematic_robot

struct KinematicRobot {
  template <typename T>
  using Params = kinematic_robot::Params<T>;
  template <typename T>
  using State = kinematic_robot::State<T>;
  static constexpr int kStates = 3, kInputs = 3, kPosition = 0, kFactors = 0;
  static constexpr bool kOnGround = false;
  static const char* name() { return "kinematic"; }
  static const char* stateName(int i) {
    static const char* const names[kStates] = {"x", "y", "z"};
    return names[i];
  }
  template <typename T>
  AURORA_HD static void start(const Params<T>&, State<T>& s) {
    s.reset();
  }
  template <typename T>
  AURORA_HD static void step(const Params<T>&, State<T>& s, const T U[kInputs]) {
    for (int i = 0; i < 3; ++i) s.X[i] = U[i];
  }
  template <typename T>
  AURORA_HD static T limitInput(const Params<T>&, int, const T& u) {
    return u;  // [m] a position: no limit
  }
  AURORA_HD static Params<double> scaled(Params<double> p, const double*) { return p; }
};

// U = the reference's position: the robot is put there.
struct FollowReference {
  using Vehicle = KinematicRobot;
  using Data = FollowReference;
  template <typename T>
  using Gains = kinematic_robot::Gains<T>;
  template <typename T>
  using Memory = kinematic_robot::Memory<T>;
  struct Input {
    static constexpr int kWidth = 3;
    AURORA_HD static constexpr int state(int j) { return j; }
  };
  static const char* name() { return "follow_reference"; }

  template <typename T>
  AURORA_HD static void command(const KinematicRobot::Params<T>&, const Gains<T>&, Memory<T>&, const Reference<T>& ref,
                                const T X[3], T U[3], T err[3]) {
    for (int i = 0; i < 3; ++i) U[i] = ref.pos[i], err[i] = ref.pos[i] - X[i];
  }
};

}  // namespace aurora_control
