// AuRoRA's triangle (docs/formation.md, "The triangle") as the one
// formation loop flies it (formation_runner.h): a triangle file's setup
// (triangle_yaml.h) becomes a FormationRun of the triangle's shape, its
// robots three of the formations' drones on their law (other_laws.h's
// FormationDroneLaw: AuRoRA's AR.Drones, underactuated), one model step per Ts,
// the layer on its own clock every period (on the base tick of both: the
// drones every q ticks, the layer every p, after the drones' steps that end
// by its tick), or three kinematic robots (kinematic_robot.h: each put at
// its reference, one step per period). Each robot's state reaches its law
// and the layer through its own delay (in drone steps; a kinematic
// robot's in periods) and link. ROS-free.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/triangle/kinematic_robot.h"
#include "aurora_control/formation/triangle/triangle_formation.h"
#include "aurora_control/formation/robot_namespace.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/params/limits.h"

namespace aurora_control {

// The triangle's flying robots: the formations' drones (other_laws.h), named
// here only (every other file of the triangle says TriangleDroneLaw).
using TriangleDroneLaw = FormationDroneLaw;
using TriangleDrones = TriangleDroneLaw::Data;
using TriangleDrone = TriangleDroneLaw::Vehicle;

struct TriangleSetup {
  TriangleLaw law = TriangleLaw::kN;
  FormationGains<double, 9> gains = FormationGains<double, 9>::of<TriangleFormation<double>>();
  double period = 0.05;      // [s] the layer's
  double duration = 50.0;    // [s]: the layer's periods n with t = n period < duration
  bool kinematic = true;     // the robots are their references (no vehicles)
  double start[9] = {1, 0, 0, -1, 0, 0, 0, 1, 0};  // [m] the robots' positions
  TriangleDrone::Params<double> drone{};  // flying: each drone's (its Ts the robots' step)
  std::string drone_file;    // flying: the drones' vehicle file (robots.vehicle), in the config folder
  TriangleDroneLaw::Gains<double> drone_gains = TriangleDroneLaw::Gains<double>::defaults();
  long layer_ticks = 1, drone_ticks = 1;  // the base tick's divisors: period / tick, Ts / tick
  long delay[3] = {0, 0, 0};  // each robot's feedback delay [drone steps; kinematic robots: layer periods]
  LinkParams link[3];         // each drone's link (docs/links.md; ideal unless the file gives one)
  std::string name_space[3] = {robotNamespace<TriangleDrone>(0), robotNamespace<TriangleDrone>(1),
                               robotNamespace<TriangleDrone>(2)};  // ROS namespaces (robots.namespaces)
  PredictorRun<TriangleDrone, double> predictor;  // flying: the drones' controller file's (docs/predictor.md)
  long periods() const { return std::lround(std::ceil(duration / period - 1e-9)); }
};

using Triangle = TriangleFormation<double>;
template <class Law>
using TriangleRun = FormationRun<double, Triangle, typename Law::Data>;

// The robot steps that fly periods 0 .. periods() - 1: through the step
// before which the last period's layer runs.
inline long triangleSteps(const TriangleSetup& s) {
  const long last = s.periods() - 1;
  return s.kinematic ? last + 1 : last * s.layer_ticks / s.drone_ticks + 1;
}

// A flying robot's model and gains; a kinematic robot's step (the period).
inline void triangleRobot(const TriangleSetup& s, FormationDrone<double, TriangleDroneLaw::Data>& robot) {
  robot.plant = robot.model = s.drone;
  robot.gains = s.drone_gains;
  robot.predictor = s.predictor;
}
inline void triangleRobot(const TriangleSetup& s, FormationDrone<double, FollowReference>& robot) {
  robot.plant = robot.model = KinematicRobot::Params<double>{s.period};
}

// The run of the setup's robots: flying (Law: TriangleDroneLaw) or
// kinematic (Law: FollowReference).
template <class Law>
TriangleRun<Law> triangleRun(const TriangleSetup& s) {
  TriangleRun<Law> run;
  run.law = s.law;
  run.gains = s.gains;
  run.reference.path = FormationPath::kOwn;  // the carrousel (TriangleFormation::ownReference)
  run.schedule.own_clock = true;
  run.schedule.own_period = s.period;
  run.schedule.period_ticks = s.kinematic ? 1 : s.layer_ticks;
  run.schedule.step_ticks = s.kinematic ? 1 : s.drone_ticks;
  for (int d = 0; d < 3; ++d) {
    auto& robot = run.drone[d];
    triangleRobot(s, robot);
    robot.delay = s.delay[d];
    robot.link = s.link[d];
    for (int i = 0; i < 3; ++i) robot.start[i] = s.start[3 * d + i];
  }
  return run;
}

// Flies the setup's robots (flying or kinematic: `fly(law)` with the law
// type's default value), as generic code over either.
template <class Fly>
auto withTriangleLaw(const TriangleSetup& s, Fly&& fly) -> decltype(fly(FollowReference())) {
  if (s.kinematic) return fly(FollowReference());
  return fly(TriangleDroneLaw());
}

// What the table and the errors read at period n: each robot's state at
// the period (its positions first) and its last command as applied, the
// layer's variables, error and Qd.
struct TrianglePeriod {
  long n;
  const double* X[3];
  const double* U[3];
  const FormationLayer<double, Triangle>& layer;
  double position(int d, int i) const { return X[d][i]; }  // [m]
};

// The setup's robots (law `Law`) through the one formation loop, `at(p)`
// at each of its periods: the robots' states at the period (X_k of the
// step the layer runs before), their commands of the step before.
template <class Law, class At>
void flyTrianglePeriods(const TriangleSetup& setup, At&& at) {
  using Vehicle = typename Law::Vehicle;
  static_assert(Vehicle::kPosition == 0, "TrianglePeriod reads a robot's x y z first in its state");
  const TriangleRun<Law> run = triangleRun<Law>(setup);
  double U[3][Vehicle::kInputs] = {};
  long n = 0;
  auto observe = [&](const FormationObservation<double, Triangle, typename Law::Data>& o) {
    if (o.layer_ran) at(TrianglePeriod{n++, {o.X_before[0], o.X_before[1], o.X_before[2]}, {U[0], U[1], U[2]}, o.layer});
    for (int d = 0; d < 3; ++d) std::copy(o.steps[d].U, o.steps[d].U + Vehicle::kInputs, U[d]);
  };
  runFormation<Law, double, Triangle, kDelayHistory>(run, triangleSteps(setup), observe);
}

}  // namespace aurora_control
