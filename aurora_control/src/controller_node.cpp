#include "controller_node.h"

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Path.h>
#include <std_msgs/Empty.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "aurora_sim/command_mapping.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "aurora_sim/vehicle/vehicle_type.h"  // every vehicle with its SimProfile
#include "aurora_control/loop/law_settings_yaml.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/loop/live_settings.h"
#include "aurora_control/predictor/predictor_yaml.h"
#include "aurora_control/task/tracking.h"
#include "aurora_control/ros/control_msg.h"
#include "controller_params.h"
#include "param_tree.h"
#include "task_markers.h"

namespace aurora_control {

template <class Settings>
ControllerNodeOf<Settings>::ControllerNodeOf(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh), pnh_(private_nh) {
  refuseDuplicatedKeysInLoadedFiles(pnh_);
  core_.reset(new Core());
  Settings& set = core_->settings;
  // The vehicle, with the same range rules as the sim's: Ts for every law,
  // the whole model for a law that inverts it; then the law's gains.
  loadLaw(nh_, pnh_, set);
  Ts_ = set.Ts;
  const long given_delay = readDelaySamples();
  loadLink(pnh_, given_delay, set);
  set.clamp_commands = aurora_common::boolParam(pnh_, "clamp_commands", true);
  const std::string mode = readLoopMode();
  task_ = loadTask(pnh_, TaskHeights::of<Vehicle>());
  task_iterations_ = taskStepCount(task_.duration(), Ts_);  // steps 0..N (docs/controllers.md)
  refuseDelayBeyondTheTask(set.delay);
  refuseUnknownTopLevelKeys();
  core_->configureLink();
  loadPredictor();
  safety_ = loadSafetyConfig(pnh_);
  safety_.ground_robot = Vehicle::kOnGround;  // no take-off; it stops where a drone lands
  refuseDroneOnlySafetyKeys();
  const SafetyConfig& safety = safety_;
  supervisor_.configure(safety);
  JoystickConfig joystick;
  joystick_enabled_ = loadJoystickConfig(pnh_, joystick);
  joystick_ = JoystickMapper(joystick);
  resume_ = ResumeSlew(joystick.resume_max_step, joystick.resume_min_cycles);

  connectTopics(safety);
  advertiseLiveSettings();

  if (!lockstep_) {
    timer_ = nh_.createTimer(ros::Duration(Ts_), &ControllerNodeOf::onTimer, this);
    rate_timer_ = nh_.createWallTimer(ros::WallDuration(1.0), &ControllerNodeOf::onRateCheck, this);
  }
  publishTaskMarkers();
  ROS_INFO("controller: %s (%s), delay %s (%.4f s), link %s, %s commands, %s mode, %s task over "
           "%.1f s%s%s", lawNameOf(set), gainsText(set).c_str(), delayOriginText(given_delay, set.link).c_str(),
           set.delay * Ts_, linkName().c_str(),
           set.clamp_commands ? "clamped" : "unclamped", mode.c_str(), taskTypeName(task_.type),
           task_.duration(), safety.flight_sequence ? ", flight sequence (take-off, task, landing)" : "",
           joystick_enabled_ ? ", joystick override" : "");
}

// mode (realtime or lockstep), trigger and the lockstep subscriber counts.
template <class Settings>
std::string ControllerNodeOf<Settings>::readLoopMode() {
  const std::string mode = wordParam(pnh_, kParameterTable[kRowMode]);
  lockstep_ = mode == "lockstep";
  // Realtime: by default the law runs as soon as a state arrives (lowest
  // latency, AuRoRA's read-then-send loop); the 30 Hz timer is then the
  // stale-state watchdog. trigger=timer runs the law on the timer only, on
  // the newest state received.
  timer_triggered_ = !lockstep_ && wordParam(pnh_, kParameterTable[kRowTrigger]) == "timer";
  // Lockstep: the first state is answered only once the subscribers that
  // must see every step are connected (a recorder, test nodes); until then
  // the sim re-sends it. Without this a link that connects late misses the
  // first steps, depending on machine load.
  lockstep_cmd_subscribers_ = static_cast<int>(wholeParam(pnh_, kParameterTable[kRowLockstepCmdSubscribers]));
  lockstep_control_subscribers_ = static_cast<int>(wholeParam(pnh_, kParameterTable[kRowLockstepControlSubscribers]));
  record_subscribers_ = static_cast<int>(wholeParam(pnh_, kParameterTable[kRowRecordSubscribers]));
  return mode;
}

// Publishers, the driver channels and subscribers.
template <class Settings>
void ControllerNodeOf<Settings>::connectTopics(const SafetyConfig& safety) {
  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1000);
  control_pub_ = nh_.advertise<aurora_msgs::Control>("control", 1000);
  if (lockstep_) step_cmd_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("cmd_vel_stamped", 1000);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("waypoints", 1, true);
  desired_path_pub_ = nh_.advertise<nav_msgs::Path>("desired_path", 1, true);
  // The drivers' names (ardrone_autonomy: ardrone/takeoff ...; bebop_autonomy:
  // takeoff ...) are set by remapping in the launch file.
  takeoff_land_ = TakeoffLand(nh_, "takeoff", "land", "", safety);
  reset_ = DriverCommandChannel(nh_, "reset", "reset", DeliveryPolicy());  // once: a toggle
  if (joystick_enabled_) {
    joy_sub_ = nh_.subscribe("joy", 10, &ControllerNodeOf::onJoy, this,
                             ros::TransportHints().tcpNoDelay());
  }
  state_sub_ = nh_.subscribe("state", 100, &ControllerNodeOf::onState, this,
                             ros::TransportHints().tcpNoDelay());
}

