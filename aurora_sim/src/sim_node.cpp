#include "sim_node.h"

#include "aurora_common/ros/node_main.h"
#include "aurora_common/ros/topic_publishers.h"

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2/LinearMath/Quaternion.h>

#include <cmath>
#include <limits>

#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/vehicle_half.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "aurora_sim/sim_parameters.h"
#include "aurora_sim/vehicle/vehicle_type.h"

namespace aurora_sim {

using aurora_common::ConfigError;
using aurora_common::flagParam;
using aurora_common::fullKey;
using aurora_common::paramOr;
using aurora_common::tableParam;
using aurora_common::textParam;
using aurora_common::wholeParam;
using aurora_common::wordParam;

namespace {
constexpr double kTakeoffClimb = 0.5;     // climb command during take-off (fraction)
constexpr double kLandingClimb = -0.5;    // climb command during landing (fraction)
}  // namespace

template <class Vehicle>
SimNode<Vehicle>::SimNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), pnh_(private_nh) {
  params_ = loadVehicleParams<Vehicle>(nh_, "vehicle", "this simulator");

  readParameters();

  resetModel();
  path_.header.frame_id = frame_id_;

  const bool lockstep = mode_ == Mode::kLockstep;
  // Deep queues: in lockstep a recorder must not lose a step when it lags.
  state_pub_ = nh_.advertise<aurora_msgs::DroneState>("state", 1000);
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>(Profile::odomTopic(), 1000);
  path_pub_ = nh_.advertise<nav_msgs::Path>("path", 1);
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  cmd_sub_ = nh_.subscribe("cmd_vel", 10, &SimNode::onCmdVel, this, hints);
  if (Profile::kFlies) {  // a ground robot's driver has no take-off or landing
    takeoff_sub_ = nh_.subscribe("takeoff", 1, &SimNode::onTakeoff, this);
    land_sub_ = nh_.subscribe("land", 1, &SimNode::onLand, this);
  }
  reset_sub_ = nh_.subscribe("reset", 1, &SimNode::onReset, this);

  if (lockstep) {
    // The sim owns the clock: one step per command that answers its newest
    // state (cmd_vel_stamped: the driver's Twist stamped with the state's
    // stamp), as fast as the controller answers; a second answer to a step
    // already taken is ignored, so the steps never depend on timing. Until
    // the first command arrives the initial state is re-sent, so a
    // controller that connects late still starts the loop.
    step_cmd_sub_ = nh_.subscribe("cmd_vel_stamped", 10, &SimNode::onStepCommand, this, hints);
    if (publish_clock_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 1000);
    retry_timer_ = nh_.createWallTimer(ros::WallDuration(0.2), &SimNode::onLockstepRetry,
                                       this);
    ROS_INFO("sim: %s, lockstep mode, Ts = %.6f s; starts once %s has %d subscriber(s)", Vehicle::name(),
             params_.Ts, state_pub_.getTopic().c_str(), lockstep_subscribers_);
  } else {
    start_time_ = ros::Time::now();
    timer_ = nh_.createTimer(ros::Duration(params_.Ts), &SimNode::onRealtimeTimer, this);
    ROS_INFO("sim: %s, realtime mode at %.3f Hz, cmd_timeout %.3f s", Vehicle::name(), 1.0 / params_.Ts,
             cmd_timeout_);
  }
}

// Every row of the simulator's parameter table (sim_parameters.h).
template <class Vehicle>
void SimNode<Vehicle>::readParameters() {
  const auto& rows = kSimParameterTable;
  mode_ = wordParam(pnh_, rows[kSimRowMode]) == "lockstep" ? Mode::kLockstep : Mode::kRealtime;
  cmd_timeout_ = tableParam(pnh_, rows[kSimRowCmdTimeout]);
  takeoff_altitude_ = tableParam(pnh_, rows[kSimRowTakeoffAltitude]);
  frame_id_ = textParam(pnh_, rows[kSimRowFrameId], rows[kSimRowFrameId].text);
  std::string ns = nh_.getNamespace();
  while (!ns.empty() && ns.front() == '/') ns.erase(ns.begin());
  child_frame_id_ = textParam(pnh_, rows[kSimRowChildFrameId], ns.empty() ? "base_link" : ns + "/base_link");
  path_decimation_ = static_cast<int>(wholeParam(pnh_, rows[kSimRowPathDecimation]));
  nan_quiet_period_ = tableParam(pnh_, rows[kSimRowNanQuietPeriod]);
  nan_burst_ = RejectionBurst(nan_quiet_period_, tableParam(pnh_, rows[kSimRowNanSummaryPeriod]));
  stop_after_ = tableParam(pnh_, rows[kSimRowStopAfter]);
  lockstep_subscribers_ = static_cast<int>(wholeParam(pnh_, rows[kSimRowLockstepSubscribers]));
  max_real_time_factor_ = tableParam(pnh_, rows[kSimRowMaxRealTimeFactor]);
  // The study's initial state (z = 0.75 m, in the air); false starts landed.
  // A ground robot drives from the first state.
  flight_ = !Profile::kFlies || flagParam(pnh_, rows[kSimRowStartFlying]) ? Flight::kFlying : Flight::kLanded;
  readStart();
  // Several sims in lockstep (formation.launch): one of them owns /clock.
  publish_clock_ = flagParam(pnh_, rows[kSimRowPublishClock]);
}

