#include "formation_node.h"

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>

#include <algorithm>
#include <limits>

#include "aurora_common/refusal_text.h"
#include "aurora_common/ros/config_dir.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_control/params/parameter_table.h"
#include "formation_markers.h"
#include "param_tree.h"
#include "aurora_control/ros/control_msg.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"

namespace aurora_control {

namespace {

// The formation node's own row; its other parameters are the controller's
// rows (parameter_table.h). Both modes: a realtime flight's first tick is
// published once its watchers listen, as a lockstep one's (a test started
// late on a loaded machine saw the real formations' ticks from the middle).
constexpr ParameterSpec kFormationSubscribers{
    "formation_subscribers", ParamKind::kWhole, 0, 0, 100, "subscribers",
    "formation node, both modes: subscribers of formation (a recorder, a test) to wait for before the first state"};
constexpr char kRenamedFormationSubscribers[] = "lockstep_subscribers/formation";

}  // namespace

FormationNode::FormationNode(ros::NodeHandle nh, ros::NodeHandle private_nh) : nh_(nh), pnh_(private_nh) {
  refuseDuplicatedKeysInLoadedFiles(pnh_);
  loadCrew();
  const std::string mode = aurora_common::wordParam(pnh_, kParameterTable[kRowMode]);  // the controller's row
  lockstep_ = mode == "lockstep";
  configureSequence();
  cmd_subscribers_ = static_cast<int>(aurora_common::wholeParam(pnh_, kParameterTable[kRowLockstepCmdSubscribers]));
  if (pnh_.hasParam(kRenamedFormationSubscribers)) {
    throw aurora_common::ConfigError("'" + pnh_.resolveName(kRenamedFormationSubscribers) + "' is now '" +
                                     pnh_.resolveName(kFormationSubscribers.name) +
                                     "' (it holds in both modes): rename it in your launch file");
  }
  formation_subscribers_ = static_cast<int>(aurora_common::wholeParam(pnh_, kFormationSubscribers));
  record_subscribers_ = static_cast<int>(aurora_common::wholeParam(pnh_, kParameterTable[kRowRecordSubscribers]));
  connect();
  std::string delays;
  for (int d = 0; d < crew_->robots(); ++d) delays += (d ? ", " : "") + std::to_string(crew_->robot(d).delay);
  ROS_INFO("formation_controller: %s, %s formation (%s), robots %s, delays %s samples of %.4f s", mode.c_str(),
           crew_->shape().c_str(), crew_->lawName().c_str(), joinKeys(drones_).c_str(), delays.c_str(),
           crew_->sampleTime());
}

// The formation file (~formation_file; ~vehicle, the vehicle of robots
// whose file names none: the two-drone line's drones) and ~delay_1 .. ~delay_3 (-1: the file's); ~drones, when given,
// must be the crew's namespaces (the launch started those sims).
void FormationNode::loadCrew() {
  CrewRequest q;
  q.file = aurora_common::requireParam<std::string>(pnh_, "formation_file", "a formation file (config/formations/NAME.yaml)");
  // The file's relative paths are in ~config_dir, by default the tools' folder ($AURORA_CONFIG_DIR, else aurora_config).
  q.config_dir = aurora_common::paramOr<std::string>(pnh_, "config_dir", "");
  if (q.config_dir.empty()) q.config_dir = aurora_common::configDir();
  const FormationDocument file = loadFormationDocument(q.file, q.config_dir);
  withUnnamedVehicleOf(file.shape, [&](auto v) {  // a shape whose file names no vehicle flies ~vehicle's
    q.vehicle.set<decltype(v)>(aurora_sim::loadVehicleParams<decltype(v)>(pnh_, "vehicle"));
  });
  for (int d = 0; d < kMaxCrew; ++d) {
    const std::string key = "delay_" + std::to_string(d + 1);
    const double given = aurora_common::rangedParam(pnh_, key, -1, -1, double(kMaxDelaySamples), "samples (-1: the file's)");
    if (given != double(long(given))) {
      throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, key) + "' = " + aurora_common::numberText(given) +
                                    " is refused: accepted whole samples");
    }
    q.delays.push_back(static_cast<long>(given));  // a delay given replaces the robot's, its link's uplink delay included
    q.delay_keys.push_back(aurora_common::fullKey(pnh_, key));
  }
  crew_ = loadFormationCrew(q, file);
  for (int d = 0; d < crew_->robots(); ++d) drones_.push_back(crew_->robot(d).name_space);
  std::vector<std::string> launched;
  if (pnh_.getParam("drones", launched) && launched != drones_) {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, "drones") + "' = [" + joinKeys(launched) +
                                  "]: the formation file '" + q.file + "' flies " + std::to_string(crew_->robots()) +
                                  " robots in namespaces " + joinKeys(drones_) + ": give those (formation.launch does)");
  }
  refuseOtherSims();
}

