// ROS side of DriverCommand (driver_command.h): one std_msgs/Empty publisher
// to a driver topic (takeoff, land or reset), the delivery rule, and the
// log lines, each said once per request.
#pragma once

#include <ros/ros.h>

#include <string>

#include "aurora_control/driver_command.h"

namespace aurora_control {

class DriverCommandChannel {
 public:
  DriverCommandChannel() = default;
  // what: "take-off", "land" or "reset" (for the log).
  DriverCommandChannel(ros::NodeHandle& nh, const std::string& topic, const std::string& what,
                       const DeliveryPolicy& policy);

  void request(double now, double reference = 0.0);
  void cancel() { command_.cancel(); }
  // Call every cycle (and right after a request): publishes when an attempt
  // is due; shown: a fresh state shows the command's effect.
  void service(double now, bool shown);

  const DriverCommand& command() const { return command_; }

 private:
  void logTransition(Delivery before, bool sent, double now);

  ros::Publisher pub_;
  std::string what_;
  DriverCommand command_;
  bool said_waiting_ = false;
};

}  // namespace aurora_control
