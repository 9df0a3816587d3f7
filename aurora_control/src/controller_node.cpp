#include "controller_node.h"

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>

#include "aurora_control/task_check.h"
#include "aurora_sim/command_mapping.h"
#include "aurora_sim/ros_conversions.h"
#include "aurora_sim/ros_params.h"

namespace aurora_control {

using aurora_sim::fullKey;
using aurora_sim::ParameterError;
using aurora_sim::paramOr;
using aurora_sim::requireParam;

namespace {

double requireGain(const ros::NodeHandle& pnh, const std::string& key) {
  const double value = requireParam<double>(pnh, key, "a number in [0, 10]");
  if (!(std::isfinite(value) && value >= 0.0 && value <= 10.0)) {
    throw ParameterError("parameter '" + fullKey(pnh, key) + "' = " + std::to_string(value) +
                         " is invalid: accepted range [0, 10]");
  }
  return value;
}

double xmlNumber(XmlRpc::XmlRpcValue& v, const std::string& key) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw ParameterError("'" + key + "' must be a number");
}

WaypointTask<double> loadTask(const ros::NodeHandle& pnh) {
  const std::string prefix = fullKey(pnh, "task") + "/";
  XmlRpc::XmlRpcValue waypoints, end_times;
  if (!pnh.getParam("task/waypoints", waypoints) ||
      waypoints.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParameterError("missing parameter '" + prefix +
                         "waypoints' (accepted: a list of [x, y, z] in m; load a task file "
                         "such as config/tasks/mission4.yaml, launch arg 'task')");
  }
  if (!pnh.getParam("task/end_times", end_times) ||
      end_times.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      end_times.size() != waypoints.size()) {
    throw ParameterError("parameter '" + prefix +
                         "end_times' must be a list with one time [s] per waypoint");
  }
  WaypointTask<double> task;
  task.count = waypoints.size();
  if (task.count > 16) task.count = 17;  // rejected by checkTask with the accepted range
  for (int i = 0; i < waypoints.size() && i < 16; ++i) {
    const std::string key = prefix + "waypoints[" + std::to_string(i) + "]";
    if (waypoints[i].getType() != XmlRpc::XmlRpcValue::TypeArray || waypoints[i].size() != 3) {
      throw ParameterError("'" + key + "' must be [x, y, z] in m");
    }
    for (int j = 0; j < 3; ++j) task.position[i][j] = xmlNumber(waypoints[i][j], key);
    task.end_time[i] = xmlNumber(end_times[i], prefix + "end_times");
  }
  task.duration = requireParam<double>(pnh, "task/duration", "a time in (0, 86400] s");
  const std::string problem = checkTask(task, prefix);
  if (!problem.empty()) throw ParameterError(problem);
  return task;
}

}  // namespace

ControllerNode::ControllerNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), pnh_(private_nh), reconfigure_(config_mutex_, private_nh) {
  // The controller needs only Ts of the vehicle; it is read with the same
  // range rules as the sim's.
  Ts_ = aurora_sim::loadVehicleParams(nh_, "vehicle").Ts;

  const std::string name = requireParam<std::string>(pnh_, "controller/name", "'pd_saturated'");
  if (name != "pd_saturated") {
    throw ParameterError("parameter '" + fullKey(pnh_, "controller/name") + "' = '" + name +
                         "' is unknown: accepted controllers: 'pd_saturated'");
  }
  core_.reset(new Core());
  ControllerSettings& set = core_->settings;
  set.Ts = Ts_;
  set.gains.kp = requireGain(pnh_, "controller/kp");
  set.gains.kd = requireGain(pnh_, "controller/kd");
  set.delay = readDelaySamples();
  set.clamp_commands = paramOr(pnh_, "clamp_commands", true);
  const std::string mode = paramOr<std::string>(pnh_, "mode", "realtime");
  if (mode != "realtime" && mode != "lockstep") {
    throw ParameterError("parameter '" + fullKey(pnh_, "mode") + "' = '" + mode +
                         "' is invalid: accepted values 'realtime', 'lockstep'");
  }
  lockstep_ = mode == "lockstep";
  // Realtime: by default the law runs as soon as a state arrives (lowest
  // latency, AuRoRA's read-then-send loop); the 30 Hz timer is then the
  // stale-state watchdog. trigger=timer runs the law on the timer only, on
  // the newest state received.
  const std::string trigger = paramOr<std::string>(pnh_, "trigger", "state");
  if (trigger != "state" && trigger != "timer") {
    throw ParameterError("parameter '" + fullKey(pnh_, "trigger") + "' = '" + trigger +
                         "' is invalid: accepted values 'state', 'timer'");
  }
  timer_triggered_ = !lockstep_ && trigger == "timer";
  stale_timeout_ = paramOr(pnh_, "stale_timeout", 0.5);
  if (!(stale_timeout_ > 0.0 && stale_timeout_ <= 60.0)) {
    throw ParameterError("parameter '" + fullKey(pnh_, "stale_timeout") +
                         "' is invalid: accepted range (0, 60] s");
  }
  task_ = loadTask(pnh_);

  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1000);
  control_pub_ = nh_.advertise<aurora_msgs::Control>("control", 1000);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("waypoints", 1, true);
  desired_path_pub_ = nh_.advertise<nav_msgs::Path>("desired_path", 1, true);
  state_sub_ = nh_.subscribe("state", 100, &ControllerNode::onState, this,
                             ros::TransportHints().tcpNoDelay());

  ControllerConfig config;
  config.kp = set.gains.kp;
  config.kd = set.gains.kd;
  config.delay_samples = static_cast<int>(set.delay);
  reconfigure_.updateConfig(config);
  reconfigure_.setCallback([this](ControllerConfig& c, uint32_t level) { onReconfigure(c, level); });

  if (!lockstep_) {
    timer_ = nh_.createTimer(ros::Duration(Ts_), &ControllerNode::onTimer, this);
  }
  publishTaskMarkers();
  ROS_INFO("controller: pd_saturated Kp=%g Kd=%g, delay %ld samples (%.4f s), %s commands, "
           "%s mode, task of %d waypoints over %.1f s",
           set.gains.kp, set.gains.kd, set.delay, set.delay * Ts_,
           set.clamp_commands ? "clamped" : "unclamped", mode.c_str(), task_.count, task_.duration);
}

