// Driver-compatible fake for the real-drone tests: listens on the driver's
// topics, relative to its namespace as the drivers' are (ardrone_autonomy:
// cmd_vel, ardrone/takeoff|land|reset; bebop_autonomy in its launch's
// namespace: bebop/cmd_vel, bebop/takeoff|land|reset), flies the model
// core on cmd_vel with the drivers' sign conventions and clamping, and
// publishes a motion-capture PoseStamped at 120 Hz with small noise,
// occasional dropouts and out-of-order stamps (seeded, deterministic).
// Test hooks: ~true_state (DroneState), ~pause_mocap (Float64: seconds),
// ~received (String, latched: "takeoff=N land=N reset=N", every message
// received, ignored ones included). A late or not-yet-ready driver:
// ~takeoff_subscribe_after [s] subscribes to take-off only after that long;
// ~ignore_takeoffs, ~ignore_lands [count] drop the first ones received.
// ~start [x, y] (m, world frame): where it stands on the ground at first.
// ~command_latency, ~command_jitter [s]: each cmd_vel takes effect that
// long after it arrives, plus a uniform 0 .. jitter (the driver's and the
// radio's delay, which no message declares: what identify must find),
// counted from the message's receipt (not from when its callback runs).
// The model steps at its own nominal times t0 + m Ts, caught up to the
// current time whenever a timer runs (a late callback steps the steps due
// with the commands in force at their times), so a loaded machine delays
// the messages, as a real robot's radio would, and not the robot's physics;
// each step [t - Ts, t] flies the commands in force over it, averaged (a
// command acts from its due time, not from the model's next step), and a
// pose between steps lies on the way to the next one (not a staircase).
// The vehicle is the one of the file loaded under ~vehicle (its type: an
// AR.Drone 2.0 or a Bebop 2, each with its own model and cmd_vel mapping;
// or a Pioneer P3-DX behind RosAria: RosAria/cmd_vel, no take-off or
// landing, driving from the start, the mocap pose of its centre).
#include <aurora_msgs/DroneState.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Transform.h>

#include <algorithm>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sim/command_mapping.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"

namespace {

using namespace aurora_sim;
using namespace aurora_common;

template <class Vehicle>
class FakeDriver {
 public:
  using Profile = SimProfile<Vehicle>;

