// The formation node's tick, ROS-free (docs/formation.md, "In the ROS
// loop"): each drone's controller core (delayed_controller.h: its delay
// buffer or its link, its law, as the single-drone node's) and the formation
// layer on the states those cores deliver. Tick k is the offline runner's
// (formation_runner.h, "One tick"): when k is a multiple of the period the
// layer runs on the delivered positions towards Qd(k Ts), then each drone's
// law runs towards its held reference. The node calls it with the drones'
// states as they arrive; a test compares the drones' trajectories with the
// offline runner's bit for bit.
#pragma once

#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_sim/command_mapping.h"

namespace aurora_control {

template <int Capacity>
class FormationController {
 public:
  using Line = LineFormation<double>;
  static constexpr int kDrones = Line::kDrones;

  // What tick k gave each drone, and whether the layer ran.
  struct Tick {
    long k = 0;
    bool layer_ran = false;
    int not_finite = -1;  // the first drone whose law gave a non-finite command: every drone hovers instead
    Reference<double> ref[kDrones];
    ControlOutput out[kDrones];
  };

  // `run`: the formation (formation_yaml.h's formationRun), its drones'
  // delays and links; `law`: the drones' law. Commands are not clamped here
  // (the formation script clamps nowhere; drivers and the sim clamp).
  FormationController(const FormationRun<double, Line>& run, LawType law)
      : run_(run), layer_(run.law, run.gains, run.schedule.period(run.drone[0].plant.Ts)) {
    for (int d = 0; d < kDrones; ++d) {
      ControllerSettings& s = core_[d].settings;
      s.law = law;
      s.gains = run.drone[d].gains.pd;
      s.underactuated = run.drone[d].gains.underactuated;
      s.vehicle = run.drone[d].model;
      s.delay = run.drone[d].delay;
      s.link = run.drone[d].link;
      s.clamp_commands = false;
      s.Ts = run.drone[d].plant.Ts;
      core_[d].configureLink(static_cast<uint64_t>(d));  // keyed by the drone, as runFormation
    }
    startPositions(run, start_);
    startLayer();
  }

  // A state of drone d arrived; false for a re-sent one (lockstep). A step
  // going back (a reset sim) starts that drone's core afresh.
  bool push(int d, const StateSample& s) { return core_[d].push(s); }

  // The step every drone's newest state has, -1 when they differ or one has none.
  long commonStep() const {
    if (core_[0].empty()) return -1;
    const long k = core_[0].newest().step;
    for (int d = 1; d < kDrones; ++d) {
      if (core_[d].empty() || core_[d].newest().step != k) return -1;
    }
    return k;
  }
  bool ready(int d) const { return !core_[d].empty(); }
  const StateSample& newest(int d) const { return core_[d].newest(); }
  // The drones' stacked positions of their newest states (every drone ready).
  void newestPositions(double X[Line::kVariables]) const {
    const double* newest_X[kDrones];
    for (int d = 0; d < kDrones; ++d) newest_X[d] = core_[d].newest().X;
    dronePositions<Line>(newest_X, X);
  }

  // Tick k (the layer's period counts from k = 0; a k below the last one
  // starts the layer again, as the drones' reset did).
  Tick tick(long k) {
    if (k < last_k_) startLayer();
    last_k_ = k;
    Tick t;
    t.k = k;
    double time = 0.0, Qd[Line::kVariables];
    t.layer_ran = desiredBefore(run_, k, time, Qd);
    if (t.layer_ran) {
      double seen[Line::kVariables];
      const double* delivered[kDrones];
      for (int d = 0; d < kDrones; ++d) delivered[d] = core_[d].delivered().X;
      dronePositions<Line>(delivered, seen);
      layer_.update(seen, Qd);
    }
    for (int d = 0; d < kDrones; ++d) {
      t.ref[d] = heldReference(layer_, d);
      t.out[d] = core_[d].compute(t.ref[d]);
      if (t.not_finite < 0 && !aurora_sim::allFinite(t.out[d].U, 4)) t.not_finite = d;
    }
    // A NaN or infinite command never reaches a drone (the layer is singular
    // where the drones are level, line_formation.h): both hover, as the
    // flight sequence does when either must.
    if (t.not_finite >= 0) {
      for (int d = 0; d < kDrones; ++d) t.out[d] = core_[d].hover();
    }
    return t;
  }

  // Real drones (formation_supervisor.h): the formation starts from where
  // the drones are (positions, 3 per drone, m); the next tick is tick 0.
  void startFrom(const double X0[Line::kVariables]) {
    for (int i = 0; i < Line::kVariables; ++i) start_[i] = X0[i];
    startLayer();
  }
  // Before the formation starts: drone d's law flies to p and rests there.
  ControlOutput hold(int d, const double p[3]) { return core_[d].compute(p); }
  // A watchdog's hover: no law, a zero command.
  ControlOutput hover(int d) { return core_[d].hover(); }

  const FormationLayer<double, Line>& layer() const { return layer_; }
  const FormationRun<double, Line>& run() const { return run_; }

 private:
  void startLayer() {
    startLayerAt(run_, start_, layer_);
    last_k_ = -1;
  }

  FormationRun<double, Line> run_;
  FormationLayer<double, Line> layer_;
  DelayedController<Capacity> core_[kDrones];
  double start_[Line::kVariables];  // the drones' positions the layer starts from
  long last_k_ = -1;
};

}  // namespace aurora_control