template <class Settings>
void ControllerNodeOf<Settings>::refuseDroneOnlySafetyKeys() const {
  if (!Vehicle::kOnGround) {
    if (safety_.max_speed > 0.0 || safety_.max_turn_rate > 0.0) {
      throw ConfigError("parameter '" + fullKey(pnh_, safety_.max_speed > 0.0 ? "safety/max_speed" : "safety/max_turn_rate") +
                        "' is a ground robot's speed limit, but this node flies a " + Vehicle::name() +
                        ": leave it out (0) for a drone");
    }
    return;
  }
  for (const char* key : {"takeoff_altitude", "takeoff_timeout", "takeoff_rise", "descent_speed", "land_resend_timeout"}) {
    if (pnh_.hasParam(std::string("safety/") + key)) {
      throw ConfigError("parameter '" + fullKey(pnh_, std::string("safety/") + key) + "' sets a take-off or landing, but a " +
                        Vehicle::name() + " is a ground robot: it drives from the first state and stops instead of "
                        "landing (use config/safety/real_ground.yaml)");
    }
  }
}

template <class Settings>
void ControllerNodeOf<Settings>::refuseDelayBeyondTheTask(long delay) const {
  const std::string key = pnh_.hasParam("delay/seconds") ? "delay/seconds" : "delay/samples";
  if (!delayShorterThanRun(delay, task_iterations_)) {
    throw ConfigError("parameter '" + fullKey(pnh_, key) + "' = " + delayRunText(delay, task_iterations_, Ts_));
  }
  const std::string late = latestPacketRefusal(core_->settings.link, delay, task_iterations_, Ts_);
  if (!late.empty()) throw ConfigError("parameter '" + fullKey(pnh_, "link") + "': " + late);
}

// The link for the start-up line: its name (~link_name, the launch's
// link:=) and, unless ideal, every value that defines it.
template <class Settings>
std::string ControllerNodeOf<Settings>::linkName() const {
  const LinkParams& l = core_->settings.link;
  const std::string name = aurora_common::paramOr<std::string>(pnh_, "link_name", pnh_.hasParam("link") ? "~link" : "ideal");
  return l.ideal() && l.uplink.delay == 0 ? name : name + " (" + linkText(l) + ")";
}

