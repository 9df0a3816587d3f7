// Joystick override (ROS-free): while a deadman button is held the sticks
// drive cmd_vel directly; releasing it hands back to the controller through
// a slew limit, so the command does not jump; edge-triggered buttons for
// take-off, land and emergency reset. Works with any sensor_msgs/Joy driver
// (axes and buttons by index, from YAML).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "aurora_sim/command_mapping.h"

namespace aurora_control {

struct AxisMap {
  int axis = -1;       // index into Joy.axes; -1 = unused
  double scale = 1.0;  // command per unit of stick (negative to invert)
};

struct JoystickConfig {
  int deadman_button = 4;  // Xbox-style pad (xpad): LB
  int takeoff_button = 3;  // Y
  int land_button = 0;     // A
  int reset_button = 1;    // B: emergency (motors off, as the drivers' reset)
  AxisMap linear_x{4, 1.0};   // right stick up: forward
  AxisMap linear_y{3, 1.0};   // right stick left: left
  AxisMap linear_z{1, 1.0};   // left stick up: climb
  AxisMap angular_z{0, 1.0};  // left stick left: counter-clockwise yaw
  double resume_max_step = 0.05;  // largest change of any command per cycle after release
  int resume_min_cycles = 30;     // ... applied for at least this many cycles (1 s)
};

struct JoystickInput {
  bool deadman = false;
  bool takeoff = false, land = false, reset = false;  // pressed since the last message
  aurora_sim::TwistCommand sticks{0, 0, 0, 0};         // driver fractions, clamped to [-1, 1]
};

class JoystickMapper {
 public:
  explicit JoystickMapper(const JoystickConfig& cfg = JoystickConfig()) : cfg_(cfg) {}

  JoystickInput map(const std::vector<float>& axes, const std::vector<int>& buttons) {
    JoystickInput in;
    in.deadman = pressed(buttons, cfg_.deadman_button);
    in.takeoff = edge(buttons, cfg_.takeoff_button, 0);
    in.land = edge(buttons, cfg_.land_button, 1);
    in.reset = edge(buttons, cfg_.reset_button, 2);
    in.sticks.linear_x = axis(axes, cfg_.linear_x);
    in.sticks.linear_y = axis(axes, cfg_.linear_y);
    in.sticks.linear_z = axis(axes, cfg_.linear_z);
    in.sticks.angular_z = axis(axes, cfg_.angular_z);
    return in;
  }

 private:
  static bool pressed(const std::vector<int>& b, int i) {
    return i >= 0 && i < static_cast<int>(b.size()) && b[i] != 0;
  }
  bool edge(const std::vector<int>& b, int i, int slot) {
    const bool now = pressed(b, i);
    const bool rising = now && !was_[slot];
    was_[slot] = now;
    return rising;
  }
  static double axis(const std::vector<float>& a, const AxisMap& m) {
    if (m.axis < 0 || m.axis >= static_cast<int>(a.size()) || !std::isfinite(a[m.axis])) return 0.0;
    return std::max(-1.0, std::min(1.0, m.scale * a[m.axis]));
  }

  JoystickConfig cfg_;
  bool was_[3] = {false, false, false};
};

// Limits the per-cycle change of the command after the joystick hands back,
// for at least `min_cycles` and until the controller's command is reached;
// then passes it through. The minimum lets the law's own transient after the
// manual flight settle under the same limit.
class ResumeSlew {
 public:
  explicit ResumeSlew(double max_step = 0.05, int min_cycles = 30)
      : max_step_(max_step), min_cycles_(min_cycles) {}

  void start(const double from[4]) {
    for (int i = 0; i < 4; ++i) last_[i] = from[i];
    active_ = true;
    cycles_ = 0;
  }
  bool active() const { return active_; }

  void apply(double U[4]) {
    if (!active_) return;
    bool reached = true;
    for (int i = 0; i < 4; ++i) {
      const double delta = U[i] - last_[i];
      if (std::fabs(delta) > max_step_) {
        U[i] = last_[i] + (delta > 0 ? max_step_ : -max_step_);
        reached = false;
      }
      last_[i] = U[i];
    }
    ++cycles_;
    active_ = !reached || cycles_ < min_cycles_;
  }

 private:
  double max_step_;
  int min_cycles_;
  int cycles_ = 0;
  double last_[4] = {0, 0, 0, 0};
  bool active_ = false;
};

}  // namespace aurora_control
