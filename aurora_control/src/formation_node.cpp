#include "formation_node.h"

#include <geometry_msgs/Twist.h>

#include "aurora_control/formation/formation_yaml.h"
#include "aurora_control/params/parameter_table.h"
#include "formation_markers.h"
#include "param_tree.h"
#include "aurora_control/ros/control_msg.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"

namespace aurora_control {

namespace {

// The formation node's own row; its other parameters are the controller's
// rows (parameter_table.h).
constexpr ParameterSpec kFormationSubscribers{
    "lockstep_subscribers/formation", ParamKind::kWhole, 0, 0, 100, "subscribers",
    "formation node, lockstep: subscribers of formation to wait for (a recorder, a test)"};

}  // namespace

FormationNode::FormationNode(ros::NodeHandle nh, ros::NodeHandle private_nh) : nh_(nh), pnh_(private_nh) {
  refuseDuplicatedKeysInLoadedFiles(pnh_);
  LawType law = LawType::kUnderactuated;
  const FormationRun<double, LineFormation<double>> run = loadRun(law);
  core_.reset(new Core(run, law));
  const std::string mode = aurora_common::wordParam(pnh_, kParameterTable[kRowMode]);  // the controller's row
  lockstep_ = mode == "lockstep";
  configureSequence();
  cmd_subscribers_ = static_cast<int>(aurora_common::wholeParam(pnh_, kParameterTable[kRowLockstepCmdSubscribers]));
  formation_subscribers_ = static_cast<int>(aurora_common::wholeParam(pnh_, kFormationSubscribers));
  connect();
  ROS_INFO("formation_controller: %s, drones %s and %s, delays %ld and %ld samples, %s law, layer every %ld steps",
           mode.c_str(), drones_[0].c_str(), drones_[1].c_str(), run.drone[0].delay, run.drone[1].delay,
           lawName(law), run.schedule.period_ticks);
}

// The formation file (~formation_file) with the drones' vehicle (~vehicle)
// and ~delay_1, ~delay_2 (-1: the file's); ~drones, when given, must be the
// file's namespaces (the launch started those sims).
FormationRun<double, LineFormation<double>> FormationNode::loadRun(LawType& law) {
  const std::string file = aurora_common::requireParam<std::string>(pnh_, "formation_file", "a formation file (config/formations/NAME.yaml)");
  const std::string config_dir = aurora_common::paramOr<std::string>(pnh_, "config_dir", "");
  const FormationFile f = readFormationFile(file, config_dir);
  const aurora_control::LawVehicleParams vehicle = aurora_sim::loadVehicleParams(pnh_, "vehicle");
  FormationRun<double, LineFormation<double>> run = formationRun(f, vehicle);
  law = f.drones[0].controller.law;
  for (int d = 0; d < kDrones; ++d) {
    drones_.push_back(f.drones[d].name_space);
    const std::string key = "delay_" + std::to_string(d + 1);
    const double given = aurora_common::rangedParam(pnh_, key, -1, -1, double(kMaxDelaySamples), "samples (-1: the file's)");
    if (given != double(long(given))) {
      throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, key) + "' = " + aurora_common::numberText(given) +
                                    " is refused: accepted whole samples");
    }
    // A delay given replaces the drone's, its link's uplink delay included (docs/links.md).
    if (given >= 0) run.drone[d].delay = static_cast<long>(given);
  }
  refuseFormationDelays(run, vehicle.Ts, {aurora_common::fullKey(pnh_, "delay_1"), aurora_common::fullKey(pnh_, "delay_2")});
  std::vector<std::string> launched;
  if (pnh_.getParam("drones", launched) && launched != drones_) {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, "drones") + "': the launch started drones '" +
                                  (launched.empty() ? std::string() : launched[0]) + "', ... but the formation file '" + file +
                                  "' names " + drones_[0] + " and " + drones_[1] + ": give the file's namespaces");
  }
  if (formationHistory(run) > kMaxDelaySamples) {
    throw aurora_common::ConfigError("the drones' delays plus their links' jitter need more than " +
                                  std::to_string(kMaxDelaySamples) + " samples of history");
  }
  return run;
}