// The controller file's predictor block as loaded under ~predictor; a
// relative model is taken from ~controller_file's folder (the launch files
// give it), as offline (predictor_yaml.h). The sim and the drivers clamp
// what they receive (a Pioneer's limit passes it on).
template <class Settings>
void ControllerNodeOf<Settings>::loadPredictor() {
  // Live (dynparam predictor) without a block: the node's own vehicle file as the model.
  predictor_base_.model = core_->settings.vehicle;
  predictor_base_.path = CommandPath{0, 0, true};
  if (!pnh_.hasParam("predictor")) return;
  const std::string controller_file = aurora_common::paramOr<std::string>(pnh_, "controller_file", "");
  const PredictorFile f = readPredictorBlock(
      YamlReader("parameter ", "/"), paramAsYaml(pnh_, "predictor"), aurora_common::fullKey(pnh_, "predictor"),
      controller_file.empty() ? "" : aurora_common::folderOf(controller_file),
      controller_file.empty() ? aurora_common::fullKey(pnh_, "predictor") : controller_file);
  if (f.form == PredictorForm::kOff) return;
  const LinkParams& link = core_->settings.link;
  const long delay = core_->settings.delay;
  const long history = link.ideal() ? delay : link.historyNeeded(delay);
  core_->settings.withLawType([&](auto law) {
    predictor_base_ = predictorRun<decltype(law)>(f, Ts_, link.downlink.delay, history, true);
  });
  core_->settings.predictor = f.form;
  applyPredictor();
  ROS_INFO("controller: the %s predictor on (docs/predictor.md), model '%s', horizon %ld samples",
           predictorFormName(f.form), f.model.c_str(), core_->predictor().path.horizon);
}

template <class Settings>
void ControllerNodeOf<Settings>::applyPredictor() {
  PredictorRun<Vehicle, double> p = predictor_base_;
  p.form = core_->settings.predictor;
  p.path.delay = core_->settings.link.downlink.delay;
  core_->configurePredictor(p);
}

template <class Settings>
void ControllerNodeOf<Settings>::refuseUnknownTopLevelKeys() {
  // The node's own keys and those the reconfigure server writes beside them.
  std::vector<std::string> accepted{"controller", "task", "safety", "joystick", "mode", "trigger",
                                    "delay", "clamp_commands", "lockstep_subscribers", "record_subscribers",
                                    "delay_samples", "link", "link_name", "yaml_files", "predictor",
                                    "controller_file"};
  for (const auto& gain : liveGainsShown(core_->settings)) accepted.push_back(gain.first);
  refuseUnknownParams(pnh_, "", accepted, "a typo, or a key of another file");
  refuseUnknownParams(pnh_, "delay", {"samples", "seconds"}, "");
}

template <class Settings>
long ControllerNodeOf<Settings>::readDelaySamples() {
  static_assert(Core::kMaxDelay == kHistoryCapacity - 1, "delay range follows the history");
  const bool has_seconds = pnh_.hasParam("delay/seconds");
  if (pnh_.hasParam("delay/samples") && has_seconds) {
    throw ConfigError("both '" + fullKey(pnh_, "delay/samples") + "' and '" +
                      fullKey(pnh_, "delay/seconds") + "' are set: give only one");
  }
  const std::string key = has_seconds ? "delay/seconds" : "delay/samples";
  if (!pnh_.hasParam(key)) return kDelayNotGiven;  // the link's uplink delay, or 0
  double value = 0.0;  // an int parameter reads as a double too; 2.5 samples is refused below
  const bool number = pnh_.getParam(key, value);
  long samples = 0;
  const std::string refusal = number ? delayRefusal(value, has_seconds, Ts_, samples)
                                     : std::string("is refused: accepted ") + (has_seconds ? "seconds" : delayRangeText());
  if (!refusal.empty()) {
    throw ConfigError("parameter '" + fullKey(pnh_, key) + "' = " +
                      (number ? aurora_common::numberText(value) : std::string("(not a number)")) + " " + refusal);
  }
  if (has_seconds) {
    ROS_INFO("controller: delay %.6f s rounded to %ld whole samples of Ts = %.6f s (%.6f s)", value, samples, Ts_,
             samples * Ts_);
  }
  return samples;
}

