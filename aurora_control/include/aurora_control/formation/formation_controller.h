// The formation node's tick, ROS-free (docs/formation.md, "In the ROS
// loop"): each robot's controller core (delayed_controller.h: its delay
// buffer or its link, its law, as the single-robot node's) and the formation
// layer of any shape (the two-drone line, the UAV-UGV line, the triangle) on
// the states those cores deliver. Tick k is the offline runner's
// (formation_runner.h, "One tick"): when the schedule says a period is due
// before robot step k the layer runs on the delivered positions towards Qd
// of its time, then each robot's law runs towards its held reference. The
// node calls it with the robots' states as they arrive; tests compare the
// robots' trajectories with the offline runner's bit for bit.
#pragma once

#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_sim/command_mapping.h"

namespace aurora_control {

// Robot r's controller settings from the run: its gains and the model its
// law inverts.
template <class Data>
void robotSettings(const FormationDrone<double, Data>& robot, LawSettings<Data>& s) {
  s.gains = robot.gains;
  s.vehicle = robot.model;
}

// Settings: LawSettings<Data> (the robots' law chosen at run time among
// Data's family; a mixed crew's EitherLaw is its own).
template <int Capacity, class Shape, class Settings>
class FormationController {
 public:
  using Data = typename Settings::Data;
  using Vehicle = typename Data::Vehicle;
  using Run = FormationRun<double, Shape, Data>;
  using Layer = LayerOf<double, Shape>;
  static constexpr int kDrones = Shape::kDrones, kN = Shape::kVariables;

  // What tick k gave each robot, and whether the layer ran.
  struct Tick {
    long k = 0;
    bool layer_ran = false;
    int not_finite = -1;  // the first robot whose law gave a non-finite command: every robot hovers instead
    Reference<double> ref[kDrones];
    ControlOutput out[kDrones];
  };

  // `run`: the formation (its robots, their delays and links); `common`:
  // what every robot's settings share (the AR.Drones' law). Commands are
  // not clamped here (AuRoRA's formation scripts clamp nowhere; drivers and
  // the sims clamp).
  FormationController(const Run& run, const Settings& common)
      : run_(run), layer_(run.law, run.gains, run.schedule.period(run.drone[0].plant.Ts)) {
    for (int d = 0; d < kDrones; ++d) {
      Settings& s = core_[d].settings;
      s = common;
      robotSettings(run.drone[d], s);
      s.delay = run.drone[d].delay;
      s.link = run.drone[d].link;
      s.clamp_commands = false;
      s.Ts = run.drone[d].plant.Ts;
      core_[d].configureLink(static_cast<uint64_t>(d));  // keyed by the robot, as runFormation
      core_[d].configurePredictor(dronePredictor(run, d));
    }
    startPositions(run, start_);
    startLayer();
  }

  // A state of robot d arrived; false for a re-sent one (lockstep). A step
  // going back (a reset sim) starts that robot's core afresh.
  bool push(int d, const StateSample& s) { return core_[d].push(s); }

  // The step every robot's newest state has, -1 when they differ or one has none.
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
  // The robots' stacked positions of their newest states (every robot ready).
  void newestPositions(double X[kN]) const {
    const double* newest_X[kDrones];
    for (int d = 0; d < kDrones; ++d) newest_X[d] = core_[d].newest().X;
    dronePositions<Shape, Vehicle>(newest_X, X);
  }

  // Tick k (a k below the last one starts the layer again, as the robots'
  // reset did): formationTick's steps on the states the cores deliver.
  Tick tick(long k) {
    if (k < last_k_) startLayer();
    last_k_ = k;
    Tick t;
    t.k = k;
    double time = 0.0, Qd[kN];
    t.layer_ran = desiredBefore(run_, k, time, Qd);
    // The states each robot's law flies on (its predictor's, when its
    // controller file has one), as the offline runner's layer reads them;
    // then each robot's core towards its held reference.
    StateSample flown[kDrones];
    const double* flown_X[kDrones] = {};
    for (int d = 0; t.layer_ran && d < kDrones; ++d) flown[d] = core_[d].flownState(), flown_X[d] = flown[d].X;
    layerThenRobots<Vehicle>(layer_, t.layer_ran ? Qd : nullptr, time, flown_X, [&](int d, const Reference<double>& ref) {
      t.ref[d] = ref;
      t.out[d] = core_[d].compute(ref);
      if (t.not_finite < 0 && !aurora_sim::allFinite(t.out[d].U, Vehicle::kInputs)) t.not_finite = d;
    });
    // A NaN or infinite command never reaches a robot (the line is singular
    // where the drones are level, line_formation.h): all hover, as the
    // flight sequence does when any must.
    if (t.not_finite >= 0) {
      for (int d = 0; d < kDrones; ++d) t.out[d] = core_[d].hover();
    }
    return t;
  }

  // Real robots (formation_supervisor.h): the formation starts from where
  // the robots are (positions, 3 per robot, m); the next tick is tick 0.
  void startFrom(const double X0[kN]) {
    for (int i = 0; i < kN; ++i) start_[i] = X0[i];
    startLayer();
  }
  // Before the formation starts: robot d's law flies to p and rests there.
  ControlOutput hold(int d, const double p[3]) { return core_[d].compute(p); }
  // A watchdog's hover: no law, a zero command.
  ControlOutput hover(int d) { return core_[d].hover(); }

  const Layer& layer() const { return layer_; }
  const Run& run() const { return run_; }

 private:
  void startLayer() {
    startLayerAt(run_, start_, layer_);
    last_k_ = -1;
  }

  Run run_;
  Layer layer_;
  DelayedController<Capacity, Settings> core_[kDrones];
  double start_[kN];  // the robots' positions the layer starts from
  long last_k_ = -1;
};

}  // namespace aurora_control
