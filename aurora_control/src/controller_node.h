// ROS wrapper of the delay-study controller: feeds received states into the
// delay buffer and publishes the command computed from the delayed state;
// runs the flight sequence and safety watchdogs (FlightSupervisor) and the
// joystick override. The same node flies the simulated and the real drone.
#pragma once

#include <aurora_control/ControllerConfig.h>
#include <aurora_msgs/Control.h>
#include <aurora_msgs/DroneState.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>

#include <boost/thread/recursive_mutex.hpp>
#include <memory>
#include <string>

#include "aurora_common/ros/node_main.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/robot/flight_supervisor.h"
#include "aurora_control/robot/joystick.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/task/task.h"
#include "driver_command_channel.h"
#include "state_age.h"

namespace aurora_control {

// The node for one family of laws: Settings is LawSettings<Data> (the law
// of Data's family its controller mapping names, other_laws.h); its
// vehicle's commands go out as its driver's cmd_vel.
template <class Settings>
class ControllerNodeOf {
 public:
  static constexpr int kHistoryCapacity = kDelayHistory;  // limits.h: delays up to 2047 samples (68 s)

  // Throws aurora_common::ConfigError on a missing or invalid parameter.
  ControllerNodeOf(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  using Core = DelayedController<kHistoryCapacity, Settings>;
  using Vehicle = typename Core::Vehicle;

  void onState(const aurora_msgs::DroneState::ConstPtr& msg);
  void onJoy(const sensor_msgs::Joy::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  void onRateCheck(const ros::WallTimerEvent& event);
  // dynamic_reconfigure's set_parameters, served here so that each value is
  // seen as the caller gave it (the stock server clamps first) and a refused
  // change fails the call (live_settings.h).
  bool onSetParameters(dynamic_reconfigure::Reconfigure::Request& req,
                       dynamic_reconfigure::Reconfigure::Response& rsp);
  void advertiseLiveSettings();
  dynamic_reconfigure::Config liveConfig() const;  // the settings in force, as the server shows them
  // age: of the newest state [s] (stateAge)
  void cycle(const ros::Time& now, double age);
  void logEvent(const std::string& event) const;
  void fillOutput(const ControlOutput& out, aurora_msgs::Control& control) const;
  // Says once when the task's time is up ("mission complete", the headline
  // metrics) and when a delay raised live is in force again.
  void reportProgress(const ControlOutput& out, const Reference<double>& ref,
                      const FlightDecision& decision, double task_time);
  void announceDelayChange(long delay);
  void sendCommand(const double U[kMaxInputs]);
  void serviceDriverCommands(double now, const double* fresh_X);
  void publishTaskMarkers();
  void fillLaw(aurora_msgs::Control& control) const;
  long readDelaySamples();  // ~delay/*, or kDelayNotGiven
  std::string linkName() const;
  std::string readLoopMode();  // sets lockstep_, timer_triggered_, the lockstep subscriber counts
  void connectTopics(const SafetyConfig& safety);
  void refuseDelayBeyondTheTask(long delay) const;
  // A ground robot's node refuses a drone's take-off and landing keys, a drone's a ground robot's speed limits.
  void refuseDroneOnlySafetyKeys() const;  // limits.h: shorter than the run
  void refuseUnknownTopLevelKeys();
  void loadPredictor();   // ~predictor (docs/predictor.md, "Configuration")
  void applyPredictor();  // the settings' form with predictor_base_'s model, over the link's command delay
  double stateAge(const ros::Time& now) const;  // [s] infinite before the first state
  bool lockstepListenersReady() const;

  ros::NodeHandle nh_, pnh_;
  double Ts_;
  bool lockstep_;
  bool timer_triggered_;  // realtime: compute on the 30 Hz timer instead of on each new state
  int lockstep_cmd_subscribers_ = 1;      // lockstep: subscribers of cmd_vel before the first step
  int lockstep_control_subscribers_ = 0;  // ... and of control
  Task<double> task_;
  long task_iterations_ = 0;  // the task's iteration count: a delay must be shorter

  std::unique_ptr<Core> core_;     // delay buffer, law, clamp, metrics (ROS-free)
  PredictorRun<Vehicle, double> predictor_base_;  // the predictor's model and horizon (form: settings.predictor)
  FlightSupervisor supervisor_;    // flight sequence and watchdogs (ROS-free)
  std::string state_frame_ = "world";
  ros::Time last_state_time_;      // ROS time the newest fresh state arrived
  ProcessStall stall_;             // this process's last stall, which the state's age leaves out
  bool warned_stale_input_ = false;
  bool mission_reported_ = false;          // "mission complete" said for this task
  bool delay_pending_announced_ = false;   // a live delay raise waits for history

  bool joystick_enabled_ = false;
  JoystickMapper joystick_;
  JoystickInput joy_;              // newest joystick input
  ResumeSlew resume_;
  double last_sent_[kMaxInputs] = {0, 0, 0, 0};  // the newest command sent (re-sent on a repeated state)

  long sent_in_window_ = 0;        // cmd_vel messages since the last rate check
  bool low_rate_ = false;

  boost::recursive_mutex config_mutex_;
  ros::ServiceServer set_parameters_;
  ros::Publisher descriptions_pub_, updates_pub_;
  ros::Publisher cmd_pub_, control_pub_, markers_pub_, desired_path_pub_;
  // Lockstep: each command also as cmd_vel_stamped, stamped with the state
  // it answers (answering_), on which the sim steps once per step.
  ros::Publisher step_cmd_pub_;
  int record_subscribers_ = 0;  // recorders of control to wait for before the first state (record:=true)
  bool recorderReady() const;
  ros::Time answering_;
  // take-off and land: held until the driver listens, re-sent until shown;
  // reset: sent once
  TakeoffLand takeoff_land_;
  DriverCommandChannel reset_;
  SafetyConfig safety_;
  ros::Subscriber state_sub_, joy_sub_;
  ros::Timer timer_;
  ros::WallTimer rate_timer_;
};

// The controller node: the law ~controller/name names (its controller file,
// loaded there), on that law's vehicle (~vehicle: its vehicle file).
struct ControllerOfLaw {
  static std::shared_ptr<void> make(ros::NodeHandle nh, ros::NodeHandle private_nh);
};
using ControllerNode = aurora_common::ChosenNode<ControllerOfLaw>;

}  // namespace aurora_control
