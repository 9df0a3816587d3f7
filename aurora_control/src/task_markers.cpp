#include "task_markers.h"

#include <cmath>
#include <string>

namespace aurora_control {

namespace {

geometry_msgs::PoseStamped poseAt(const double p[3], const std_msgs::Header& header) {
  geometry_msgs::PoseStamped pose;
  pose.header = header;
  pose.pose.position.x = p[0];
  pose.pose.position.y = p[1];
  pose.pose.position.z = p[2];
  pose.pose.orientation.w = 1.0;
  return pose;
}

}  // namespace

visualization_msgs::MarkerArray waypointMarkers(const Task<double>& task) {
  visualization_msgs::MarkerArray markers;
  if (task.isTrajectory()) return markers;
  for (int i = 0; i < task.waypoints.count; ++i) {
    visualization_msgs::Marker m;
    m.header.frame_id = "world";
    m.ns = "waypoints";
    m.id = i;
    m.type = visualization_msgs::Marker::SPHERE;
    m.action = visualization_msgs::Marker::ADD;
    m.pose = poseAt(task.waypoints.position[i], m.header).pose;
    m.scale.x = m.scale.y = m.scale.z = 0.12;
    m.color.r = 0.9f;
    m.color.a = 1.0f;
    markers.markers.push_back(m);
    visualization_msgs::Marker label = m;
    label.ns = "waypoint_labels";
    label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    label.text = std::to_string(i + 1);
    label.pose.position.z += 0.15;
    label.color.r = label.color.g = label.color.b = 1.0f;
    markers.markers.push_back(label);
  }
  return markers;
}

nav_msgs::Path desiredPath(const Task<double>& task) {
  nav_msgs::Path path;
  path.header.frame_id = "world";
  path.header.stamp = ros::Time(0);
  if (!task.isTrajectory()) {
    for (int i = 0; i < task.waypoints.count; ++i) {
      path.poses.push_back(poseAt(task.waypoints.position[i], path.header));
    }
    return path;
  }
  const long samples = std::lround(task.duration() * 10.0);
  for (long k = 0; k <= samples; ++k) {
    path.poses.push_back(poseAt(task.at(double(k) / 10.0).pos, path.header));
  }
  return path;
}

}  // namespace aurora_control
