#include "controller_params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/task/task_yaml.h"
#include "param_tree.h"
#include "aurora_common/ros/params.h"

namespace aurora_control {

std::string controllerName(const ros::NodeHandle& pnh) {
  std::string name;
  return pnh.getParam("controller/name", name) ? name : "";
}

const char* taskTypeName(TaskType type) {
  return type == TaskType::kCircle ? "circle" : (type == TaskType::kLemniscate ? "lemniscate" : "waypoint");
}

void loadLink(const ros::NodeHandle& pnh, long given_delay, LoopSettings& set) {
  if (pnh.hasParam("link")) set.link = readLink(YamlReader("parameter ", "/"), paramAsYaml(pnh, "link"), fullKey(pnh, "link"));
  set.delay = delayInForce(given_delay, set.link);  // docs/links.md, "A delay beside a link"
}

Task<double> loadTask(const ros::NodeHandle& pnh, const TaskHeights& heights) {
  const YAML::Node task = paramAsYaml(pnh, "task");
  if (!task) {
    throw ConfigError("missing parameter '" + fullKey(pnh, "task") +
                         "': load a task file such as config/tasks/mission4.yaml (launch arg 'task')");
  }
  return readTask(YamlReader("parameter ", "/"), task, fullKey(pnh, "task"), heights);
}

namespace {

void readVector3(const ros::NodeHandle& pnh, const std::string& key, double out[3]) {
  std::vector<double> v;
  if (!pnh.getParam(key, v) || v.size() != 3) {
    throw ConfigError("parameter '" + fullKey(pnh, key) + "' must be [x, y, z] in m");
  }
  for (int i = 0; i < 3; ++i) out[i] = v[i];
}

int buttonParam(const ros::NodeHandle& pnh, const std::string& key, int fallback) {
  const int b = paramOr(pnh, key, fallback);
  if (b < -1 || b > 63) {
    throw ConfigError("parameter '" + fullKey(pnh, key) + "' = " + std::to_string(b) +
                         " is invalid: accepted a button index in [0, 63], or -1 for none");
  }
  return b;
}

AxisMap axisParam(const ros::NodeHandle& pnh, const std::string& key, const AxisMap& fallback) {
  AxisMap m;
  m.axis = paramOr(pnh, key + "/axis", fallback.axis);
  m.scale = paramOr(pnh, key + "/scale", fallback.scale);
  if (m.axis < -1 || m.axis > 63 || !std::isfinite(m.scale) || std::fabs(m.scale) > 1.0) {
    throw ConfigError("parameter '" + fullKey(pnh, key) +
                         "' is invalid: accepted axis in [0, 63] (-1: none) and |scale| <= 1");
  }
  return m;
}

}  // namespace

SafetyConfig loadSafetyConfig(const ros::NodeHandle& pnh) {
  const SafetyConfig d;  // the defaults, written once in flight_supervisor.h
  SafetyConfig c;
  c.flight_sequence = aurora_common::boolParam(pnh, "safety/flight_sequence", d.flight_sequence);
  c.takeoff_altitude = rangedParam(pnh, "safety/takeoff_altitude", d.takeoff_altitude, 0.2, 5.0, "m");
  c.takeoff_timeout = rangedParam(pnh, "safety/takeoff_timeout", d.takeoff_timeout, 1.0, 120.0, "s");
  c.hover_after = rangedParam(pnh, "safety/hover_after", d.hover_after, 0.01, 60.0, "s");
  c.land_after = rangedParam(pnh, "safety/land_after", d.land_after, 0.0, 600.0, "s (0 = never)");
  c.command_resend_period =
      rangedParam(pnh, "safety/command_resend_period", d.command_resend_period, 0.1, 10.0, "s");
  c.land_resend_timeout =
      rangedParam(pnh, "safety/land_resend_timeout", d.land_resend_timeout, 1.0, 120.0, "s");
  c.takeoff_rise = rangedParam(pnh, "safety/takeoff_rise", d.takeoff_rise, 0.02, 1.0, "m");
  c.descent_speed = rangedParam(pnh, "safety/descent_speed", d.descent_speed, 0.02, 1.0, "m/s");
  c.max_speed = rangedParam(pnh, "safety/max_speed", d.max_speed, 0.0, 2.0, "m/s (a ground robot's; 0: none)");
  c.max_turn_rate = rangedParam(pnh, "safety/max_turn_rate", d.max_turn_rate, 0.0, 5.0,
                                "rad/s (a ground robot's; 0: none)");
  if (c.land_after > 0.0 && c.land_after <= c.hover_after) {
    throw ConfigError("parameter '" + fullKey(pnh, "safety/land_after") +
                         "' must be 0 (never) or longer than safety/hover_after");
  }
  c.box_enabled = pnh.hasParam("safety/box/min") || pnh.hasParam("safety/box/max");
  if (c.box_enabled) {
    readVector3(pnh, "safety/box/min", c.box_min);
    readVector3(pnh, "safety/box/max", c.box_max);
    for (int i = 0; i < 3; ++i) {
      if (!(c.box_min[i] < c.box_max[i])) {
        throw ConfigError("parameter '" + fullKey(pnh, "safety/box") +
                             "' is empty: min must be below max on every axis");
      }
    }
  }
  return c;
}

bool loadJoystickConfig(const ros::NodeHandle& pnh, JoystickConfig& c) {
  if (!aurora_common::boolParam(pnh, "joystick/enabled", false)) return false;
  const JoystickConfig d;
  c.deadman_button = buttonParam(pnh, "joystick/buttons/deadman", d.deadman_button);
  if (c.deadman_button < 0) {
    throw ConfigError("parameter '" + fullKey(pnh, "joystick/buttons/deadman") +
                         "' is required when the joystick is enabled: a button index in [0, 63]");
  }
  c.takeoff_button = buttonParam(pnh, "joystick/buttons/takeoff", d.takeoff_button);
  c.land_button = buttonParam(pnh, "joystick/buttons/land", d.land_button);
  c.reset_button = buttonParam(pnh, "joystick/buttons/reset", d.reset_button);
  c.linear_x = axisParam(pnh, "joystick/axes/linear_x", d.linear_x);
  c.linear_y = axisParam(pnh, "joystick/axes/linear_y", d.linear_y);
  c.linear_z = axisParam(pnh, "joystick/axes/linear_z", d.linear_z);
  c.angular_z = axisParam(pnh, "joystick/axes/angular_z", d.angular_z);
  c.resume_max_step = rangedParam(pnh, "joystick/resume_max_step", d.resume_max_step, 0.001, 2.0,
                                 "(command change per cycle)");
  c.resume_min_cycles = static_cast<int>(rangedParam(pnh, "joystick/resume_min_cycles",
                                                    d.resume_min_cycles, 0, 3000, "cycles"));
  return true;
}

}  // namespace aurora_control