template <class Settings>
dynamic_reconfigure::Config ControllerNodeOf<Settings>::liveConfig() const {
  const Settings& set = core_->settings;
  ControllerConfig config = ControllerConfig::__getDefault__();
  config.delay_samples = static_cast<double>(set.delay);
  config.uplink_jitter = static_cast<double>(set.link.uplink.jitter_max);
  config.uplink_loss = set.link.uplink.loss;
  config.uplink_burst = set.link.uplink.burst;
  config.downlink_delay = static_cast<double>(set.link.downlink.delay);
  config.downlink_jitter = static_cast<double>(set.link.downlink.jitter_max);
  config.downlink_loss = set.link.downlink.loss;
  config.downlink_burst = set.link.downlink.burst;
  config.predictor = predictorFormName(set.predictor);
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  // The live laws' gains, by their rows' names (the server's fields of the same names).
  for (const auto& gain : liveGainsShown(set)) {
    for (auto& d : message.doubles) {
      if (d.name == gain.first) d.value = gain.second;
    }
  }
  return message;
}

template <class Settings>
void ControllerNodeOf<Settings>::advertiseLiveSettings() {
  descriptions_pub_ = pnh_.advertise<dynamic_reconfigure::ConfigDescription>("parameter_descriptions", 1, true);
  descriptions_pub_.publish(ControllerConfig::__getDescriptionMessage__());
  updates_pub_ = pnh_.advertise<dynamic_reconfigure::Config>("parameter_updates", 1, true);
  updates_pub_.publish(liveConfig());
  set_parameters_ = pnh_.advertiseService("set_parameters", &ControllerNodeOf::onSetParameters, this);
}

template <class Settings>
bool ControllerNodeOf<Settings>::onSetParameters(dynamic_reconfigure::Reconfigure::Request& req,
                                     dynamic_reconfigure::Reconfigure::Response& rsp) {
  boost::recursive_mutex::scoped_lock lock(config_mutex_);
  std::vector<LiveChange> changes;
  for (const auto& d : req.config.doubles) changes.push_back({d.name, d.value});
  for (const auto& i : req.config.ints) changes.push_back({i.name, static_cast<double>(i.value)});
  for (const auto& b : req.config.bools) changes.push_back({b.name, std::nan("")});  // no boolean setting
  for (const auto& t : req.config.strs) changes.push_back({t.name, std::nan(""), t.value});
  Settings& set = core_->settings;
  Settings next = set;
  for (const LiveChange& c : changes) {
    const std::string problem = checkLiveChange(next, c, task_iterations_);
    if (!problem.empty()) {
      // The caller's request fails (dynparam and the Python client raise);
      // nothing of it is applied. Logged too, for rqt users.
      ROS_ERROR("controller: live change refused, settings unchanged (%s): %s", gainsText(set).c_str(),
                problem.c_str());
      throw std::invalid_argument(problem);
    }
    applyLiveChange(next, c);
  }
  if (gainsText(set) != gainsText(next) || next.delay != set.delay) {
    ROS_INFO("controller: reconfigured %s, delay %ld samples", gainsText(next).c_str(), next.delay);
  }
  if (next.delay != set.delay) announceDelayChange(next.delay);
  const bool link_changed = next.link != set.link;
  const bool predictor_changed = next.predictor != set.predictor || (link_changed && next.predictor != PredictorForm::kOff);
  set = next;
  if (predictor_changed) {  // it starts afresh from the next state received
    applyPredictor();
    ROS_INFO("controller: state predictor %s live (docs/predictor.md)", predictorFormName(set.predictor));
  }
  if (link_changed) {  // the channels start afresh with the new values
    core_->configureLink();
    LinkParams shown = set.link;
    shown.uplink.delay = set.delay;  // the node's delay is the uplink's
    ROS_INFO("controller: link changed live (docs/links.md): %s", linkText(shown).c_str());
  }
  rsp.config = liveConfig();
  updates_pub_.publish(rsp.config);
  return true;
}

