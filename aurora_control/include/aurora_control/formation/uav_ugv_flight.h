// The UAV-UGV line flown (docs/formation.md, "The UAV-UGV line"): a
// Pioneer P3-DX (robot 1, the reference) and an AR.Drone (robot 2), each on
// its own law and model at the formation's tick, under the layer without
// integration (uav_ugv_line.h). Each tick k (t = k tick): the layer on the
// measured positions, the drone's law, the Pioneer's law, the drone's
// step, the Pioneer's step (AuRoRA's script's order). Each robot's state
// reaches the layer and its law, and its command the robot, over its own
// link (robot_link.h: the delay rule with its delay over an ideal link, 0
// AuRoRA's; or its link model). ROS-free.
#pragma once

#include <cmath>

#include "aurora_control/formation/robot_link.h"
#include "aurora_control/formation/uav_ugv_line.h"
#include "aurora_control/link/loop_link.h"
#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/law/pioneer_laws.h"

namespace aurora_control {

struct UavUgvLineSetup {
  aurora_sim::Pioneer3dx::Params<double> pioneer{};  // its sample time is the tick's
  PioneerDynamicGains<double> pioneer_gains = PioneerDynamicGains<double>::defaults();
  double pioneer_start[3] = {-1, 0, 0};  // [m] its control point (AuRoRA's 2018 rSetPose), heading 0
  LawVehicleParams drone{};
  LawGains<double> drone_gains{{0.0, 0.0}, UnderactuatedGains<double>::defaults()};  // the underactuated law's
  double drone_start[3] = {0, 0, 0.75};  // [m], at rest
  double k1[6], k2[6];                   // the layer's gains (UavUgvLine::defaultGains: AuRoRA's)
  double tick = 1.0 / 30.0;              // [s]
  long delay[2] = {0, 0};                // [ticks] each robot's feedback delay (Pioneer, drone)
  LinkParams link[2];                    // each robot's link (docs/links.md; ideal unless its file gives one)
  double duration = 130.0;               // [s]: ticks k = 0 .. round(duration / tick) - 1
  long ticks() const { return std::lround(duration / tick); }
};

class UavUgvLineFlight {
 public:
  using DroneLaw = ArdroneLaw<LawType::kUnderactuated>;

  explicit UavUgvLineFlight(const UavUgvLineSetup& s)
      : layer(s.k1, s.k2), s_(s), pioneer_link_(s.link[0], s.delay[0], 0, s.tick), drone_link_(s.link[1], s.delay[1], 1, s.tick) {
    pioneer.reset();
    for (int i = 0; i < 3; ++i) pioneer.X[aurora_sim::kX + i] = s.pioneer_start[i];
    pioneer_memory_.reset();
    drone.reset(s.drone_start[2]);
    drone.X[aurora_sim::kX] = s.drone_start[0], drone.X[aurora_sim::kY] = s.drone_start[1];
    drone_memory_.reset();
  }

  // Tick k: the states received (each robot's link), the layer, both
  // laws, the commands over the links, both steps.
  void tick(long k) {
    pioneer_history_.push(pioneer.X), drone_history_.push(drone.X);
    double Xp[aurora_sim::Pioneer3dx::kStates], Xd[aurora_sim::Ardrone2::kStates];
    pioneer_history_.read(pioneer_link_.uplinkIndex(k), Xp);
    drone_history_.read(drone_link_.uplinkIndex(k), Xd);
    uavUgvReference(double(k) * s_.tick, Qd, dQd);
    const double X[6] = {Xp[0], Xp[1], Xp[2], Xd[0], Xd[1], Xd[2]};
    layer.update(X, Qd, dQd);
    double err[3];
    DroneLaw::command(s_.drone, s_.drone_gains, drone_memory_, held(1), Xd, U_drone, err);
    PioneerDynamic::command(s_.pioneer, s_.pioneer_gains, pioneer_memory_, held(0), Xp, U_pioneer, err);
    drone_link_.downlink(k, U_drone, U_drone);  // what each robot applies (as sent over an ideal link)
    pioneer_link_.downlink(k, U_pioneer, U_pioneer);
    aurora_sim::Ardrone2::step(s_.drone, drone, U_drone);
    aurora_sim::Pioneer3dx::step(s_.pioneer, pioneer, U_pioneer);
  }

  UavUgvLineLayer<double> layer;
  aurora_sim::Pioneer3dx::State<double> pioneer;
  aurora_sim::Ardrone2::State<double> drone;
  double U_pioneer[2] = {0, 0}, U_drone[4] = {0, 0, 0, 0};  // the last tick's commands, as applied
  double Qd[6] = {}, dQd[6] = {};                            // the last tick's desired formation

 private:
  // Robot r's reference of this tick: the desired position, the law's velocity.
  Reference<double> held(int r) const {
    Reference<double> ref{};
    for (int i = 0; i < 3; ++i) ref.pos[i] = layer.position(r)[i], ref.vel[i] = layer.velocity(r)[i];
    return ref;
  }

  UavUgvLineSetup s_;
  PioneerDynamic::Memory<double> pioneer_memory_;
  DroneLaw::Memory<double> drone_memory_;
  // What each law reads of its robot's states (a Pioneer's z is 0: not kept).
  StateHistory<PioneerDynamic, double, kDelayHistory> pioneer_history_;
  StateHistory<DroneLaw, double, kDelayHistory> drone_history_;
  RobotLink<aurora_sim::Pioneer3dx::kInputs> pioneer_link_;
  RobotLink<aurora_sim::Ardrone2::kInputs> drone_link_;
};

}  // namespace aurora_control
