// Reading the controller node's parameters (task, gains, safety, joystick)
// strictly: a missing or invalid value is a ConfigError naming the full
// key and what is accepted.
#pragma once

#include <ros/ros.h>

#include <cstdio>
#include <string>

#include "aurora_control/params/parameter_table.h"
#include "aurora_control/robot/flight_supervisor.h"
#include "aurora_control/robot/joystick.h"
#include "aurora_control/loop/law_settings_yaml.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "param_tree.h"
#include "aurora_control/task/task.h"
#include "aurora_control/task/task_check.h"
#include "aurora_common/ros/params.h"

namespace aurora_control {

// The strict ROS parameter readers (aurora_common/ros/params.h) the node's
// sources use.
using aurora_common::fullKey;
using aurora_common::paramOr;
using aurora_common::rangedParam;
using aurora_common::tableParam;
using aurora_common::wholeParam;
using aurora_common::wordParam;

std::string controllerName(const ros::NodeHandle& pnh);  // ~controller/name, or "" when it has none

// The vehicle under `vehicle` (nh's; its file, of the law's vehicle), its
// sample time, and the law named by ~controller/name with its gains (all
// required). Unknown keys under ~controller are refused naming the
// accepted ones for that law.
template <class Settings>
void loadLaw(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, Settings& set) {
  using Vehicle = typename Settings::Data::Vehicle;
  set.vehicle = aurora_sim::loadVehicleParams<Vehicle>(nh, "vehicle", "the controller '" + controllerName(pnh) + "'");
  set.Ts = set.vehicle.Ts;
  readLawMapping(YamlReader("parameter ", "/"), paramAsYaml(pnh, "controller"), fullKey(pnh, "controller"), set);
}

// "kp=0.5 kd=0.85" or "k1_x=0.5 k2_x=2 ...": the gains in force, for the log.
template <class Settings>
std::string gainsText(const Settings& settings) {
  std::string out;
  for (const auto& gain : gainsInForce(settings)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s=%g", out.empty() ? "" : " ", gain.first.c_str(), gain.second);
    out += buf;
  }
  return out;
}
const char* taskTypeName(TaskType type);

// ~task through the one task schema (task_yaml.h).
// `heights`: the vehicle's (TaskHeights::of<Vehicle>(): a ground robot's task lies on the floor).
Task<double> loadTask(const ros::NodeHandle& pnh, const TaskHeights& heights = TaskHeights::flying());
// ~link (a link file loaded by the launch's link:=NAME; absent: ideal) into
// set.link, and set.delay: `given_delay` (~delay/*; kDelayNotGiven when
// absent) replaces the link's uplink delay (link_yaml.h, delayInForce).
void loadLink(const ros::NodeHandle& pnh, long given_delay, LoopSettings& set);
SafetyConfig loadSafetyConfig(const ros::NodeHandle& pnh);
// False when the joystick is not enabled (joystick/enabled).
bool loadJoystickConfig(const ros::NodeHandle& pnh, JoystickConfig& config);

}  // namespace aurora_control
