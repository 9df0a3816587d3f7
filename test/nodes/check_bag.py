#!/usr/bin/python3
"""A bag recorded through sim.launch holds state, cmd_vel, control and tf."""
import os
import sys
import unittest

import rosbag
import rospy
import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until  # noqa: E402


class BagTest(unittest.TestCase):
    def test_bag_has_analysis_topics(self):
        bag_dir = rospy.get_param("~bag_dir")
        prefix = rospy.get_param("~prefix")
        bag_path = record_until(300, bag_dir, prefix)
        ns = rospy.get_namespace()
        with rosbag.Bag(bag_path) as bag:
            info = bag.get_type_and_topic_info().topics
            counts = {t: info[t].message_count for t in info}
        rospy.loginfo("bag %s: %s", bag_path, counts)
        expected = {ns + "state": "aurora_msgs/DroneState", ns + "cmd_vel": "geometry_msgs/Twist",
                    ns + "control": "aurora_msgs/Control", "/tf": "tf2_msgs/TFMessage",
                    "/clock": "rosgraph_msgs/Clock"}
        for topic, msg_type in expected.items():
            self.assertIn(topic, info, "topic %s missing from the bag (has %s)" % (topic, sorted(info)))
            self.assertEqual(info[topic].msg_type, msg_type)
            self.assertGreaterEqual(info[topic].message_count, 250, "%s: only %d messages" % (topic, info[topic].message_count))
        os.remove(bag_path)


if __name__ == "__main__":
    rospy.init_node("check_bag")
    rostest.rosrun("aurora_tests", "bag_record", BagTest)
