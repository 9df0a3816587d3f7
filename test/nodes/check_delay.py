#!/usr/bin/python3
"""The delay in force equals the configured one, sample by sample."""
import threading
import time
import unittest

import rospy
import rostest
from aurora_msgs.msg import Control, DroneState


class DelayTest(unittest.TestCase):
    def test_state_used_is_exactly_d_samples_old(self):
        d = rospy.get_param("~expected_delay")
        ts = rospy.get_param("vehicle/sample_time")
        n = 240
        stamps = {}
        controls = []
        done = threading.Event()

        def on_state(msg):
            stamps[msg.step] = msg.header.stamp

        def on_control(msg):
            controls.append(msg)
            if msg.step >= n:
                done.set()

        rospy.Subscriber("state", DroneState, on_state, queue_size=1000)
        rospy.Subscriber("control", Control, on_control, queue_size=1000)
        self.assertTrue(done.wait(60.0), "no control message for step %d within 60 s" % n)
        # state and control arrive on two connections, each with its own
        # thread: the control of step k can be handled before the state of
        # step k. Wait until every state up to the last control's step is in.
        # Controls go on arriving: check those taken now, whose states the
        # wait below covers (one of a later step failed with KeyError once).
        taken = list(controls)
        last = max(c.step for c in taken)
        deadline = time.time() + 10.0
        while any(k not in stamps for k in range(last + 1)) and time.time() < deadline:
            time.sleep(0.01)
        missing = [k for k in range(last + 1) if k not in stamps]
        self.assertEqual(missing, [], "states never received (the sim published every step)")
        by_step = {}
        for c in taken:
            by_step.setdefault(c.step, c)  # a re-sent state is answered again: keep the first
        self.assertEqual(sorted(by_step), list(range(0, max(by_step) + 1)), "control steps are not contiguous")
        for step, c in sorted(by_step.items()):
            self.assertEqual(c.delay_samples, d)
            self.assertAlmostEqual(c.delay_seconds, d * ts, places=12)
            k = step + 1  # the spec's 1-based iteration
            expected_step = step - d if k > d else step
            self.assertEqual(c.state_used.step, expected_step, "control of step %d used step %d" % (step, c.state_used.step))
            self.assertEqual(c.delay_in_force, d if k > d else 0)
            self.assertEqual(c.state_used.header.stamp, stamps[expected_step],
                             "control of step %d: state_used stamp differs from the published state" % step)
            lag = (c.header.stamp - c.state_used.header.stamp).to_sec()
            self.assertAlmostEqual(lag, (step - expected_step) * ts, delta=2e-9)
        rospy.loginfo("checked %d control messages, delay %d samples", len(by_step), d)


if __name__ == "__main__":
    rospy.init_node("check_delay")
    rostest.rosrun("aurora_tests", "delay_semantics", DelayTest)