void FormationNode::connect() {
  for (int d = 0; d < kDrones; ++d) {
    const std::string ns = "/" + drones_[d];
    cmd_pubs_.push_back(nh_.advertise<geometry_msgs::Twist>(ns + "/cmd_vel", 1000));
    state_subs_.push_back(nh_.subscribe<aurora_msgs::DroneState>(
        ns + "/state", 1000, [this, d](const aurora_msgs::DroneState::ConstPtr& m) { onState(d, m); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
  }
  formation_pub_ = nh_.advertise<aurora_msgs::Formation>("formation", 1000);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("markers", 10);
  if (!lockstep_) timer_ = nh_.createTimer(ros::Duration(core_->run().drone[0].plant.Ts), &FormationNode::onTimer, this);
}

bool FormationNode::listenersReady() const {
  for (const ros::Publisher& p : cmd_pubs_) {
    if (static_cast<int>(p.getNumSubscribers()) < cmd_subscribers_) return false;
  }
  return static_cast<int>(formation_pub_.getNumSubscribers()) >= formation_subscribers_;
}

// Lockstep: a drone's state; once every drone's state of step k is here,
// tick k. A re-sent state of the step last answered (its command was lost)
// gets that command again; a re-sent state of a step not answered yet (the
// other drone's state has not come) gets nothing: the sim would step on
// the previous command and leave the drones a step apart.
void FormationNode::onState(int d, const aurora_msgs::DroneState::ConstPtr& msg) {
  if (msg->stale) return;  // the estimator's source stopped: the state ages
  if (lockstep_ && answered_ < 0 && !listenersReady()) {
    ROS_INFO_THROTTLE(5.0, "formation_controller: lockstep waits for the listeners of cmd_vel and formation");
    return;  // the sims re-send their states
  }
  const bool fresh = core_->push(d, sampleFromMsg(*msg));
  last_state_[d] = ros::Time::now();
  if (!lockstep_) return;
  if (!fresh) {
    if (static_cast<long>(msg->step) == answered_) {
      cmd_pubs_[d].publish(aurora_sim::twistMsgFromModelCommand(last_sent_[d]));
    }
    return;
  }
  const long k = core_->commonStep();
  if (k >= 0) answer(k, msg->header.stamp);
}

// Realtime: every Ts on the newest states, once every drone sent one.
void FormationNode::onTimer(const ros::TimerEvent&) {
  if (sequence_) return flightCycle(ros::Time::now());
  for (int d = 0; d < kDrones; ++d) {
    if (!core_->ready(d)) return;
  }
  answer(cycles_++, ros::Time::now());
}

void FormationNode::answer(long k, const ros::Time& stamp) {
  const Core::Tick t = core_->tick(k);
  send(t);
  answered_ = k;
  publish(t, stamp);
}

void FormationNode::send(const Core::Tick& t) {
  if (t.not_finite >= 0) {
    const std::string& ns = drones_[t.not_finite];
    mode_ = "hover (" + ns + ": non-finite command)";
    if (!told_not_finite_) {
      ROS_ERROR("formation_controller: tick %ld: %s's law gave a non-finite command (the formation layer is singular "
                "where the drones are level or together, docs/formation.md): every drone hovers (zero commands) "
                "while it lasts; this is said once", t.k, ns.c_str());
      told_not_finite_ = true;
    }
  } else if (!sequence_) {
    mode_ = "fly";
  }
  for (int d = 0; d < kDrones; ++d) {
    for (int i = 0; i < 4; ++i) last_sent_[d][i] = t.out[d].U[i];
    cmd_pubs_[d].publish(aurora_sim::twistMsgFromModelCommand(t.out[d].U));
  }
}

void FormationNode::publish(const Core::Tick& t, const ros::Time& stamp) {
  aurora_msgs::Formation m;
  m.header.stamp = stamp;
  m.header.frame_id = "world";
  m.step = static_cast<uint64_t>(t.k);
  m.sample_time = core_->run().drone[0].plant.Ts;
  m.ticks = static_cast<uint64_t>(formationTicks(core_->run().reference.duration, m.sample_time));
  m.layer_ran = t.layer_ran;
  m.drones = drones_;
  m.mode = mode_;
  const FormationLayer<double, LineFormation<double>>& layer = core_->layer();
  for (int i = 0; i < 6; ++i) m.Q[i] = layer.Q()[i], m.Qd[i] = layer.Qd()[i], m.Qtil[i] = layer.Qtil()[i];
  for (int d = 0; d < kDrones; ++d) {
    for (int i = 0; i < 3; ++i) {
      m.reference_position.push_back(t.ref[d].pos[i]);
      m.reference_velocity.push_back(t.ref[d].vel[i]);
    }
    for (int i = 0; i < 4; ++i) m.command.push_back(t.out[d].U[i]);
  }
  formation_pub_.publish(m);
  if (t.k % kMarkerDecimation == 0 && markers_pub_.getNumSubscribers() > 0) {
    for (int d = 0; d < kDrones; ++d) {
      if (!core_->ready(d)) return;
    }
    double X[LineFormation<double>::kVariables];
    core_->newestPositions(X);
    markers_pub_.publish(formationMarkers(X, layer, "world"));
  }
}

}  // namespace aurora_control
