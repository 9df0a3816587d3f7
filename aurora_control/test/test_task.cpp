// Waypoint task schedule and validation.
#include <gtest/gtest.h>

#include "aurora_control/task/task.h"
#include "aurora_control/task/task_check.h"

using aurora_control::checkTask;
using aurora_control::WaypointTask;

namespace {
WaypointTask<double> mission() {
  WaypointTask<double> t;
  t.count = 4;
  const double wp[4][3] = {{1, 0, 1.5}, {1, 1.5, 2}, {-0.5, 1.5, 1.5}, {0, 0, 1}};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) t.position[i][j] = wp[i][j];
    t.end_time[i] = 15.0 * (i + 1);
  }
  t.duration = 60.0;
  return t;
}
}  // namespace

TEST(WaypointTask, OneWaypointPerQuarter) {
  const auto t = mission();
  EXPECT_EQ(t.activeIndex(0.0), 0);
  EXPECT_EQ(t.activeIndex(15.0), 0);
  EXPECT_EQ(t.activeIndex(15.01), 1);
  EXPECT_EQ(t.activeIndex(44.99), 2);
  EXPECT_EQ(t.activeIndex(59.0), 3);
  EXPECT_EQ(t.activeIndex(100.0), 3);  // holds the last waypoint after the end
  EXPECT_EQ(checkTask(t, "task/"), "");
}

TEST(Task, TaskTimeIsIntegerStepTimesTs) {
  EXPECT_EQ(aurora_control::taskTime(450, 1.0 / 30.0), 450 * (1.0 / 30.0));
}

TEST(WaypointTask, ValidationNamesTheKey) {
  auto t = mission();
  t.end_time[2] = 10.0;
  const std::string msg = checkTask(t, "/ardrone1/controller/task/");
  EXPECT_NE(msg.find("/ardrone1/controller/task/end_times[2]"), std::string::npos) << msg;
  t = mission();
  t.duration = -1;
  EXPECT_NE(checkTask(t, "task/").find("duration"), std::string::npos);
  t = mission();
  t.count = 0;
  EXPECT_NE(checkTask(t, "task/").find("waypoints"), std::string::npos);
}

// A waypoint under the ground (or on it) is refused like a circle's height
// below 0.2 m; an end time after the task's end is refused, not cut.
TEST(WaypointTask, RefusesWaypointsBelowTheGroundAndEndTimesAfterTheTask) {
  auto t = mission();
  t.position[1][2] = -2.0;
  std::string msg = checkTask(t, "task/");
  EXPECT_NE(msg.find("'task/waypoints[1]' has z = -2 m: accepted heights [0.2, 100] m"), std::string::npos) << msg;
  t.position[1][2] = 0.1;
  EXPECT_NE(checkTask(t, "task/").find("waypoints[1]"), std::string::npos);
  t.position[1][2] = 0.2;
  EXPECT_EQ(checkTask(t, "task/"), "");
  t = mission();
  t.count = 1;
  t.end_time[0] = 90.0;
  msg = checkTask(t, "task/");
  EXPECT_NE(msg.find("'task/end_times[0]' = 90 is after the task's duration (60 s)"), std::string::npos) << msg;
  t.end_time[0] = 60.0;
  EXPECT_EQ(checkTask(t, "task/"), "");
}