long ControllerNode::readDelaySamples() {
  static_assert(Core::kMaxDelay == kHistoryCapacity - 1, "delay range follows the history");
  const bool has_samples = pnh_.hasParam("delay/samples");
  const bool has_seconds = pnh_.hasParam("delay/seconds");
  const std::string accepted = "integer samples in [0, " +
                               std::to_string(kHistoryCapacity - 1) + "]";
  if (has_samples && has_seconds) {
    throw ParameterError("both '" + fullKey(pnh_, "delay/samples") + "' and '" +
                         fullKey(pnh_, "delay/seconds") + "' are set: give only one");
  }
  if (has_seconds) {
    double seconds = 0.0;
    if (!pnh_.getParam("delay/seconds", seconds) || !std::isfinite(seconds) || seconds < 0.0 ||
        seconds / Ts_ > kHistoryCapacity - 1) {
      throw ParameterError("parameter '" + fullKey(pnh_, "delay/seconds") +
                           "' is invalid: accepted range [0, " +
                           std::to_string((kHistoryCapacity - 1) * Ts_) + "] s");
    }
    const long samples = std::lround(seconds / Ts_);
    ROS_INFO("controller: delay %.6f s rounded to %ld whole samples of Ts = %.6f s (%.6f s)",
             seconds, samples, Ts_, samples * Ts_);
    return samples;
  }
  int samples = 0;
  if (has_samples && !pnh_.getParam("delay/samples", samples)) {
    throw ParameterError("parameter '" + fullKey(pnh_, "delay/samples") +
                         "' must be an integer: accepted " + accepted);
  }
  if (samples < 0 || samples > kHistoryCapacity - 1) {
    throw ParameterError("parameter '" + fullKey(pnh_, "delay/samples") + "' = " +
                         std::to_string(samples) + " is invalid: accepted " + accepted);
  }
  return samples;
}

void ControllerNode::onReconfigure(ControllerConfig& config, uint32_t) {
  ControllerSettings& set = core_->settings;
  if (config.kp != set.gains.kp || config.kd != set.gains.kd || config.delay_samples != set.delay) {
    ROS_INFO("controller: reconfigured Kp=%g Kd=%g delay=%d samples", config.kp, config.kd,
             config.delay_samples);
  }
  set.gains.kp = config.kp;
  set.gains.kd = config.kd;
  set.delay = config.delay_samples;
}

