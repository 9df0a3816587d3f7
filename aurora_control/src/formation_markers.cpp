#include "formation_markers.h"

namespace aurora_control {

namespace {

visualization_msgs::Marker base(const std::string& frame, const std::string& ns, int id, int type,
                                const float rgba[4], double scale) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = scale;
  m.color.r = rgba[0], m.color.g = rgba[1], m.color.b = rgba[2], m.color.a = rgba[3];
  return m;
}

geometry_msgs::Point point(const double* p) {
  geometry_msgs::Point q;
  q.x = p[0], q.y = p[1], q.z = p[2];
  return q;
}

}  // namespace

visualization_msgs::MarkerArray formationMarkers(const std::vector<double>& X, const std::vector<double>& Xd,
                                                 const std::vector<const double*>& held, const std::string& frame) {
  const float actual[4] = {0.1f, 0.9f, 0.2f, 1.0f}, desired[4] = {1.0f, 1.0f, 1.0f, 0.8f},
              reference[4] = {1.0f, 0.6f, 0.0f, 0.9f};
  visualization_msgs::MarkerArray a;
  visualization_msgs::Marker line = base(frame, "formation_line", 0, visualization_msgs::Marker::LINE_STRIP, actual, 0.03);
  visualization_msgs::Marker want = base(frame, "desired_line", 0, visualization_msgs::Marker::LINE_STRIP, desired, 0.02);
  visualization_msgs::Marker spots = base(frame, "desired_drones", 0, visualization_msgs::Marker::SPHERE_LIST, desired, 0.12);
  visualization_msgs::Marker refs = base(frame, "references", 0, visualization_msgs::Marker::SPHERE_LIST, reference, 0.08);
  const size_t robots = held.size();
  for (size_t d = 0; d < robots; ++d) {
    line.points.push_back(point(&X[3 * d]));
    want.points.push_back(point(&Xd[3 * d]));
    spots.points.push_back(point(&Xd[3 * d]));
    refs.points.push_back(point(held[d]));
  }
  if (robots > 2) {  // a closed shape (the triangle): back to robot 1
    line.points.push_back(line.points.front());
    want.points.push_back(want.points.front());
  }
  a.markers = {line, want, spots, refs};
  return a;
}

}  // namespace aurora_control
