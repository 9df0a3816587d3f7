// AuRoRA's line formation of two AR.Drones (docs/formation.md; its formation
// files, flight's and the sweep's line) as the one formation loop flies it:
// its run, what the runner's observers see of it and its judge, spelled
// once here, beside the other shapes' runs (uav_ugv_run.h, triangle_run.h),
// so that no generic header names a vehicle. ROS-free.
#pragma once

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/line/line_formation.h"
#include "aurora_control/law/ardrone2/control_law.h"

namespace aurora_control {

using ArdroneLineRun = FormationRun<double, LineFormation<double>, ArdroneLawData>;
using ArdroneLineObservation = FormationObservation<double, LineFormation<double>, ArdroneLawData>;
using ArdroneLineJudge = FormationJudge<double, LineFormation<double>, ArdroneLawData>;

}  // namespace aurora_control
