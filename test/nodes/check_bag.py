#!/usr/bin/python3
"""A bag recorded through sim.launch holds state, cmd_vel, control and tf;
aurora.read_bag gives its states and controls as DataFrames, equal to the
offline flight (aurora.simulate) at every recorded step."""
import os
import sys
import unittest

import numpy as np
import rosbag
import rospy
import rostest

import aurora

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
        self.check_read_bag(bag_path, ns.rstrip("/"))
        os.remove(bag_path)

    def check_read_bag(self, bag_path, ns):
        f = aurora.read_bag(bag_path)[ns]
        offline = aurora.simulate("pd_saturated", "mission4", delay=4)  # sim.launch's defaults, lockstep
        k = f.states.step.to_numpy()
        self.assertGreaterEqual(len(k), 250)
        self.assertTrue(np.array_equal(k, np.arange(len(k))), "state steps missing or repeated")
        for i, c in enumerate(("x", "y", "z", "roll", "pitch", "yaw")):
            self.assertTrue(np.array_equal(f.states[c].to_numpy(), offline.states[k, i]), c)
        steps = f.controls.step.to_numpy()
        for i, c in enumerate(("u1", "u2", "u3", "u4")):
            self.assertTrue(np.array_equal(f.controls[c].to_numpy(), offline.commands[steps, i]), c)
        self.assertTrue((f.controls.delay_samples == 4).all())
        self.assertEqual(f.metrics["iae"], f.controls.iae.iloc[-1])
        with self.assertRaises(ValueError) as e:
            aurora.read_bag(bag_path + ".missing")
        self.assertIn("does not exist", str(e.exception))


if __name__ == "__main__":
    rospy.init_node("check_bag")
    rostest.rosrun("aurora_tests", "bag_record", BagTest)
