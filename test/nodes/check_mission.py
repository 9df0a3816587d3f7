#!/usr/bin/python3
"""The mission reaches each waypoint within `~tolerance` before its quarter ends."""
import math
import threading
import unittest

import rospy
import rostest
from aurora_msgs.msg import DroneState


class MissionTest(unittest.TestCase):
    def test_reaches_each_waypoint_in_time(self):
        waypoints = rospy.get_param("~task/waypoints")
        end_times = rospy.get_param("~task/end_times")
        tol = rospy.get_param("~tolerance")
        ts = rospy.get_param("vehicle/sample_time")
        last_step = int(round(end_times[-1] / ts))
        best = [float("inf")] * len(waypoints)
        done = threading.Event()

        def on_state(msg):
            t = msg.step * ts
            i = next((k for k, end in enumerate(end_times) if t <= end), None)
            if i is not None:
                p = msg.position
                wp = waypoints[i]
                err = math.sqrt((p.x - wp[0]) ** 2 + (p.y - wp[1]) ** 2 + (p.z - wp[2]) ** 2)
                best[i] = min(best[i], err)
            if msg.step >= last_step:
                done.set()

        rospy.Subscriber("state", DroneState, on_state, queue_size=2000)
        self.assertTrue(done.wait(90.0), "the mission did not reach step %d in 90 s" % last_step)
        for i, err in enumerate(best):
            rospy.loginfo("waypoint %d: closest approach %.4f m before t = %.1f s", i + 1, err, end_times[i])
            self.assertLess(err, tol, "waypoint %d %s: closest %.4f m before its quarter ended (t = %.1f s)"
                            % (i + 1, waypoints[i], err, end_times[i]))


if __name__ == "__main__":
    rospy.init_node("check_mission")
    rostest.rosrun("aurora_tests", "mission_reaches_waypoints", MissionTest)
