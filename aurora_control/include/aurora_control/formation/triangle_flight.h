// AuRoRA's triangle flown (docs/formation.md, "The triangle"): the layer
// (formation_layer.h with TriangleFormation) every `period`, and either
// kinematic robots (each put at its reference before every period, the
// original's simulations) or three AR.Drones on the underactuated law, one
// model step per Ts. On a base tick of period / p = Ts / q (1/60 s for
// 0.05 s and 1/30 s): tick j = 0 the layer only; j >= 1 a multiple of q
// every drone's law and step; j a multiple of p, after the drones, the layer
// at t = j tick on the drones' positions. Each robot's state reaches its law
// and the layer through its own feedback delay (the delay rule,
// delay_buffer.h: in drone steps for drones, in layer periods for kinematic
// robots; 0: AuRoRA's), a drone's over its own link (robot_link.h).
// ROS-free.
#pragma once

#include <cmath>

#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/formation/triangle_formation.h"
#include "aurora_control/formation/triangle_reference.h"
#include "aurora_control/formation/robot_link.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/link/loop_link.h"
#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/params/limits.h"

namespace aurora_control {

struct TriangleSetup {
  TriangleLaw law = TriangleLaw::kN;
  FormationGains<double, 9> gains = FormationGains<double, 9>::of<TriangleFormation<double>>();
  double period = 0.05;      // [s] the layer's
  double duration = 50.0;    // [s]: the layer's periods n with t = n period < duration
  bool kinematic = true;     // the robots are their references (no vehicles)
  double start[9] = {1, 0, 0, -1, 0, 0, 0, 1, 0};  // [m] the robots' positions
  LawVehicleParams drone{};  // flying: each drone's (its Ts the robots' step)
  LawGains<double> drone_gains{{0.0, 0.0}, UnderactuatedGains<double>::defaults()};
  long layer_ticks = 1, drone_ticks = 1;  // the base tick's divisors: period / tick, Ts / tick
  long delay[3] = {0, 0, 0};  // each robot's feedback delay [drone steps; kinematic robots: layer periods]
  LinkParams link[3];         // each drone's link (docs/links.md; ideal unless the file gives one)
  long periods() const { return std::lround(std::ceil(duration / period - 1e-9)); }
};

class TriangleFlight {
 public:
  using DroneLaw = ArdroneLaw<LawType::kUnderactuated>;
  using Layer = FormationLayer<double, TriangleFormation<double>>;

  explicit TriangleFlight(const TriangleSetup& s)
      : layer(s.law, s.gains, s.period),
        s_(s),
        links_{{s.link[0], s.delay[0], 0, s.drone.Ts}, {s.link[1], s.delay[1], 1, s.drone.Ts},
               {s.link[2], s.delay[2], 2, s.drone.Ts}} {
    for (int d = 0; d < 3; ++d) {
      drone[d].reset(s.start[3 * d + 2]);
      drone[d].X[aurora_sim::kX] = s.start[3 * d], drone[d].X[aurora_sim::kY] = s.start[3 * d + 1];
      memory_[d].reset();
      history_[d].push(drone[d].X);  // state 0 (a drone's); its start (a kinematic robot's)
    }
    for (int k = 0; k < 9; ++k) X[k] = truth[k] = s.start[k];
    double Qd0[9];
    carrouselReference(0.0, Qd0);
    layer.start(X, Qd0);
  }

  // Layer period n with what comes before it: the kinematic robots put at
  // their references, or the drones' steps on the base ticks since the last
  // period.
  void period(long n) {
    if (s_.kinematic) {
      for (int k = 0; k < 9 && n > 0; ++k) truth[k] = layer.position(k / 3)[k % 3];
      for (int d = 0; d < 3 && n > 0; ++d) pushPosition(d, truth + 3 * d);
    } else {
      for (long j = (n - 1) * s_.layer_ticks + 1; n > 0 && j <= n * s_.layer_ticks; ++j) {
        if (j % s_.drone_ticks == 0) stepDrones();
      }
      for (int d = 0; d < 3; ++d) {
        for (int i = 0; i < 3; ++i) truth[3 * d + i] = drone[d].X[i];
      }
    }
    // The newest state: after steps_ drone steps, or a kinematic robot's of period n.
    const long newest = s_.kinematic ? n : steps_;
    for (int d = 0; d < 3; ++d) receivedPosition(d, newest, X + 3 * d);
    carrouselReference(double(n) * s_.period, Qd);
    layer.update(X, Qd);
  }

  Layer layer;
  aurora_sim::Ardrone2::State<double> drone[3];
  double X[9];                  // the positions the last period saw (each robot's delay)
  double truth[9];              // the robots' positions at the last period
  double Qd[9] = {};
  double U[3][4] = {};          // each drone's last command, as applied

 private:
  // Drone step `steps_`: each law on its drone's received state, each step;
  // the new states kept.
  void stepDrones() {
    for (int d = 0; d < 3; ++d) {
      Reference<double> ref{};
      for (int i = 0; i < 3; ++i) ref.pos[i] = layer.position(d)[i], ref.vel[i] = layer.velocity(d)[i];
      double xc[aurora_sim::Ardrone2::kStates], err[3];
      history_[d].read(links_[d].uplinkIndex(steps_), xc);
      DroneLaw::command(s_.drone, s_.drone_gains, memory_[d], ref, xc, U[d], err);
      links_[d].downlink(steps_, U[d], U[d]);  // what it applies
      aurora_sim::Ardrone2::step(s_.drone, drone[d], U[d]);
      history_[d].push(drone[d].X);
    }
    ++steps_;
  }

  // A kinematic robot's position as its state (the rest 0).
  void pushPosition(int d, const double p[3]) {
    double S[aurora_sim::Ardrone2::kStates] = {};
    for (int i = 0; i < 3; ++i) S[aurora_sim::kX + i] = p[i];
    history_[d].push(S);
  }

  // Robot d's position as received when its newest state is `newest`
  // (its index since the start), through its delay.
  void receivedPosition(int d, long newest, double p[3]) {
    double S[aurora_sim::Ardrone2::kStates];
    history_[d].read(links_[d].uplinkIndex(newest), S);
    for (int i = 0; i < 3; ++i) p[i] = S[aurora_sim::kX + i];
  }

  TriangleSetup s_;
  DroneLaw::Memory<double> memory_[3];
  StateHistory<DroneLaw, double, kDelayHistory> history_[3];  // each robot's states since the start
  RobotLink<aurora_sim::Ardrone2::kInputs> links_[3];
  long steps_ = 0;  // drone steps taken
};

}  // namespace aurora_control