  FakeDriver(ros::NodeHandle nh, ros::NodeHandle pnh) : rng_(pnh.param("seed", 1)) {
    params_ = loadVehicleParams<Vehicle>(pnh, "vehicle", "the fake driver");
    const std::string driver = pnh.param<std::string>("driver", "ardrone");
    if (driver != "ardrone" && driver != "bebop" && driver != "rosaria") {
      throw ConfigError("~driver: ardrone, bebop or rosaria");
    }
    const std::string prefix = driver == "ardrone" ? "ardrone/" : driver == "bebop" ? "bebop/" : "RosAria/";
    const std::string cmd = driver == "ardrone" ? "cmd_vel" : prefix + "cmd_vel";
    noise_pos_ = pnh.param("noise_position", 0.0005);
    noise_ang_ = pnh.param("noise_angle", 0.05 * kPi / 180.0);
    dropout_ = pnh.param("dropout_probability", 0.03);
    reorder_ = pnh.param("reorder_probability", 0.02);
    latency_ = pnh.param("command_latency", 0.0);
    jitter_ = pnh.param("command_jitter", 0.0);
    if (!(latency_ >= 0.0 && latency_ <= 1.0) || !(jitter_ >= 0.0 && jitter_ <= 1.0)) {
      throw ConfigError("~command_latency, ~command_jitter: seconds in [0, 1]");
    }
    frame_ = pnh.param<std::string>("mocap_frame", "world");
    std::vector<double> xyz{0, 0, 0}, rpy{0, 0, 0};
    pnh.getParam("mocap_to_world/xyz", xyz);
    pnh.getParam("mocap_to_world/rpy", rpy);
    tf2::Quaternion q;
    q.setRPY(rpy[0], rpy[1], rpy[2]);
    world_to_mocap_ = tf2::Transform(q, tf2::Vector3(xyz[0], xyz[1], xyz[2])).inverse();

    std::vector<double> start{0, 0};
    pnh.getParam("start", start);
    if (start.size() != 2) throw ConfigError("~start: [x, y] in metres");
    const double at[3] = {start[0], start[1], 0.0};
    Profile::place(params_, model_, at);  // on the ground, rotors stopped
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    subs_.push_back(nh.subscribe(cmd, 10, &FakeDriver::onCmd, this, hints));
    ignore_takeoffs_ = pnh.param("ignore_takeoffs", 0);
    ignore_lands_ = pnh.param("ignore_lands", 0);
    const double late = pnh.param("takeoff_subscribe_after", 0.0);
    const std::string takeoff = prefix + "takeoff";
    if (!Profile::kFlies) {  // RosAria: no take-off or landing; it drives from the start
      phase_ = Phase::kFlying;
    } else if (late > 0.0) {
      late_timer_ = nh.createWallTimer(ros::WallDuration(late), [this, nh, takeoff](const ros::WallTimerEvent&) {
        ros::NodeHandle n(nh);
        subs_.push_back(n.subscribe(takeoff, 1, &FakeDriver::onTakeoff, this));
        ROS_INFO("fake_driver: subscribed to %s late", takeoff.c_str());
      }, true);
    } else {
      subs_.push_back(nh.subscribe(takeoff, 1, &FakeDriver::onTakeoff, this));
    }
    if (Profile::kFlies) {
      subs_.push_back(nh.subscribe(prefix + "land", 1, &FakeDriver::onLand, this));
      subs_.push_back(nh.subscribe(prefix + "reset", 1, &FakeDriver::onReset, this));
    }
    subs_.push_back(pnh.subscribe("pause_mocap", 1, &FakeDriver::onPause, this));
    pose_pub_ = nh.advertise<geometry_msgs::PoseStamped>(pnh.param<std::string>("pose_topic", "/mocap/pose"), 50);
    true_pub_ = pnh.advertise<aurora_msgs::DroneState>("true_state", 100);
    status_pub_ = pnh.advertise<std_msgs::String>("status", 10, true);
    received_pub_ = pnh.advertise<std_msgs::String>("received", 10, true);
    countReceived(0, 0, 0);
    step_timer_ = nh.createTimer(ros::Duration(params_.Ts), &FakeDriver::onStep, this);
    mocap_timer_ = nh.createTimer(ros::Duration(1.0 / pnh.param("mocap_rate", 120.0)), &FakeDriver::onMocap, this);
    status(Profile::kFlies ? "landed" : "driving");
  }

 private:
  enum class Phase { kLanded, kTakingOff, kFlying, kLanding };