// A simulated robot whose vehicle file (/NS/vehicle, as the launch loads it)
// is another vehicle, or steps at another sample time, would not fly the
// formation's run: refused naming the key.
void FormationNode::refuseOtherSims() const {
  for (int d = 0; d < crew_->robots(); ++d) {
    const CrewRobot& r = crew_->robot(d);
    const std::string type_key = "/" + r.name_space + "/vehicle/type", ts_key = "/" + r.name_space + "/vehicle/sample_time";
    std::string type;
    if (nh_.getParam(type_key, type) && type != r.vehicle) {
      throw aurora_common::ConfigError("parameter '" + type_key + "' = '" + type + "': robot " + std::to_string(d + 1) +
                                    " of the formation is a " + r.vehicle + ": load its vehicle file there");
    }
    double Ts = 0.0;
    if (nh_.getParam(ts_key, Ts) && Ts != crew_->sampleTime()) {
      throw aurora_common::ConfigError("parameter '" + ts_key + "' = " + aurora_common::numberText(Ts) +
                                    " s is not the formation's step " + aurora_common::numberText(crew_->sampleTime()) +
                                    " s (every robot steps at it): formation.launch sets it from the formation file");
    }
  }
}

void FormationNode::connect() {
  for (const std::string& name : drones_) {
    const std::string ns = "/" + name;
    const int d = static_cast<int>(cmd_pubs_.size());
    cmd_pubs_.push_back(nh_.advertise<geometry_msgs::Twist>(ns + "/cmd_vel", 1000));
    if (lockstep_) step_cmd_pubs_.push_back(nh_.advertise<geometry_msgs::TwistStamped>(ns + "/cmd_vel_stamped", 1000));
    state_subs_.push_back(nh_.subscribe<aurora_msgs::DroneState>(
        ns + "/state", 1000, [this, d](const aurora_msgs::DroneState::ConstPtr& m) { onState(d, m); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
  }
  formation_pub_ = nh_.advertise<aurora_msgs::Formation>("formation", 1000);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("markers", 10);
  if (!lockstep_) timer_ = nh_.createTimer(ros::Duration(crew_->sampleTime()), &FormationNode::onTimer, this);
}

bool FormationNode::listenersReady() const {
  for (const ros::Publisher& p : cmd_pubs_) {
    if (static_cast<int>(p.getNumSubscribers()) < cmd_subscribers_) return false;
  }
  // Each robot's sim steps on its cmd_vel_stamped (lockstep).
  for (const ros::Publisher& p : step_cmd_pubs_) {
    if (static_cast<int>(p.getNumSubscribers()) < std::min(1, cmd_subscribers_)) return false;
  }
  return true;
}

// Lockstep: a robot's state; once every robot's state of step k is here,
// tick k. A re-sent state of the step last answered (its command was lost)
// gets that command again; a re-sent state of a step not answered yet (a
// robot's state has not come) gets nothing: the sim would step on the
// previous command and leave the robots a step apart.
// A recorded flight (record:=true) takes its first state once the recorder
// listens to the formation topic and every robot's cmd_vel: the bag then
// holds every tick from the first (the controller node's rule). Both modes
// wait so for ~formation_subscribers listeners of formation too.
bool FormationNode::audienceReady() {
  if (audience_ready_) return true;
  const int formation = std::max(record_subscribers_, formation_subscribers_);
  bool ready = static_cast<int>(formation_pub_.getNumSubscribers()) >= formation;
  for (const ros::Publisher& p : cmd_pubs_) ready = ready && static_cast<int>(p.getNumSubscribers()) >= record_subscribers_;
  if (!ready) {
    ROS_INFO_THROTTLE(5.0, "formation_controller: waits for %d subscriber(s) of formation and %d recorder(s) of each "
                      "cmd_vel before its first state", formation, record_subscribers_);
  }
  audience_ready_ = ready;
  return ready;
}

void FormationNode::onState(int d, const aurora_msgs::DroneState::ConstPtr& msg) {
  if (msg->stale) return;  // the estimator's source stopped: the state ages
  if (!audienceReady()) return;
  if (lockstep_ && answered_ < 0 && !listenersReady()) {
    ROS_INFO_THROTTLE(5.0, "formation_controller: lockstep waits for the listeners of cmd_vel");
    return;  // the sims re-send their states
  }
  const bool fresh = crew_->push(d, sampleFromMsg(*msg));
  last_state_[d] = ros::Time::now();
  if (!lockstep_) return;
  if (!fresh) {
    if (static_cast<long>(msg->step) == answered_) {
      command(d, msg->header.stamp);
    }
    return;
  }
  const long k = crew_->commonStep();
  if (k >= 0) answer(k, msg->header.stamp);
}

// Realtime: every Ts on the newest states, once every robot sent one.
void FormationNode::onTimer(const ros::TimerEvent& event) {
  stall_.timerRan(event, crew_->sampleTime());  // state_age.h
  if (sequence_) return flightCycle(event.current_real);
  for (int d = 0; d < crew_->robots(); ++d) {
    if (!crew_->ready(d)) return;
  }
  answer(cycles_++, ros::Time::now());
}

void FormationNode::answer(long k, const ros::Time& stamp) {
  const CrewTick t = crew_->tick(k);
  send(t, stamp);
  answered_ = k;
  publish(t, stamp);
}

void FormationNode::command(int d, const ros::Time& stamp) {
  const geometry_msgs::Twist twist = aurora_sim::twistMsgOf(crew_->toDriver(d, last_sent_[d]));
  cmd_pubs_[d].publish(twist);
  if (!lockstep_) return;
  geometry_msgs::TwistStamped answer;
  answer.header.stamp = stamp;
  answer.twist = twist;
  step_cmd_pubs_[d].publish(answer);
}

void FormationNode::send(const CrewTick& t, const ros::Time& stamp) {
  if (t.not_finite >= 0) {
    const std::string& ns = drones_[t.not_finite];
    mode_ = "hover (" + ns + ": non-finite command)";
    if (!told_not_finite_) {
      ROS_ERROR("formation_controller: tick %ld: %s's law gave a non-finite command (the formation layer is singular "
                "where the drones are level or together, docs/formation.md): every robot hovers (zero commands) "
                "while it lasts; this is said once", t.k, ns.c_str());
      told_not_finite_ = true;
    }
  } else if (!sequence_) {
    mode_ = "fly";
  }
  for (int d = 0; d < crew_->robots(); ++d) {
    for (int i = 0; i < 4; ++i) last_sent_[d][i] = t.out[d].U[i];
    if (sequence_) crew_->limitSpeed(d, last_sent_[d], safety_[d].max_speed, safety_[d].max_turn_rate);
    command(d, stamp);
  }
}

void FormationNode::publish(const CrewTick& t, const ros::Time& stamp) {
  aurora_msgs::Formation m;
  m.header.stamp = stamp;
  m.header.frame_id = "world";
  m.step = static_cast<uint64_t>(t.k);
  m.shape = crew_->shape();
  m.sample_time = crew_->sampleTime();
  m.ticks = static_cast<uint64_t>(crew_->ticks());
  m.layer_ran = t.layer_ran;
  m.drones = drones_;
  m.mode = mode_;
  const int n = crew_->variables(), robots = crew_->robots();
  for (int i = 0; i < n; ++i) m.variables.push_back(crew_->variableName(i));
  m.Q.assign(crew_->Q(), crew_->Q() + n);
  m.Qd.assign(crew_->Qd(), crew_->Qd() + n);
  m.Qtil.assign(crew_->Qtil(), crew_->Qtil() + n);
  m.desired_position.resize(3 * robots);
  crew_->positionsOf(m.Qd.data(), m.desired_position.data());
  bool all_ready = true;
  for (int d = 0; d < robots; ++d) {
    m.vehicles.push_back(crew_->robot(d).vehicle);
    all_ready = all_ready && crew_->ready(d);
    for (int i = 0; i < 3; ++i) {
      m.reference_position.push_back(t.ref[d].pos[i]);
      m.reference_velocity.push_back(t.ref[d].vel[i]);
    }
    for (int i = 0; i < 4; ++i) m.command.push_back(last_sent_[d][i]);  // as sent (send() ran first)
  }
  m.position_error = m.shape_error = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> X(3 * robots);
  if (all_ready) {
    crew_->newestPositions(X.data());
    m.Q_newest.resize(n);
    crew_->variablesOf(X.data(), m.Q_newest.data());
    crew_->errors(X.data(), m.desired_position.data(), m.position_error, m.shape_error);
  }
  formation_pub_.publish(m);
  if (all_ready && t.k % kMarkerDecimation == 0 && markers_pub_.getNumSubscribers() > 0) {
    std::vector<const double*> held;
    for (int d = 0; d < robots; ++d) held.push_back(crew_->heldPosition(d));
    markers_pub_.publish(formationMarkers(X, m.desired_position, held, "world"));
  }
}

}  // namespace aurora_control
