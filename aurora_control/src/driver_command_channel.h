// ROS side of DriverCommand (driver_command.h): one std_msgs/Empty publisher
// to a driver topic (takeoff, land or reset), the delivery rule, and the
// log lines, each said once per request; TakeoffLand: one drone's take-off
// and land as the safety file delivers them (the controller node's drone,
// each drone of the formation node).
#pragma once

#include <ros/ros.h>

#include <string>

#include "aurora_control/robot/driver_command.h"
#include "aurora_control/robot/flight_supervisor.h"

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

// One drone's take-off and land: each re-sent every
// safety.command_resend_period until the state shows the climb or the
// descent (land given up after safety.land_resend_timeout); a request
// cancels the other command.
class TakeoffLand {
 public:
  TakeoffLand() = default;
  // who: "" or the drone's namespace, naming the commands in the log
  // ("take-off", "ardrone1 take-off").
  TakeoffLand(ros::NodeHandle& nh, const std::string& takeoff_topic, const std::string& land_topic,
              const std::string& who, const SafetyConfig& safety);

  void takeoff(double now, double z);  // z [m]: the height now (a climb above it shows the take-off)
  void land(double now);
  // The supervisor's requests of this cycle.
  void apply(const FlightDecision& d, double now, double z) {
    if (d.send_takeoff) takeoff(now, z);
    if (d.send_land) land(now);
  }
  // Every cycle. fresh_X: the newest state when fresh, else nullptr (only a
  // fresh state can show that the driver acted).
  void service(double now, const double* fresh_X);

  const DriverCommand& takeoffCommand() const { return takeoff_.command(); }
  const DriverCommand& landCommand() const { return land_.command(); }

 private:
  DriverCommandChannel takeoff_, land_;
  SafetyConfig safety_;
};

}  // namespace aurora_control