template <class Settings>
void ControllerNodeOf<Settings>::announceDelayChange(long delay) {
  // The delay rule (docs/delay-and-study.md) sends the current state while
  // fewer than delay + 1 states are kept: a live raise beyond the history
  // means no delay at all for a while. Say so now, and again when it holds.
  const long pending = core_->empty() ? 0 : core_->delayPending(delay);
  // A raise still waiting stays announced until a delay is in force again.
  delay_pending_announced_ = delay_pending_announced_ || pending > 0;
  if (pending > 0) {
    ROS_WARN("controller: delay raised live to %ld samples (%.3f s) but only %ld states are kept: "
             "the delay rule sends the current state (NO delay, Control.delay_in_force 0) for the next "
             "%ld states (%.1f s), until the history holds %ld",
             delay, delay * Ts_, delay + 1 - pending, pending, pending * Ts_, delay + 1);
  }
}

template <class Settings>
void ControllerNodeOf<Settings>::onState(const aurora_msgs::DroneState::ConstPtr& msg) {
  if (msg->stale) {
    // The estimator says its source stopped: not a fresh state; the
    // watchdogs see the age grow.
    if (!warned_stale_input_) ROS_WARN("controller: the state source reports stale states");
    warned_stale_input_ = true;
    return;
  }
  warned_stale_input_ = false;
  if (core_->empty() && !recorderReady()) return;  // the first state the recorder will see
  if (lockstep_ && core_->empty() && !lockstepListenersReady()) return;  // the sim re-sends it
  const StateSample sample = sampleFromMsg(*msg);
  const bool went_back = !core_->empty() && sample.step < core_->newest().step;
  if (!core_->push(sample)) {
    // The lockstep sim re-sends a state it got no answer to: answer again
    // with the same command; the history already holds this sample.
    answering_ = msg->header.stamp;
    if (lockstep_) sendCommand(last_sent_);
    return;
  }
  if (went_back) {
    mission_reported_ = false;
    ROS_INFO("controller: state step went back to %ld (source reset): history cleared",
             sample.step);
  }
  if (!msg->header.frame_id.empty()) state_frame_ = msg->header.frame_id;
  last_state_time_ = ros::Time::now();
  if (lockstep_) {
    answering_ = msg->header.stamp;
    cycle(msg->header.stamp, 0.0);
  } else if (!timer_triggered_) {
    cycle(ros::Time::now(), 0.0);
  }
}

// A recorded flight (record:=true) starts once the recorder listens to
// control and cmd_vel: the law's first cycle, its delay history and its
// memory are then in the bag, and replay reproduces every cycle (a recorder
// that connected a few cycles late made replay of realtime bags differ).
template <class Settings>
bool ControllerNodeOf<Settings>::recorderReady() const {
  const int control = static_cast<int>(control_pub_.getNumSubscribers());
  const int cmd = static_cast<int>(cmd_pub_.getNumSubscribers());
  if (control >= record_subscribers_ && cmd >= record_subscribers_) return true;
  ROS_INFO_THROTTLE(5.0, "controller: waits for %d recorder(s) of %s and %s (%d and %d now) before its first state",
                    record_subscribers_, control_pub_.getTopic().c_str(), cmd_pub_.getTopic().c_str(), control, cmd);
  return false;
}

template <class Settings>
bool ControllerNodeOf<Settings>::lockstepListenersReady() const {
  const int cmd = static_cast<int>(cmd_pub_.getNumSubscribers());
  const int control = static_cast<int>(control_pub_.getNumSubscribers());
  // The sim steps on cmd_vel_stamped: it listens there when cmd_vel has listeners to wait for.
  const int stepping = static_cast<int>(step_cmd_pub_.getNumSubscribers());
  if (cmd >= lockstep_cmd_subscribers_ && control >= lockstep_control_subscribers_ &&
      stepping >= std::min(1, lockstep_cmd_subscribers_)) {
    return true;
  }
  ROS_INFO_THROTTLE(5.0, "controller: lockstep waits for %d subscriber(s) of %s (%d now) and %d of "
                    "%s (%d now) before the first step", lockstep_cmd_subscribers_,
                    cmd_pub_.getTopic().c_str(), cmd, lockstep_control_subscribers_,
                    control_pub_.getTopic().c_str(), control);
  return false;
}