  void status(const std::string& s) {
    std_msgs::String m;
    m.data = s;
    status_pub_.publish(m);
  }
  void onCmd(const ros::MessageEvent<geometry_msgs::Twist const>& event) {
    double U[Vehicle::kInputs];
    Vehicle::fromDriver(twistCommandFromMsg(*event.getConstMessage()), U);
    if (!allFinite(U, Vehicle::kInputs)) return;
    Pending p;
    for (int i = 0; i < Vehicle::kInputs; ++i) p.U[i] = Vehicle::limitInput(params_, i, U[i]);
    std::uniform_real_distribution<double> late(0.0, jitter_);
    p.due = event.getReceiptTime() + ros::Duration(latency_ + (jitter_ > 0.0 ? late(rng_) : 0.0));
    pending_.push_back(p);
  }
  // The commands in force over [from, to], averaged over it: each takes
  // effect at its due time, in the order they arrived (a driver's queue:
  // never out of order), the last one stays; `newest` the due time of the
  // last one in force by `to`. (A real robot answers a command when it takes
  // effect, not at the model's next step: the average is one Euler step's
  // exact share of each.)
  void averageOver(ros::Time from, const ros::Time& to, double U[], ros::Time& newest) const {
    const double span = (to - from).toSec();
    const double* held = cmd_;
    newest = cmd_time_;
    std::fill(U, U + Vehicle::kInputs, 0.0);
    for (const Pending& p : pending_) {
      if (p.due > to) break;
      const ros::Time at = std::max(p.due, from);
      for (int i = 0; i < Vehicle::kInputs; ++i) U[i] += held[i] * (at - from).toSec();
      held = p.U, from = at, newest = p.due;
    }
    for (int i = 0; i < Vehicle::kInputs; ++i) U[i] = (U[i] + held[i] * (to - from).toSec()) / span;
  }
  // The commands due by t become the one in force.
  void takeDueCommands(const ros::Time& t) {
    while (!pending_.empty() && pending_.front().due <= t) {
      std::copy(pending_.front().U, pending_.front().U + Vehicle::kInputs, cmd_);
      cmd_time_ = pending_.front().due;
      pending_.pop_front();
    }
  }
  void countReceived(int takeoff, int land, int reset) {
    received_[0] += takeoff, received_[1] += land, received_[2] += reset;
    std_msgs::String m;
    m.data = "takeoff=" + std::to_string(received_[0]) + " land=" + std::to_string(received_[1]) +
             " reset=" + std::to_string(received_[2]);
    received_pub_.publish(m);
  }
  // As both drivers: a take-off while flying and a land while landing change nothing.
  void onTakeoff(const std_msgs::Empty::ConstPtr&) {
    countReceived(1, 0, 0);
    if (ignore_takeoffs_ > 0) return (void)--ignore_takeoffs_;
    if (phase_ == Phase::kLanded) phase_ = Phase::kTakingOff, status("taking off");
  }
  void onLand(const std_msgs::Empty::ConstPtr&) {
    countReceived(0, 1, 0);
    if (ignore_lands_ > 0) return (void)--ignore_lands_;
    if (phase_ != Phase::kLanded) phase_ = Phase::kLanding, status("landing");
  }
  void onReset(const std_msgs::Empty::ConstPtr&) {
    countReceived(0, 0, 1);
    phase_ = Phase::kLanded;
    touchDown();
    status("landed (reset)");
  }
  void onPause(const std_msgs::Float64::ConstPtr& msg) {
    paused_until_ = ros::Time::now() + ros::Duration(msg->data);
  }
  void touchDown() {
    const double at[3] = {model_.X[kX], model_.X[kY], 0.0}, yaw = model_.X[kYaw];
    Profile::place(params_, model_, at);
    model_.X[kYaw] = yaw;
  }

  // The model steps on its own clock (time passes at the real rate whatever
  // the command rate).
  void onStep(const ros::TimerEvent&) { advanceTo(ros::Time::now()); }

  // Every step whose nominal time has come, each at that time.
  void advanceTo(const ros::Time& now) {
    if (next_step_time_.isZero()) next_step_time_ = last_step_time_ = now;
    while (next_step_time_ <= now) {
      stepAt(next_step_time_);
      next_step_time_ += ros::Duration(params_.Ts);
    }
  }

  // What the robot flies over [from, to] in its phase: the drivers'
  // automatic climb or descent, the commands in force, or a hover when they
  // stop (bebop: 0.2 s).
  void flownOver(const ros::Time& from, const ros::Time& to, double U[]) const {
    std::fill(U, U + Vehicle::kInputs, 0.0);
    if (phase_ == Phase::kTakingOff) U[Profile::kClimbInput] = 0.5;
    if (phase_ == Phase::kLanding) U[Profile::kClimbInput] = -0.5;
    if (phase_ != Phase::kFlying) return;
    ros::Time newest;
    averageOver(from, to, U, newest);
    if ((to - newest).toSec() > 0.2) std::fill(U, U + Vehicle::kInputs, 0.0);
  }

  // One model step of `model` with U, on the ground at most.
  void fly(typename Vehicle::template State<double>& model, const double U[]) const {
    Vehicle::step(params_, model, U);
    if (model.X[kZ] < 0.0) {  // the ground
      model.X[kZ] = 0.0;
      if (model.X[kVz] < 0.0) model.X[kVz] = 0.0;
    }
  }

  // The step [t - Ts, t].
  void stepAt(const ros::Time& t) {
    double U[Vehicle::kInputs];
    flownOver(t - ros::Duration(params_.Ts), t, U);
    takeDueCommands(t);
    if (phase_ == Phase::kTakingOff && model_.X[kZ] >= 0.75) phase_ = Phase::kFlying, status("flying");
    if (phase_ != Phase::kLanded) {
      fly(model_, U);
      if (phase_ == Phase::kLanding && model_.X[kZ] <= 0.05) {
        phase_ = Phase::kLanded;
        touchDown();
        status("landed");
      }
    }
    last_step_time_ = t;
    aurora_msgs::DroneState s;
    s.header.stamp = t;
    s.header.frame_id = "world";
    s.step = step_++;
    stateToMsg(model_.X, s);
    true_pub_.publish(s);
  }