namespace {

double xmlNumber(XmlRpc::XmlRpcValue& v, const std::string& key) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
  throw ConfigError("parameter '" + key + "' = " + v.toXml() + " is invalid: accepted a number [m]");
}

}  // namespace

// Where the robot starts: ~start [x, y, z] [m], else (0, 0, 0.75); its body
// there, or (~start_at_state_point, formation.launch) the point its state
// gives (a Pioneer's control point).
template <class Vehicle>
void SimNode<Vehicle>::readStart() {
  const char* start = kSimParameterTable[kSimRowStart].name;
  start_at_state_point_ = flagParam(pnh_, kSimParameterTable[kSimRowStartAtStatePoint]);
  XmlRpc::XmlRpcValue list;
  const std::string key = fullKey(pnh_, start);
  if (!pnh_.getParam(start, list)) return;
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray || list.size() != 3) {
    throw ConfigError("parameter '" + key + "' is invalid: accepted [x, y, z] in m");
  }
  for (int j = 0; j < 3; ++j) start_[j] = xmlNumber(list[j], key);
  if (!Profile::kFlies && start_[2] != 0.0) {
    throw ConfigError("parameter '" + key + "' is invalid: a " + Vehicle::name() +
                      " is a ground robot: accepted [x, y, 0] in m (its centre on the floor)");
  }
}

template <class Vehicle>
void SimNode<Vehicle>::resetModel() {
  // In the air at the start (the study's initial state unless ~start), or on
  // the ground below it when landed (sim_profile.h).
  const double at[3] = {start_[0], start_[1], flight_ == Flight::kLanded ? 0.0 : start_[2]};
  Profile::place(params_, model_, at);
  // A formation's start is where the state lies (formation_runner.h,
  // startFormation: AuRoRA's rSetPose on a Pioneer's control point).
  if (start_at_state_point_) {
    for (int i = 0; i < 3; ++i) model_.X[kX + i] = at[i];
  }
  step_ = 0;
  have_command_ = false;
  for (double& u : command_) u = 0.0;
  path_.poses.clear();
}

template <class Vehicle>
ros::Time SimNode<Vehicle>::lockstepTime() const {
  // Integer nanoseconds of step * Ts, so stamps never drift by accumulation.
  return ros::Time().fromNSec(static_cast<uint64_t>(std::llround(double(step_) * params_.Ts * 1e9)));
}

// Realtime: the driver's command, applied at the next timer step. In
// lockstep cmd_vel names no step: the sim steps on cmd_vel_stamped only.
template <class Vehicle>
void SimNode<Vehicle>::onCmdVel(const geometry_msgs::Twist::ConstPtr& msg) {
  if (mode_ == Mode::kLockstep) return;
  takeCommand(*msg);
}

// Lockstep: a command stamped with the state it answers steps the sim when
// that state is its newest (lockstepTime() of its step), once: a controller
// answering a re-sent state twice (a stall longer than the re-send period)
// sends the second answer with an older stamp, or after the step.
template <class Vehicle>
void SimNode<Vehicle>::onStepCommand(const geometry_msgs::TwistStamped::ConstPtr& msg) {
  if (!lockstep_started_) return;
  if (msg->header.stamp != lockstepTime()) {
    if (answers_ignored_++ == 0) {
      ROS_INFO("sim: ignored a command answering step %.0f, already taken (now at step %lu); such answers are "
               "counted, not stepped on", msg->header.stamp.toSec() / params_.Ts, step_);
    }
    return;
  }
  takeCommand(msg->twist);
  lockstepStep();
}

