// Reading the controller node's parameters (task, gains, safety, joystick)
// strictly: a missing or invalid value is a ParameterError naming the full
// key and what is accepted.
#pragma once

#include <ros/ros.h>

#include <string>

#include "aurora_control/flight_supervisor.h"
#include "aurora_control/joystick.h"
#include "aurora_control/waypoint_task.h"

namespace aurora_control {

double requireGain(const ros::NodeHandle& pnh, const std::string& key);
WaypointTask<double> loadTask(const ros::NodeHandle& pnh);
SafetyConfig loadSafetyConfig(const ros::NodeHandle& pnh);
// False when the joystick is not enabled (joystick/enabled).
bool loadJoystickConfig(const ros::NodeHandle& pnh, JoystickConfig& config);

}  // namespace aurora_control
