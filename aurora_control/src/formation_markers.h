// rviz view of a formation of any shape (docs/formation.md, "In the ROS
// loop"): the robots joined as they are (the line; the triangle closed), the
// desired formation (the positions of the layer's Qd: joined the same way,
// a sphere per robot) and each robot's held reference. The robots' bodies
// and trails come from drone_marker and the sims' paths.
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

namespace aurora_control {

// `X`: the robots' positions (3 per robot) as the node last received them;
// `Xd`: the desired ones; `held[r]`: robot r's reference position.
visualization_msgs::MarkerArray formationMarkers(const std::vector<double>& X, const std::vector<double>& Xd,
                                                 const std::vector<const double*>& held, const std::string& frame);

}  // namespace aurora_control