void ControllerNode::onState(const aurora_msgs::DroneState::ConstPtr& msg) {
  StateSample sample;
  sample.step = static_cast<long>(msg->step);
  sample.stamp_ns = static_cast<int64_t>(msg->header.stamp.toNSec());
  aurora_sim::stateFromMsg(*msg, sample.X);
  const bool went_back = !core_->empty() && sample.step < core_->newest().step;
  if (!core_->push(sample)) {
    // The lockstep sim re-sends a state it got no answer to: answer again
    // with the same command; the history already holds this sample.
    if (lockstep_ && have_control_) {
      cmd_pub_.publish(aurora_sim::twistMsgFromModelCommand(last_control_.command.data()));
    }
    return;
  }
  if (went_back) {
    ROS_INFO("controller: state step went back to %ld (source reset): history cleared",
             sample.step);
  }
  if (!msg->header.frame_id.empty()) state_frame_ = msg->header.frame_id;
  last_state_time_ = ros::Time::now();
  if (stale_) {
    ROS_INFO("controller: state stream is back");
    stale_ = false;
  }
  if (lockstep_) {
    cycle(msg->header.stamp);
  } else if (!timer_triggered_) {
    cycle(ros::Time::now());
  }
}

void ControllerNode::onTimer(const ros::TimerEvent& event) {
  const bool stale = (ros::Time::now() - last_state_time_).toSec() > stale_timeout_;
  if (timer_triggered_ || stale) cycle(event.current_real);
}

void ControllerNode::cycle(const ros::Time& now) {
  if (core_->empty()) return;  // waiting for the first state
  boost::recursive_mutex::scoped_lock lock(config_mutex_);
  const ControllerSettings& set = core_->settings;
  const StateSample& newest = core_->newest();
  const int wp = task_.activeIndex(WaypointTask<double>::timeOfStep(newest.step, Ts_));

  const bool stale = !lockstep_ && (ros::Time::now() - last_state_time_).toSec() > stale_timeout_;
  if (stale && !stale_) {
    ROS_WARN("controller: no state for %.2f s (> %.2f s): commanding hover",
             (ros::Time::now() - last_state_time_).toSec(), stale_timeout_);
    stale_ = true;
  }
  const ControlOutput out = stale ? core_->hover() : core_->compute(task_.position[wp]);

  aurora_msgs::Control control;
  control.header.stamp = now;
  control.header.frame_id = "world";
  control.step = newest.step;
  control.waypoint_index = wp;
  control.desired_position.x = task_.position[wp][0];
  control.desired_position.y = task_.position[wp][1];
  control.desired_position.z = task_.position[wp][2];
  control.delay_samples = set.delay;
  control.delay_in_force = static_cast<uint32_t>(out.delay_in_force);
  control.delay_seconds = set.delay * Ts_;
  control.sample_time = Ts_;
  control.kp = set.gains.kp;
  control.kd = set.gains.kd;
  control.clamped = set.clamp_commands;
  control.mode = stale ? "hover (stale state)" : "fly";
  control.state_used.header.stamp.fromNSec(static_cast<uint64_t>(out.used->stamp_ns));
  control.state_used.header.frame_id = state_frame_;
  control.state_used.step = out.used->step;
  aurora_sim::stateToMsg(out.used->X, control.state_used);
  control.position_error.x = out.position_error[0];
  control.position_error.y = out.position_error[1];
  control.position_error.z = out.position_error[2];
  for (int i = 0; i < 4; ++i) {
    control.command[i] = out.U[i];
    control.command_unclamped[i] = out.U_unclamped[i];
  }
  control.iae = out.iae;
  control.itae = out.itae;
  control.iasc = out.iasc;
  cmd_pub_.publish(aurora_sim::twistMsgFromModelCommand(out.U));
  control_pub_.publish(control);
  last_control_ = control;
  have_control_ = true;
}

void ControllerNode::publishTaskMarkers() {
  visualization_msgs::MarkerArray markers;
  nav_msgs::Path path;
  path.header.frame_id = "world";
  path.header.stamp = ros::Time(0);
  for (int i = 0; i < task_.count; ++i) {
    visualization_msgs::Marker m;
    m.header.frame_id = "world";
    m.ns = "waypoints";
    m.id = i;
    m.type = visualization_msgs::Marker::SPHERE;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.position.x = task_.position[i][0];
    m.pose.position.y = task_.position[i][1];
    m.pose.position.z = task_.position[i][2];
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 0.12;
    m.color.r = 0.9f;
    m.color.a = 1.0f;
    markers.markers.push_back(m);
    visualization_msgs::Marker label = m;
    label.ns = "waypoint_labels";
    label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    label.text = std::to_string(i + 1);
    label.pose.position.z += 0.15;
    label.color.r = label.color.g = label.color.b = 1.0f;
    markers.markers.push_back(label);
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose = m.pose;
    path.poses.push_back(pose);
  }
  markers_pub_.publish(markers);
  desired_path_pub_.publish(path);
}

}  // namespace aurora_control