template <class Vehicle>
void SimNode<Vehicle>::takeCommand(const geometry_msgs::Twist& msg) {
  double U[Vehicle::kInputs];
  Vehicle::fromDriver(twistCommandFromMsg(msg), U);
  const double t = ros::WallTime::now().toSec();
  logBurst(nan_burst_.poll(t));
  if (!allFinite(U, Vehicle::kInputs)) {
    const BurstReport started = nan_burst_.rejected(t);
    if (started.kind == BurstReport::kStarted) {
      ROS_WARN("sim: rejected cmd_vel with NaN/Inf (linear %g %g %g, angular.z %g): the "
               "drone hovers on each such command; further ones are counted until none for %.1f s",
               msg.linear.x, msg.linear.y, msg.linear.z, msg.angular.z, nan_quiet_period_);
    }
    for (double& u : command_) u = 0.0;
  } else {
    nan_burst_.accepted();
    for (int i = 0; i < Vehicle::kInputs; ++i) command_[i] = U[i];  // clamped as the driver does, by vehicleHalf
  }
  have_command_ = true;
  command_time_ = ros::Time::now();
}

template <class Vehicle>
void SimNode<Vehicle>::lockstepStep() {
  if (max_real_time_factor_ > 0.0) {
    // Leave the CPU to subscribers that must not lose a step (rosbag's
    // subscription queue is 100 messages deep and cannot be changed).
    const ros::WallTime due = last_step_wall_ + ros::WallDuration(params_.Ts / max_real_time_factor_);
    const ros::WallTime now = ros::WallTime::now();
    if (now < due) (due - now).sleep();
  }
  last_step_wall_ = ros::WallTime::now();
  stepAndPublish(lockstepTime(), true);
}

template <class Vehicle>
void SimNode<Vehicle>::logBurst(const BurstReport& r) const {
  if (r.kind == BurstReport::kSummary) {
    ROS_WARN("sim: still rejecting NaN/Inf cmd_vel: %lu rejected (and %lu finite accepted) "
             "in the last %.1f s", r.rejected, r.accepted, r.span);
  } else if (r.kind == BurstReport::kEnded) {
    ROS_INFO("sim: no NaN/Inf cmd_vel for %.1f s: the burst ended after %lu rejected (and "
             "%lu finite accepted) over %.1f s", nan_quiet_period_, r.rejected, r.accepted, r.span);
  }
}

template <class Vehicle>
void SimNode<Vehicle>::onTakeoff(const std_msgs::Empty::ConstPtr&) {
  if (flight_ == Flight::kLanded) {
    ROS_INFO("sim: taking off to %.2f m", takeoff_altitude_);
    flight_ = Flight::kTakingOff;
  }
}

template <class Vehicle>
void SimNode<Vehicle>::onLand(const std_msgs::Empty::ConstPtr&) {
  if (flight_ == Flight::kFlying || flight_ == Flight::kTakingOff) {
    ROS_INFO("sim: landing");
    flight_ = Flight::kLanding;
  }
}

template <class Vehicle>
void SimNode<Vehicle>::onReset(const std_msgs::Empty::ConstPtr&) {
  ROS_INFO("sim: reset to the initial state");
  flight_ = !Profile::kFlies || aurora_common::boolParam(pnh_, "start_flying", true) ? Flight::kFlying : Flight::kLanded;
  resetModel();
}

template <class Vehicle>
void SimNode<Vehicle>::onRealtimeTimer(const ros::TimerEvent& event) {
  logBurst(nan_burst_.poll(ros::WallTime::now().toSec()));
  const ros::Time now = event.current_real;
  const bool fresh = have_command_ && (now - command_time_).toSec() <= cmd_timeout_;
  stepAndPublish(now, fresh);
}

