#include "mocap_estimator_node.h"

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include <cmath>
#include <vector>

#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "aurora_sim/vehicle/vehicle_type.h"

namespace aurora_control {

using aurora_common::fullKey;
using aurora_common::ConfigError;
using aurora_common::paramOr;

namespace {

std::vector<double> triple(const ros::NodeHandle& pnh, const std::string& key) {
  std::vector<double> v{0.0, 0.0, 0.0};
  if (pnh.hasParam(key) && (!pnh.getParam(key, v) || v.size() != 3)) {
    throw ConfigError("parameter '" + fullKey(pnh, key) + "' must be a list of 3 numbers");
  }
  return v;
}

}  // namespace

MocapEstimatorNode::MocapEstimatorNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), pnh_(private_nh) {
  vehicle_ = aurora_sim::loadVehicleOfFile(nh_, "vehicle");
  const double Ts = vehicle_.Ts;
  MocapFilterConfig filter;
  using aurora_common::rangedParam;
  filter.velocity_cutoff_hz =
      rangedParam(pnh_, "filter/velocity_cutoff_hz", filter.velocity_cutoff_hz, 0.0, 100.0, "Hz", false);
  filter.rate_cutoff_hz =
      rangedParam(pnh_, "filter/rate_cutoff_hz", filter.rate_cutoff_hz, 0.0, 100.0, "Hz", false);
  filter.max_gap = rangedParam(pnh_, "filter/max_gap", filter.max_gap, 0.0, 10.0, "s", false);
  estimator_ = MocapEstimator(filter);
  stale_timeout_ = rangedParam(pnh_, "stale_timeout", 0.1, 0.0, 10.0, "s", false);
  world_frame_ = paramOr<std::string>(pnh_, "world_frame", "world");
  // Poses in another frame (e.g. the mocap system's own) are mapped to the
  // world frame by a fixed transform, applied before differentiation so the
  // estimate does not jump.
  input_frame_ = paramOr<std::string>(pnh_, "input_frame", world_frame_);
  const std::vector<double> xyz = triple(pnh_, "input_to_world/xyz");
  const std::vector<double> rpy = triple(pnh_, "input_to_world/rpy");
  tf2::Quaternion q;
  q.setRPY(rpy[0], rpy[1], rpy[2]);
  input_to_world_ = tf2::Transform(q, tf2::Vector3(xyz[0], xyz[1], xyz[2]));

  state_pub_ = nh_.advertise<aurora_msgs::DroneState>("state", 10);
  pose_sub_ = nh_.subscribe("pose", 50, &MocapEstimatorNode::onPose, this,
                            ros::TransportHints().tcpNoDelay());
  // States go out at 1/Ts on a fixed schedule, each with the first pose at
  // or after its due time: the controller's rate, no drift of the step count
  // against time, and at most one pose period of added latency. The timer
  // only publishes while poses have stopped (stale states).
  Ts_ = Ts;
  timer_ = nh_.createTimer(ros::Duration(Ts), &MocapEstimatorNode::onTimer, this);
  ROS_INFO("mocap_estimator: %s -> %s at %.1f Hz, input frame '%s', filter cut-offs %.1f / %.1f Hz, "
           "stale after %.2f s",
           pose_sub_.getTopic().c_str(), state_pub_.getTopic().c_str(), 1.0 / Ts,
           input_frame_.c_str(), filter.velocity_cutoff_hz, filter.rate_cutoff_hz, stale_timeout_);
}

void MocapEstimatorNode::onPose(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  const auto& p = msg->pose.position;
  const auto& o = msg->pose.orientation;
  tf2::Transform pose(tf2::Quaternion(o.x, o.y, o.z, o.w), tf2::Vector3(p.x, p.y, p.z));
  const std::string& frame = msg->header.frame_id;
  if (frame == input_frame_ && input_frame_ != world_frame_) {
    pose = input_to_world_ * pose;
  } else if (!frame.empty() && frame != world_frame_) {
    if (!warned_frame_) {
      ROS_WARN("mocap_estimator: pose in frame '%s' ignored: accepted '%s' or '%s' (set ~input_frame "
               "and ~input_to_world)", frame.c_str(), world_frame_.c_str(), input_frame_.c_str());
      warned_frame_ = true;
    }
    return;
  }
  const double pos[3] = {pose.getOrigin().x(), pose.getOrigin().y(), pose.getOrigin().z()};
  double rpy[3];
  tf2::Matrix3x3(pose.getRotation()).getRPY(rpy[0], rpy[1], rpy[2]);
  for (double v : pos) if (!std::isfinite(v)) return;
  for (double v : rpy) if (!std::isfinite(v)) return;
  const auto result = estimator_.update(msg->header.stamp.toSec(), pos, rpy);
  if (result == MocapEstimator::Result::kNotNewer) {
    ++rejected_order_;
    ROS_DEBUG_THROTTLE(5.0, "mocap_estimator: %lu poses not newer than the last (dropped)", rejected_order_);
    return;
  }
  if (result == MocapEstimator::Result::kRestarted) {
    ROS_WARN("mocap_estimator: poses resumed after a gap: velocities restart from zero");
  }
  last_pose_arrival_ = ros::Time::now();
  if (next_due_.isZero() || (last_pose_arrival_ - next_due_).toSec() > Ts_) {
    next_due_ = last_pose_arrival_;  // start, or resynchronise after a gap
  }
  if (last_pose_arrival_ >= next_due_) {
    publish(false);
    next_due_ += ros::Duration(Ts_);
  }
}

void MocapEstimatorNode::onTimer(const ros::TimerEvent&) {
  if (!estimator_.initialized()) return;
  if ((ros::Time::now() - last_pose_arrival_).toSec() > stale_timeout_) publish(true);
}

void MocapEstimatorNode::publish(bool stale) {
  if (stale != was_stale_) {
    if (stale) {
      ROS_WARN("mocap_estimator: no pose for %.2f s: states marked stale", stale_timeout_);
    } else {
      ROS_INFO("mocap_estimator: poses are back");
    }
    was_stale_ = stale;
  }
  aurora_msgs::DroneState state;
  state.header.stamp = ros::Time(estimator_.stamp());
  state.header.frame_id = world_frame_;
  state.step = step_++;
  double body[aurora_sim::kStateSize], X[aurora_sim::kMaxStates];
  estimator_.state(body);
  vehicle_.state(body, X);  // the vehicle's state from its body's (its profile's stateFromBody)
  aurora_sim::stateToMsg(X, vehicle_.states, state);
  state.stale = stale;
  state_pub_.publish(state);
}

}  // namespace aurora_control
