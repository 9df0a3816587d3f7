#!/usr/bin/python3
"""A bag recorded through sim.launch holds state, cmd_vel, control and tf."""
import glob
import os
import subprocess
import threading
import time
import unittest

import rosbag
import rospy
import rostest
from aurora_msgs.msg import DroneState


class BagTest(unittest.TestCase):
    def test_bag_has_analysis_topics(self):
        bag_dir = rospy.get_param("~bag_dir")
        prefix = rospy.get_param("~prefix")
        started = time.time()
        reached = threading.Event()
        rospy.Subscriber("state", DroneState, lambda m: reached.set() if m.step >= 300 else None)
        self.assertTrue(reached.wait(60.0), "the loop did not reach step 300")
        # Stop the recorder the way roslaunch would at shutdown; it closes the bag.
        subprocess.run(["rosnode", "kill", rospy.get_namespace() + "recorder"], check=True,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        bag_path = None
        deadline = time.time() + 20
        while time.time() < deadline and bag_path is None:
            fresh = [p for p in glob.glob(os.path.join(bag_dir, prefix + "_*.bag"))
                     if os.path.getmtime(p) >= started - 1]
            if fresh:
                bag_path = max(fresh, key=os.path.getmtime)
            else:
                time.sleep(0.2)
        self.assertIsNotNone(bag_path, "no closed bag %s_*.bag in %s" % (prefix, bag_dir))
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
