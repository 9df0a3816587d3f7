#!/usr/bin/python3
"""replay_realtime*.test: a realtime flight recorded with record:=true holds
the loop from the controller's first cycle (the controller takes its first
state once the recorder listens), so replay gives every command again
(--expect-identical, over the flight's link file); the same bag cut to
start late (its first seconds dropped, as a recorder started late would
have it) is said to start late and still replays identical from the first
cycle whose inputs it holds; the same bag with states recorded before the
controller took its first (the recorder listens to `state` a little before
the controller sees it on `control`), or without the controller's first
states (it listens a little after: on a loaded machine, a few states each
way), replays identical too: replay starts the history where the
controller's first cycle says it began, and takes the states the bag lacks
from the control messages that used them."""
import copy
import os
import sys
import unittest

import rosbag
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402


class ReplayRealtimeTest(unittest.TestCase):
    def replay(self, bag):
        cmd = rosrun("aurora_control", "replay") + [bag, "--expect-identical"]
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
        self.assertNotIn("starts late", self.replays_identically(bag))
        # The same bag from 2 s in: says so, and the cycles it can replay are identical.
        late, early, after = bag[:-4] + "_late.bag", bag[:-4] + "_early.bag", bag[:-4] + "_after.bag"
        try:
            self.check_states_before_the_controllers_first(bag, early, ns)
            self.check_the_controllers_first_states_missing(bag, after, ns)
            with rosbag.Bag(bag) as b, rosbag.Bag(late, "w") as out:
                start = b.get_start_time() + 2.0
                for topic, msg, t in b.read_messages():
                    if t.to_sec() >= start:
                        out.write(topic, msg, t)
            self.assertIn("replay: the bag starts late: the controller's first ", self.replays_identically(late))
        finally:
            for f in (bag, late, early, after):
                if os.path.exists(f):
                    os.remove(f)


    def replays_identically(self, bag):
        """replay BAG --expect-identical succeeds with no command differing; its output."""
        rc, log = self.replay(bag)
        rospy.loginfo(log)
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        return log

    def check_states_before_the_controllers_first(self, bag, early, ns):
        """Three states before the controller's first, as a recorder listening to `state` early records
        them (copies of the first state, stepped and stamped back to just before the controller's
        history began, or before the bag's first state if that is earlier): replay leaves them out of
        the controller's history (its first cycle says it held one state of the delay's), so the delay
        comes into force at the recorded cycle and every command is identical (it came 3 cycles early).
        (Stepped back from the bag's first state alone, they took the steps of the controller's first
        states where a loaded recorder had missed those: copies standing for states it used, 3 commands
        differed.)"""
        with rosbag.Bag(bag) as b:
            first = next(m for _, m, _ in b.read_messages(topics=[ns + "/state"]))
            control = next(m for _, m, _ in b.read_messages(topics=[ns + "/control"]))
            start = b.get_start_time()
            held = control.delay_samples + 1 - control.delay_pending  # the states its first cycle held
            begin = min(first.step, control.step - held + 1)  # the controller's history's first step
            self.assertGreaterEqual(begin, 3, "the controller's history began at step %d: no room for 3 earlier states" % begin)
            with rosbag.Bag(early, "w") as out:
                for back in (3, 2, 1):
                    m = copy.deepcopy(first)
                    m.step = begin - back
                    ahead = (first.step - m.step) / 30.0
                    m.header.stamp -= rospy.Duration(ahead)
                    out.write(ns + "/state", m, rospy.Time.from_sec(start - ahead))
                for topic, msg, t in b.read_messages():
                    out.write(topic, msg, t)
        self.replays_identically(early)


    def check_the_controllers_first_states_missing(self, bag, after, ns):
        """The controller's first three states not in the bag (the recorder's `state` subscription came
        after its `control` one: seen on a loaded machine, 5 cycles differed): replay takes them from the
        control messages that used them, and every command is identical."""
        with rosbag.Bag(bag) as b:
            first = next(m for _, m, _ in b.read_messages(topics=[ns + "/control"]))
            with rosbag.Bag(after, "w") as out:
                for topic, msg, t in b.read_messages():
                    if topic == ns + "/state" and msg.step < first.step + 3:
                        continue
                    out.write(topic, msg, t)
        self.assertIn("were taken from the control messages that used them", self.replays_identically(after))


if __name__ == "__main__":
    rospy.init_node("check_replay_realtime")
    rostest.rosrun("aurora_tests", "replay_realtime", ReplayRealtimeTest)
