// Reading the controller node's parameters (task, gains, safety, joystick)
// strictly: a missing or invalid value is a ConfigError naming the full
// key and what is accepted.
#pragma once

#include <ros/ros.h>

#include <string>

#include "aurora_control/params/parameter_table.h"
#include "aurora_control/robot/flight_supervisor.h"
#include "aurora_control/robot/joystick.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/task/task.h"
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

// The law named by ~controller/name and its gains (all required), with the
// vehicle model the underactuated law inverts. Unknown keys under
// ~controller are refused naming the accepted ones for that law.
void loadLaw(const ros::NodeHandle& pnh, const aurora_control::LawVehicleParams& vehicle,
             ControllerSettings& settings);

// "Kp=0.5 Kd=0.85" or "k1_x=0.5 k2_x=2 ...": the gains in force, for the log.
std::string gainsText(const ControllerSettings& settings);
const char* taskTypeName(TaskType type);

// The underactuated gains to / from the reconfigure server's config.
template <typename Config>
void writeUnderactuatedGains(const UnderactuatedGains<double>& g, Config& c) {
  c.k1_x = g.k1[kAxisX], c.k2_x = g.k2[kAxisX], c.k1_y = g.k1[kAxisY], c.k2_y = g.k2[kAxisY];
  c.k1_z = g.k1[kAxisZ], c.k2_z = g.k2[kAxisZ], c.k1_phi = g.k1[kAxisPhi], c.k2_phi = g.k2[kAxisPhi];
  c.k1_theta = g.k1[kAxisTheta], c.k2_theta = g.k2[kAxisTheta];
  c.k1_psi = g.k1[kAxisPsi], c.k2_psi = g.k2[kAxisPsi];
}
template <typename Config>
void readUnderactuatedGains(const Config& c, UnderactuatedGains<double>& g) {
  g.k1[kAxisX] = c.k1_x, g.k2[kAxisX] = c.k2_x, g.k1[kAxisY] = c.k1_y, g.k2[kAxisY] = c.k2_y;
  g.k1[kAxisZ] = c.k1_z, g.k2[kAxisZ] = c.k2_z, g.k1[kAxisPhi] = c.k1_phi, g.k2[kAxisPhi] = c.k2_phi;
  g.k1[kAxisTheta] = c.k1_theta, g.k2[kAxisTheta] = c.k2_theta;
  g.k1[kAxisPsi] = c.k1_psi, g.k2[kAxisPsi] = c.k2_psi;
}

// ~task through the one task schema (task_yaml.h).
Task<double> loadTask(const ros::NodeHandle& pnh);
// ~link (a link file loaded by the launch's link:=NAME; absent: ideal) into
// set.link, and set.delay: `given_delay` (~delay/*; kDelayNotGiven when
// absent) replaces the link's uplink delay (link_yaml.h, delayInForce).
void loadLink(const ros::NodeHandle& pnh, long given_delay, ControllerSettings& set);
SafetyConfig loadSafetyConfig(const ros::NodeHandle& pnh);
// False when the joystick is not enabled (joystick/enabled).
bool loadJoystickConfig(const ros::NodeHandle& pnh, JoystickConfig& config);

}  // namespace aurora_control