template <class Settings>
double ControllerNodeOf<Settings>::stateAge(const ros::Time& now) const {
  if (core_->empty()) return std::numeric_limits<double>::infinity();
  return lockstep_ ? 0.0 : stall_.stateAge(now, last_state_time_);
}

template <class Settings>
void ControllerNodeOf<Settings>::onTimer(const ros::TimerEvent& event) {
  // The watchdogs run here when no state arrives; with trigger=timer the law
  // too. (With trigger=state a fresh state already ran the cycle: running it
  // here as well would double the command rate.)
  stall_.timerRan(event, Ts_);  // state_age.h: the watchdogs leave our own stalls out
  const double age = stateAge(event.current_real);
  if (timer_triggered_ || age > Ts_ * 1.5) cycle(event.current_real, age);
}

template <class Settings>
void ControllerNodeOf<Settings>::onRateCheck(const ros::WallTimerEvent&) {
  const double rate = static_cast<double>(sent_in_window_);  // per 1 s window
  sent_in_window_ = 0;
  const bool flying = supervisor_.phase() == FlightPhase::kFly;
  const bool low = flying && rate < 0.5 / Ts_;
  if (low && !low_rate_) {
    ROS_WARN("controller: command rate %.1f Hz is below half the nominal %.1f Hz", rate, 1.0 / Ts_);
  } else if (!low && low_rate_) {
    ROS_INFO("controller: command rate back to %.1f Hz", rate);
  }
  low_rate_ = low;
}

template <class Settings>
void ControllerNodeOf<Settings>::onJoy(const sensor_msgs::Joy::ConstPtr& msg) {
  const bool was_held = joy_.deadman;
  joy_ = joystick_.map(msg->axes, msg->buttons);
  const double now = ros::Time::now().toSec();
  const double z = core_->empty() ? 0.0 : core_->newest().X[aurora_sim::kZ];
  if (joy_.takeoff) {
    ROS_INFO("controller: joystick take-off");
    takeoff_land_.takeoff(now, z);
  }
  if (joy_.land) {
    ROS_WARN("controller: joystick land");
    takeoff_land_.land(now);
  }
  if (joy_.reset) {
    ROS_WARN("controller: joystick emergency reset");
    reset_.request(now);
  }
  if (joy_.takeoff || joy_.land || joy_.reset) serviceDriverCommands(now, nullptr);
  if (joy_.deadman) {
    if (!was_held) ROS_WARN("controller: joystick override (deadman held)");
    // The joystick wins at once, not at the next cycle.
    double U[kMaxInputs] = {0, 0, 0, 0};
    Vehicle::fromDriver(joy_.sticks, U);
    sendCommand(U);
  } else if (was_held) {
    ROS_INFO("controller: joystick released: back to the controller");
    resume_.start(last_sent_);
  }
}

template <class Settings>
void ControllerNodeOf<Settings>::serviceDriverCommands(double now, const double* fresh_X) {
  takeoff_land_.service(now, fresh_X);
  reset_.service(now, false);
}

template <class Settings>
void ControllerNodeOf<Settings>::sendCommand(const double U[kMaxInputs]) {
  const geometry_msgs::Twist twist = aurora_sim::twistMsgFromModelCommand<Vehicle>(U);
  cmd_pub_.publish(twist);
  if (lockstep_) {
    geometry_msgs::TwistStamped answer;
    answer.header.stamp = answering_;
    answer.twist = twist;
    step_cmd_pub_.publish(answer);
  }
  for (int i = 0; i < kMaxInputs; ++i) last_sent_[i] = U[i];
  ++sent_in_window_;
}

