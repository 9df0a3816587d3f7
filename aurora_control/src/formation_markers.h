// rviz view of a formation (docs/formation.md, "In the ROS loop"): the line
// between the drones as they are, the desired formation (the positions of
// the layer's Qd, eq. F2: its line and a sphere per drone) and each drone's
// held reference. The drones' bodies and trails come from drone_marker and
// the sims' paths.
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include "aurora_control/formation/formation_layer.h"

namespace aurora_control {

// `X`: the drones' positions (3 per drone) as the node last received them.
visualization_msgs::MarkerArray formationMarkers(const double X[6], const FormationLayer<double, LineFormation<double>>& layer,
                                                 const std::string& frame);

}  // namespace aurora_control
