// AuRoRA's line formation of two drones (docs/formation.md; its formation
// files, flight's and the sweep's line) as the one formation loop flies it:
// its run, what the runner's observers see of it and its judge, spelled
// once here, beside the other shapes' runs (uav_ugv_run.h, triangle_run.h).
// Its drones are the law list's formation drones (other_laws.h). ROS-free.
#pragma once

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/line/line_formation.h"
#include "aurora_control/law/other_laws.h"

namespace aurora_control {

// The line's crew: the family of the formations' drone law (each drone's
// file chooses its law among it), named here only (every other file of the
// line says LineDrones).
using LineDrones = FormationDroneLaw::Data;

using LineRun = FormationRun<double, LineFormation<double>, LineDrones>;
using LineObservation = FormationObservation<double, LineFormation<double>, LineDrones>;
using LineJudge = FormationJudge<double, LineFormation<double>, LineDrones>;

}  // namespace aurora_control