template <class Settings>
void ControllerNodeOf<Settings>::cycle(const ros::Time& now, double age) {
  boost::recursive_mutex::scoped_lock lock(config_mutex_);
  static const double kNoState[aurora_sim::kMaxStates] = {};
  const bool have_state = !core_->empty();
  const StateSample* newest = have_state ? &core_->newest() : nullptr;
  const long task_step = have_state ? newest->step - supervisor_.flyStartStep() : 0;
  const double task_time = taskTime(task_step, Ts_);  // step Ts
  const FlightDecision decision = supervisor_.update(
      now.toSec(), age, have_state ? newest->X : kNoState, have_state ? newest->step : 0,
      task_time, task_.duration());
  logEvent(decision.event);
  takeoff_land_.apply(decision, now.toSec(), have_state ? newest->X[aurora_sim::kZ] : 0.0);
  serviceDriverCommands(now.toSec(), have_state && age <= safety_.hover_after ? newest->X : nullptr);
  if (!have_state) {
    const double hover[kMaxInputs] = {0, 0, 0, 0};
    if (!lockstep_) sendCommand(hover);  // drivers expect a steady command stream
    return;
  }

  if (decision.event == "fly") {  // the task starts now
    core_->resetMetrics();
    mission_reported_ = false;
  }
  const Reference<double> ref =
      decision.hold ? restingAt(decision.hold_point) : task_.at(task_time);
  ControlOutput out = decision.run_law ? core_->compute(ref) : core_->hover();
  std::string mode = decision.mode;
  if (joy_.deadman) {
    Vehicle::fromDriver(joy_.sticks, out.U);
    mode = "joystick";
  } else if (resume_.active()) {
    resume_.apply(out.U);
    mode += " (resuming from joystick)";
  }
  if (low_rate_) mode += " [low command rate]";
  aurora_sim::SimProfile<Vehicle>::limitSpeed(out.U, safety_.max_speed, safety_.max_turn_rate);

  aurora_msgs::Control control;
  control.header.stamp = now;
  control.header.frame_id = "world";
  control.step = newest->step;
  control.waypoint_index = task_.activeIndex(task_time);
  control.task_time = task_time;
  control.task_duration = task_.duration();
  referenceToMsg(ref, control);
  control.law_ran = decision.run_law;
  control.overridden = joy_.deadman || resume_.active();
  control.mode = mode;
  control.takeoff_attempts = static_cast<uint32_t>(takeoff_land_.takeoffCommand().attempts());
  control.land_attempts = static_cast<uint32_t>(takeoff_land_.landCommand().attempts());
  fillLaw(control);
  fillOutput(out, control);
  sendCommand(out.U);
  control_pub_.publish(control);
  reportProgress(out, ref, decision, task_time);
}

template <class Settings>
void ControllerNodeOf<Settings>::logEvent(const std::string& event) const {
  if (event.empty()) return;
  const bool safety = event.rfind("hover", 0) == 0 || event.rfind("halt (", 0) == 0 || event.rfind("land (", 0) == 0 ||
                      event.rfind("stop (", 0) == 0;
  if (safety) {
    ROS_WARN("controller: %s", event.c_str());
  } else {
    ROS_INFO("controller: %s", event.c_str());
  }
}

template <class Settings>
void ControllerNodeOf<Settings>::fillOutput(const ControlOutput& out, aurora_msgs::Control& control) const {
  const Settings& set = core_->settings;
  control.delay_samples = set.delay;
  control.delay_in_force = static_cast<uint32_t>(out.delay_in_force);
  control.delay_pending = static_cast<uint32_t>(out.delay_pending);
  control.delay_seconds = set.delay * Ts_;
  control.sample_time = Ts_;
  control.clamped = set.clamp_commands;
  control.state_used.header.stamp.fromNSec(static_cast<uint64_t>(out.used->stamp_ns));
  control.state_used.header.frame_id = state_frame_;
  control.state_used.step = out.used->step;
  aurora_sim::stateToMsg(out.used->X, Vehicle::kStates, control.state_used);
  control.predictor = predictorFormName(core_->predictor().form);
  if (out.predicted) {
    control.prediction_step = static_cast<uint64_t>(out.prediction_step);
    control.prediction_horizon = static_cast<uint32_t>(out.prediction_horizon);
    control.predicted_state.assign(out.X_predicted, out.X_predicted + Vehicle::kStates);
  }
  control.position_error.x = out.position_error[0];
  control.position_error.y = out.position_error[1];
  control.position_error.z = out.position_error[2];
  for (int i = 0; i < kMaxInputs; ++i) {
    control.command[i] = out.U[i];
    control.command_sent[i] = out.U_sent[i];
    control.command_unclamped[i] = out.U_unclamped[i];
  }
  control.state_arrived = out.state_arrived;
  control.command_age = static_cast<int32_t>(out.command_age);
  control.drone_hovers = out.drone_hovers;
  control.uplink_losses = static_cast<uint32_t>(out.uplink_losses);
  control.downlink_losses = static_cast<uint32_t>(out.downlink_losses);
  control.iae = out.iae;
  control.itae = out.itae;
  control.iasc = out.iasc;
}

