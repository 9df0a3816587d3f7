#include "aurora_sweep/rviz_markers.h"

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cstdio>

namespace aurora_sweep {

bool rvizMasterReachable(int argc, char** argv) {
  ros::init(argc, argv, "sweep", ros::init_options::AnonymousName);
  if (ros::master::check()) return true;
  std::fprintf(stderr, "sweep: --rviz: no ROS master at %s: start roscore first, or drop --rviz "
               "(nothing was run)\n", ros::master::getURI().c_str());
  return false;
}

int publishFeasibleMarkers(int, char**, const SweepSpec& spec, const std::vector<SimResult>& results) {
  if (!ros::master::check()) {
    std::fprintf(stderr, "sweep: --rviz: the ROS master at %s went away\n", ros::master::getURI().c_str());
    return 7;
  }
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<visualization_msgs::MarkerArray>("/sweep/feasible", 1, true);
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "world";
  t.child_frame_id = "sweep";
  t.transform.rotation.w = 1.0;
  tf.sendTransform(t);

  const GridView grid = spec.view();
  const double ts = spec.Ts();
  // x and y: the first two varied parameters besides the delay (kp and kd
  // for the PD law's grids), else the first columns.
  std::vector<int> xy;
  for (int id : spec.columns()) {
    if (id != kParamDelay && spec.varies(id)) xy.push_back(id);
  }
  for (int id : spec.columns()) {
    if (id != kParamDelay && std::find(xy.begin(), xy.end(), id) == xy.end()) xy.push_back(id);
  }
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker points;
  points.header.frame_id = "sweep";
  points.header.stamp = ros::Time::now();
  points.ns = "feasible";
  points.id = 0;
  points.type = visualization_msgs::Marker::SPHERE_LIST;
  points.action = visualization_msgs::Marker::ADD;
  points.pose.orientation.w = 1.0;
  points.scale.x = points.scale.y = points.scale.z = 0.015;
  points.color.r = points.color.g = points.color.b = 0.1f;
  points.color.a = 1.0f;
  for (size_t i = 0; i < results.size(); ++i) {
    if (!feasible(results[i])) continue;
    const Combination c = grid.decode(static_cast<long>(i));
    geometry_msgs::Point p;
    p.x = c.v[xy[0]];
    p.y = c.v[xy[1]];
    p.z = c.delay() * ts;
    points.points.push_back(p);
    std_msgs::ColorRGBA color;
    color.r = static_cast<float>(c.delay() * ts / std::max(1e-9, spec.max_delay * ts));
    color.g = 0.3f;
    color.b = 1.0f - color.r;
    color.a = 1.0f;
    points.colors.push_back(color);
  }
  array.markers.push_back(points);
  const std::string labels[] = {spec.paramNameOf(xy[0]), spec.paramNameOf(xy[1]), "delay [s]"};
  for (int a = 0; a < 3; ++a) {
    visualization_msgs::Marker text;
    text.header = points.header;
    text.ns = "axes";
    text.id = a;
    text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    text.action = visualization_msgs::Marker::ADD;
    text.pose.orientation.w = 1.0;
    text.pose.position.x = a == 0 ? 0.9 : 0.0;
    text.pose.position.y = a == 1 ? 1.1 : 0.0;
    text.pose.position.z = a == 2 ? spec.max_delay * ts + 0.15 : 0.0;
    text.scale.z = 0.08;
    text.color.r = text.color.g = text.color.b = text.color.a = 1.0f;
    text.text = labels[a];
    array.markers.push_back(text);
  }
  pub.publish(array);
  std::fprintf(stderr, "sweep: published %zu feasible combinations on /sweep/feasible "
               "(x = %s, y = %s, z = delay [s]); Ctrl-C to quit\n", points.points.size(), spec.paramNameOf(xy[0]),
               spec.paramNameOf(xy[1]));
  ros::spin();
  return 0;
}

}  // namespace aurora_sweep