template <class Vehicle>
void SimNode<Vehicle>::onLockstepRetry(const ros::WallTimerEvent&) {
  if (!lockstep_started_) {
    // Wait for the controller (and a recorder) so the first states are not
    // published into the void; then give their other subscriptions (cmd_vel,
    // control, /clock) one more retry period to connect.
    if (static_cast<int>(state_pub_.getNumSubscribers()) < lockstep_subscribers_) {
      ROS_INFO_THROTTLE(5.0, "sim: lockstep waiting for %d subscriber(s) of %s (%u now)",
                        lockstep_subscribers_, state_pub_.getTopic().c_str(),
                        state_pub_.getNumSubscribers());
      return;
    }
    if (last_publish_wall_.isZero()) {
      refuseSecondClockOwner();
      last_publish_wall_ = ros::WallTime::now();
      return;
    }
    lockstep_started_ = true;
    lockstep_start_wall_ = ros::WallTime::now();
    ROS_INFO("sim: lockstep started");
    publishState(lockstepTime());
    return;
  }
  // Re-send the newest state when the loop has stalled (a controller that
  // missed our publication never answered). The controller answers a
  // re-sent state it already answered with that step's command again, and
  // the sim steps on one answer per step (onStepCommand), so a re-send to a
  // controller that was only slow (a busy machine) costs a message, not a
  // step; a second keeps re-sends rare.
  constexpr double kStalledAfter = 1.0;  // [s] wall
  if ((ros::WallTime::now() - last_publish_wall_).toSec() > kStalledAfter) {
    publishState(lockstepTime());
  }
}

// Two sims owning /clock (several robots launched with ~publish_clock left
// at its default) set every node's time back and forth between their steps:
// a recorder stops writing at the first message it receives on a clock gone
// back to 0, and timers fire out of order. Checked once the loop's nodes are
// there, before the first step: a sim that finds another owner refuses.
template <class Vehicle>
void SimNode<Vehicle>::refuseSecondClockOwner() const {
  if (!publish_clock_) return;
  for (const std::string& node : aurora_common::publishersOf(clock_pub_.getTopic())) {
    if (node == ros::this_node::getName()) continue;
    throw ConfigError("parameter '" + fullKey(pnh_, kSimParameterTable[kSimRowPublishClock].name) +
                      "' = true, but " + node + " publishes " + clock_pub_.getTopic() +
                      " too: in lockstep one sim owns the clock (formation.launch: robot 1's); set publish_clock "
                      "to false on every other sim");
  }
}

template <class Vehicle>
void SimNode<Vehicle>::stepAndPublish(const ros::Time& now, bool command_fresh) {
  double U[Vehicle::kInputs] = {};  // hover (a ground robot: stop)
  // Landed, the drone rests (no model step) but time goes on: each state is
  // a new sample (a new step), so a listener sees a live source, not
  // re-sends, and a lockstep run still reaches stop_after.
  const bool resting = flight_ == Flight::kLanded;
  switch (flight_) {
    case Flight::kLanded:
      break;
    case Flight::kTakingOff:
      U[Profile::kClimbInput] = kTakeoffClimb;
      if (model_.X[kZ] >= takeoff_altitude_) flight_ = Flight::kFlying;
      break;
    case Flight::kLanding:
      U[Profile::kClimbInput] = kLandingClimb;
      break;
    case Flight::kFlying:
      if (command_fresh) {
        for (int i = 0; i < Vehicle::kInputs; ++i) U[i] = command_[i];
      }
      break;
  }
  // The vehicle's half of every loop (vehicle_half.h): a flying vehicle's
  // commands clamped as its driver does (the climb of a take-off or a
  // landing is the node's own), then its model's step.
  if (!resting) vehicleHalf<Vehicle>(params_, flight_ == Flight::kFlying, U, model_, U);  // U: as applied
  ++step_;
  // The ground holds the drone while its rotors spin up or it touches down.
  // (In flight there is no ground, as in the study's model, so a flight
  // stays identical to the offline runner's.)
  if ((flight_ == Flight::kTakingOff || flight_ == Flight::kLanding) && model_.X[kZ] < 0.0) {
    model_.X[kZ] = 0.0;
    if (model_.X[kVz] < 0.0) model_.X[kVz] = 0.0;
  }
  if (flight_ == Flight::kLanding && model_.X[kZ] <= kLandedAltitude) {
    ROS_INFO("sim: landed");
    flight_ = Flight::kLanded;
    const double at[3] = {model_.X[kX], model_.X[kY], 0.0}, yaw = model_.X[kYaw];
    Profile::place(params_, model_, at);
    model_.X[kYaw] = yaw;
  }
  publishState(mode_ == Mode::kLockstep ? lockstepTime() : now);
  const double elapsed =
      mode_ == Mode::kLockstep ? double(step_) * params_.Ts : (now - start_time_).toSec();
  if (stop_after_ > 0.0 && elapsed >= stop_after_ - 1e-9) {
    if (mode_ == Mode::kLockstep) {
      const double wall = (ros::WallTime::now() - lockstep_start_wall_).toSec();
      ROS_INFO("sim: stop_after %.3f s reached after %lu steps in %.3f s wall "
               "(sim time / wall time = %.1f): shutting down",
               stop_after_, step_, wall, elapsed / wall);
    } else {
      ROS_INFO("sim: stop_after %.3f s reached after %lu steps: shutting down",
               stop_after_, step_);
    }
    timer_.stop();
    retry_timer_.stop();
    cmd_sub_.shutdown();
    step_cmd_sub_.shutdown();
    // A short grace period lets subscribers (rosbag) receive the last state.
    shutdown_timer_ = nh_.createWallTimer(
        ros::WallDuration(0.5), [](const ros::WallTimerEvent&) { aurora_common::endAsPlanned(); }, true);
  }
}