template <class Settings>
void ControllerNodeOf<Settings>::reportProgress(const ControlOutput& out, const Reference<double>& ref,
                                    const FlightDecision& decision, double task_time) {
  if (delay_pending_announced_ && out.delay_pending == 0 && decision.run_law) {
    ROS_INFO("controller: the delay of %ld samples is in force again", out.delay_in_force);
    delay_pending_announced_ = false;
  }
  // Once, when the task's time is up (the last step lands on its end).
  const bool on_task = (decision.run_law && !decision.hold) || decision.event == "land (task complete)";
  if (mission_reported_ || !on_task || task_time + 0.5 * Ts_ < task_.duration()) return;
  mission_reported_ = true;
  // The true final error: the newest state against this step's reference
  // (out.position_error is the delayed state's, what the law saw).
  ROS_INFO("controller: mission complete: %s task of %.1f s with a delay of %ld samples (%.3f s): "
           "IAE %.4f m s, ITAE %.4f m s^2, IASC %.4f s, final position error %.4f m",
           taskTypeName(task_.type), task_.duration(), core_->settings.delay,
           core_->settings.delay * Ts_, out.iae, out.itae, out.iasc,
           trackingError(ref, core_->newest().X));
}

template <class Settings>
void ControllerNodeOf<Settings>::fillLaw(aurora_msgs::Control& control) const {
  const Settings& set = core_->settings;
  control.controller = lawNameOf(set);
  control.vehicle = Vehicle::name();
  control.command_names.clear();
  for (int i = 0; i < Vehicle::kInputs; ++i) control.command_names.push_back(Vehicle::inputName(i));
  control.extra_state_names.clear();
  for (int i = aurora_sim::kStateSize; i < Vehicle::kStates; ++i) control.extra_state_names.push_back(Vehicle::stateName(i));
  control.gain_names.clear();
  control.gains.clear();
  control.kp = control.kd = 0.0;  // the thesis's PD gains, where the law has them
  for (const auto& gain : gainsInForce(set)) {
    control.gain_names.push_back(gain.first), control.gains.push_back(gain.second);
    if (gain.first == "kp") control.kp = gain.second;
    if (gain.first == "kd") control.kd = gain.second;
  }
}

template <class Settings>
void ControllerNodeOf<Settings>::publishTaskMarkers() {
  markers_pub_.publish(waypointMarkers(task_));
  desired_path_pub_.publish(desiredPath(task_));
}

std::shared_ptr<void> ControllerOfLaw::make(ros::NodeHandle nh, ros::NodeHandle private_nh) {
  // The node of the family of the law ~controller names (its vehicle's);
  // a missing mapping or an unknown name is refused here.
  const std::string name = lawNameIn(YamlReader("parameter ", "/"), paramAsYaml(private_nh, "controller"),
                                     fullKey(private_nh, "controller"));
  std::shared_ptr<void> node;
  withLawNamed(name, [&](auto law) {
    node = std::make_shared<ControllerNodeOf<LawSettings<typename decltype(law)::Data>>>(nh, private_nh);
  });
  return node;
}

}  // namespace aurora_control
