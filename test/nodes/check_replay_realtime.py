#!/usr/bin/python3
"""replay_realtime*.test: a realtime flight recorded with record:=true holds
the loop from the controller's first cycle (the controller takes its first
state once the recorder listens), so replay gives every command again
(--expect-identical, over the flight's link file); the same bag cut to
start late (its first seconds dropped, as a recorder started late would
have it) is said to start late and still replays identical from the first
cycle whose inputs it holds."""
import os
import sys
import unittest

import rosbag
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402


class ReplayRealtimeTest(unittest.TestCase):
    def replay(self, bag):
        cmd = ["rosrun", "aurora_control", "replay", bag, "--expect-identical"]
        if rospy.has_param("~link"):
            cmd += ["--link", rospy.get_param("~link")]
        return run(cmd)

    def test_a_realtime_bag_replays_identical(self):
        p = lambda key: rospy.get_param("~" + key)  # noqa: E731
        bag = record_until(p("steps"), p("bag_dir"), p("prefix"), timeout=180.0)
        ns = rospy.get_namespace().rstrip("/")
        with rosbag.Bag(bag) as b:
            controls = [m for _, m, _ in b.read_messages(topics=[ns + "/control"])]
        self.assertGreater(len(controls), p("steps") // 2)
        # The controller's first cycle is in the bag (roscpp numbers a publisher's messages from 0).
        self.assertEqual(controls[0].header.seq, 0, "the recorder missed the controller's first cycles")
        rc, log = self.replay(bag)
        rospy.loginfo(log)
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        self.assertNotIn("starts late", log)
        # The same bag from 2 s in: says so, and the cycles it can replay are identical.
        late = bag[:-4] + "_late.bag"
        try:
            with rosbag.Bag(bag) as b, rosbag.Bag(late, "w") as out:
                start = b.get_start_time() + 2.0
                for topic, msg, t in b.read_messages():
                    if t.to_sec() >= start:
                        out.write(topic, msg, t)
            rc, log = self.replay(late)
            rospy.loginfo(log)
            self.assertEqual(rc, 0, log)
            self.assertIn("replay: the bag starts late: the controller's first ", log)
            self.assertIn(" 0 differ, max |dU| = 0 ", log)
        finally:
            for f in (bag, late):
                if os.path.exists(f):
                    os.remove(f)


if __name__ == "__main__":
    rospy.init_node("check_replay_realtime")
    rostest.rosrun("aurora_tests", "replay_realtime", ReplayRealtimeTest)