template <class Vehicle>
void SimNode<Vehicle>::publishState(const ros::Time& stamp) {
  if (mode_ == Mode::kLockstep && publish_clock_) {
    rosgraph_msgs::Clock clock;
    clock.clock = stamp;
    clock_pub_.publish(clock);
  }
  last_publish_wall_ = ros::WallTime::now();
  const double* X = model_.X;

  aurora_msgs::DroneState state;
  state.header.stamp = stamp;
  state.header.frame_id = frame_id_;
  state.step = step_;
  stateToMsg(X, Vehicle::kStates, state);
  state.stale = false;
  state_pub_.publish(state);

  tf2::Quaternion q;
  q.setRPY(X[kRoll], X[kPitch], X[kYaw]);
  geometry_msgs::TransformStamped tf;
  tf.header.stamp = stamp;
  tf.header.frame_id = frame_id_;
  tf.child_frame_id = child_frame_id_;
  double body[3];  // the body's origin (its profile's bodyPosition: a ground robot's centre)
  Profile::bodyPosition(params_, X, body);
  tf.transform.translation.x = body[0];
  tf.transform.translation.y = body[1];
  tf.transform.translation.z = body[2];
  tf.transform.rotation.x = q.x();
  tf.transform.rotation.y = q.y();
  tf.transform.rotation.z = q.z();
  tf.transform.rotation.w = q.w();
  tf_.sendTransform(tf);

  if (odom_pub_.getNumSubscribers() > 0) {
    // nav_msgs/Odometry convention (the real driver's topic): the body's
    // pose in frame_id, its twist in the child frame (body axes).
    nav_msgs::Odometry odom;
    odom.header = tf.header;
    odom.child_frame_id = child_frame_id_;
    odom.pose.pose.position.x = body[0];
    odom.pose.pose.position.y = body[1];
    odom.pose.pose.position.z = body[2];
    odom.pose.pose.orientation = tf.transform.rotation;
    double linear[3], angular[3];
    Profile::bodyTwist(params_, X, linear, angular);
    odom.twist.twist.linear.x = linear[0], odom.twist.twist.linear.y = linear[1], odom.twist.twist.linear.z = linear[2];
    odom.twist.twist.angular.x = angular[0], odom.twist.twist.angular.y = angular[1];
    odom.twist.twist.angular.z = angular[2];
    odom_pub_.publish(odom);
  }

  if (step_ % static_cast<unsigned long>(path_decimation_) == 0) {
    geometry_msgs::PoseStamped pose;
    pose.header = tf.header;
    pose.pose.position.x = X[kX];
    pose.pose.position.y = X[kY];
    pose.pose.position.z = X[kZ];
    pose.pose.orientation = tf.transform.rotation;
    path_.header.stamp = stamp;
    path_.poses.push_back(pose);
    if (path_.poses.size() > 20000) path_.poses.erase(path_.poses.begin());
    if (path_pub_.getNumSubscribers() > 0) path_pub_.publish(path_);
  }
}

std::shared_ptr<void> SimOfVehicle::make(ros::NodeHandle nh, ros::NodeHandle private_nh) {
  std::string type;
  nh.getParam("vehicle/type", type);
  std::shared_ptr<void> node;
  withVehicleOfType(type, [&](auto vehicle) { node = std::make_shared<SimNode<decltype(vehicle)>>(nh, private_nh); });
  return node;
}

}  // namespace aurora_sim
