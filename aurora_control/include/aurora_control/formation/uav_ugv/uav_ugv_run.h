// The UAV-UGV line (docs/formation.md, "The UAV-UGV line") as the one
// formation loop flies it (formation_runner.h): a ground robot (robot 1,
// the reference) and a drone (robot 2), the law list's formation crews
// (other_laws.h: AuRoRA's Pioneer P3-DX and AR.Drone), each on its own law and model
// (a crew of EitherLaw robots), at the formation's tick, under the layer
// without integration (uav_ugv_line.h: every tick, before the laws, on the
// states the robots' links delivered). Each robot's state reaches the layer
// and its law, and its command the robot, over its own link (the delay
// rule with its delay over an ideal link, 0 AuRoRA's; or its link model,
// its draws keyed by its index). ROS-free.
#pragma once

#include <cmath>
#include <string>

#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_line.h"
#include "aurora_control/formation/robot_namespace.h"
#include "aurora_control/law/either_law.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/link/link.h"

namespace aurora_control {

// The line's robots, named here only: robot 1, the reference, the
// formations' ground robot on its law; robot 2 their drone on its law.
using UavUgvGroundLaw = FormationGroundLaw;
using UavUgvDroneLaw = FormationDroneLaw;
using UavUgvGround = UavUgvGroundLaw::Vehicle;
using UavUgvDrone = UavUgvDroneLaw::Vehicle;

struct UavUgvLineSetup {
  UavUgvGround::Params<double> ground{};  // its sample time is the tick's
  UavUgvGroundLaw::Gains<double> ground_gains = UavUgvGroundLaw::Gains<double>::defaults();
  double ground_start[3] = {-1, 0, 0};  // [m] its control point (AuRoRA's 2018 rSetPose), heading 0
  UavUgvDrone::Params<double> drone{};
  UavUgvDroneLaw::Gains<double> drone_gains = UavUgvDroneLaw::Gains<double>::defaults();  // its law's
  double drone_start[3] = {0, 0, 0.75};  // [m], at rest
  double k1[6], k2[6];                   // the layer's gains (UavUgvLine::defaultGains: AuRoRA's)
  double tick = 1.0 / 30.0;              // [s]
  long delay[2] = {0, 0};                // [ticks] each robot's feedback delay (ground robot, drone)
  LinkParams link[2];                    // each robot's link (docs/links.md; ideal unless its file gives one)
  double duration = 130.0;               // [s]: ticks k = 0 .. round(duration / tick) - 1
  std::string name_space[2] = {robotNamespace<UavUgvGround>(0),
                               robotNamespace<UavUgvDrone>(1)};  // each robot's ROS namespace (robots[i].namespace)
  std::string vehicle_file[2];           // each robot's vehicle file (robots[i].vehicle), in the config folder
  long ticks() const { return std::lround(duration / tick); }
};

using UavUgvRobots = EitherLaw<UavUgvGroundLaw, UavUgvDroneLaw>;
using UavUgvShape = UavUgvLine<double>;
using UavUgvRun = FormationRun<double, UavUgvShape, UavUgvRobots::Data>;

inline UavUgvRun uavUgvRun(const UavUgvLineSetup& s) {
  using Params = UavUgvRobots::Vehicle::Params<double>;
  UavUgvRun run;
  for (int i = 0; i < 6; ++i) run.gains.k1[i] = s.k1[i], run.gains.k2[i] = s.k2[i];
  run.reference.path = FormationPath::kOwn;  // the line's trajectory (UavUgvLine::ownReference)
  run.schedule.period_ticks = 1;  // every tick, on the robots' clock: t = k tick
  run.drone[0].plant = run.drone[0].model = Params::ofFirst(s.ground);
  run.drone[1].plant = run.drone[1].model = Params::ofSecond(s.drone);
  const double* starts[2] = {s.ground_start, s.drone_start};
  for (int r = 0; r < 2; ++r) {
    auto& robot = run.drone[r];
    robot.gains.first = s.ground_gains;
    robot.gains.second = s.drone_gains;
    robot.delay = s.delay[r];
    robot.link = s.link[r];
    for (int i = 0; i < 3; ++i) robot.start[i] = starts[r][i];
  }
  return run;
}

}  // namespace aurora_control