  // The pose at `now`, between steps: from the last step's toward the
  // next one's, flown with the commands in force so far (a real robot moves
  // between the model's steps, so the mocap stream is continuous, not a
  // staircase; a step of a fraction of Ts is no model's: the AR.Drone's
  // inner loops step at Ts).
  void poseNow(const ros::Time& now, double X[]) const {
    std::copy(model_.X, model_.X + kStateSize, X);
    const double dt = (now - last_step_time_).toSec();
    if (phase_ == Phase::kLanded || dt <= 0.0) return;
    auto next = model_;
    double U[Vehicle::kInputs];
    flownOver(last_step_time_, now, U);
    fly(next, U);
    const double share = std::min(dt / params_.Ts, 1.0);
    for (int i = 0; i < 6; ++i) {
      const double change = next.X[i] - X[i];
      X[i] += share * (i >= kRoll ? std::remainder(change, 2.0 * kPi) : change);
    }
  }

  void onMocap(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    advanceTo(now);  // the pose of now, whichever timer ran late
    if (now < paused_until_) return;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> np(0.0, noise_pos_), na(0.0, noise_ang_);
    if (u(rng_) < dropout_) return;
    double X[kStateSize];
    poseNow(now, X);
    double body[3];  // where the markers are: a Pioneer's centre, behind its control point
    Profile::bodyPosition(params_, X, body);
    tf2::Quaternion q;
    q.setRPY(X[kRoll] + na(rng_), X[kPitch] + na(rng_), X[kYaw] + na(rng_));
    const tf2::Transform world(q, tf2::Vector3(body[0] + np(rng_), body[1] + np(rng_), body[2] + np(rng_)));
    const tf2::Transform in_mocap = world_to_mocap_ * world;
    geometry_msgs::PoseStamped p;
    p.header.stamp = now;
    p.header.frame_id = frame_;
    p.pose.position.x = in_mocap.getOrigin().x();
    p.pose.position.y = in_mocap.getOrigin().y();
    p.pose.position.z = in_mocap.getOrigin().z();
    p.pose.orientation.x = in_mocap.getRotation().x();
    p.pose.orientation.y = in_mocap.getRotation().y();
    p.pose.orientation.z = in_mocap.getRotation().z();
    p.pose.orientation.w = in_mocap.getRotation().w();
    if (held_) {  // the held pose goes out after a newer one: out-of-order stamps
      pose_pub_.publish(p);
      pose_pub_.publish(held_pose_);
      held_ = false;
    } else if (u(rng_) < reorder_) {
      held_pose_ = p;
      held_ = true;
    } else {
      pose_pub_.publish(p);
    }
  }

  typename Vehicle::template Params<double> params_;
  typename Vehicle::template State<double> model_;
  Phase phase_ = Phase::kLanded;
  double cmd_[Vehicle::kInputs] = {};
  struct Pending {
    double U[Vehicle::kInputs];
    ros::Time due;
  };
  std::deque<Pending> pending_;  // commands received, in arrival order, not yet in effect
  double latency_ = 0.0, jitter_ = 0.0;
  ros::Time cmd_time_, paused_until_, last_step_time_, next_step_time_;
  unsigned long step_ = 0;
  std::mt19937 rng_;
  double noise_pos_, noise_ang_, dropout_, reorder_;
  std::string frame_;
  tf2::Transform world_to_mocap_;
  bool held_ = false;
  geometry_msgs::PoseStamped held_pose_;
  std::vector<ros::Subscriber> subs_;
  ros::Publisher pose_pub_, true_pub_, status_pub_, received_pub_;
  int ignore_takeoffs_ = 0, ignore_lands_ = 0;
  int received_[3] = {0, 0, 0};
  ros::WallTimer late_timer_;
  ros::Timer step_timer_, mocap_timer_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "fake_driver");
  ros::NodeHandle nh, pnh("~");
  try {
    std::string type;
    pnh.getParam("vehicle/type", type);
    withVehicleOfType(type, [&](auto vehicle) {
      FakeDriver<decltype(vehicle)> fake(nh, pnh);
      ros::spin();
    });
  } catch (const ConfigError& e) {
    ROS_FATAL("fake_driver: %s", e.what());
    return 2;
  }
  return 0;
}
