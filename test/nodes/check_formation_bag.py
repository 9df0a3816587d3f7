#!/usr/bin/python3
"""A bag recorded through formation.launch record:=true holds every drone's
state and cmd_vel and the formation topic, one Formation per tick, whose
Qtil is Qd - Q and whose references cover both drones."""
import os
import sys
import unittest

import rosbag
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until  # noqa: E402


class FormationBagTest(unittest.TestCase):
    def test_bag_has_every_drone_and_the_formation(self):
        bag_path = record_until(300, rospy.get_param("~bag_dir"), rospy.get_param("~prefix"),
                                state="/ardrone2/state", recorder="/recorder")
        with rosbag.Bag(bag_path) as bag:
            info = bag.get_type_and_topic_info().topics
            formation = [m for _, m, _ in bag.read_messages(topics=["/formation/formation"])]
        rospy.loginfo("bag %s: %s", bag_path, {t: info[t].message_count for t in info})
        expected = {"/ardrone1/state": "aurora_msgs/DroneState", "/ardrone2/state": "aurora_msgs/DroneState",
                    "/ardrone1/cmd_vel": "geometry_msgs/Twist", "/ardrone2/cmd_vel": "geometry_msgs/Twist",
                    "/formation/formation": "aurora_msgs/Formation", "/clock": "rosgraph_msgs/Clock",
                    "/tf": "tf2_msgs/TFMessage"}
        for topic, msg_type in expected.items():
            self.assertIn(topic, info, "topic %s missing from the bag (has %s)" % (topic, sorted(info)))
            self.assertEqual(info[topic].msg_type, msg_type)
            self.assertGreaterEqual(info[topic].message_count, 250, "%s: only %d" % (topic, info[topic].message_count))
        # Every tick once (a bag orders by arrival on its clock: two that
        # arrive on one /clock value may swap).
        steps = sorted(m.step for m in formation)
        self.assertEqual(steps, list(range(steps[0], steps[0] + len(steps))), "a tick missing or twice")
        self.assertEqual(steps[0], 0)
        for m in formation:
            self.assertEqual(list(m.drones), ["ardrone1", "ardrone2"])
            self.assertEqual((len(m.reference_position), len(m.reference_velocity), len(m.command)), (6, 6, 8))
            for i in range(6):
                self.assertEqual(m.Qtil[i], m.Qd[i] - m.Q[i])
        self.assertEqual(sum(m.layer_ran for m in formation), (len(formation) + 5) // 6)
        os.remove(bag_path)


if __name__ == "__main__":
    rospy.init_node("check_formation_bag")
    rostest.rosrun("aurora_tests", "formation_bag", FormationBagTest)
