#!/usr/bin/python3
"""NaN/Inf commands are rejected (hover, logged once per burst); big ones are clamped."""
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from aurora_msgs.msg import DroneState
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Log

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from ros_links import wait_linked  # noqa: E402


class BadInputTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.states = []
        cls.warnings = []
        cls.summaries = []
        cls.ends = []
        rospy.Subscriber("state", DroneState, lambda m: cls.states.append(m), queue_size=1000)
        rosout = rospy.Subscriber("/rosout", Log, cls.on_log, queue_size=1000)
        cls.pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        # The warnings are counted from /rosout: its link to the sim must be up
        # before the first bad command, or the one warning is lost.
        cls.rosout_linked = wait_linked(rosout, rospy.get_namespace() + "vehicle_sim")
        deadline = time.time() + 20
        # Two seconds of hover first: the rotors start at rest (spec initial state).
        while (len(cls.states) < 60 or cls.pub.get_num_connections() == 0) and time.time() < deadline:
            time.sleep(0.05)

    @classmethod
    def on_log(cls, msg):
        # Burst starts (the one warning), summaries while a burst lasts, ends.
        if "rejected cmd_vel with NaN/Inf" in msg.msg and msg.level >= Log.WARN:
            cls.warnings.append(msg)
        elif "still rejecting NaN/Inf" in msg.msg:
            cls.summaries.append(msg)
        elif "the burst ended after" in msg.msg:
            cls.ends.append(msg)

    def send_for(self, twist, seconds):
        end = time.time() + seconds
        while time.time() < end and not rospy.is_shutdown():
            self.pub.publish(twist)
            time.sleep(1.0 / 30.0)

    def wait_for(self, predicate, timeout):
        end = time.time() + timeout
        while not predicate() and time.time() < end:
            time.sleep(0.02)
        return predicate()

    def test_1_nan_and_inf_never_reach_the_model(self):
        self.assertTrue(self.states, "no state from the sim")
        self.assertTrue(self.rosout_linked, "/rosout never linked to the sim")
        start = len(self.states)
        for bad in (float("nan"), float("inf"), -float("inf")):
            t = Twist()
            t.linear.x = bad
            t.linear.z = 0.5
            t.angular.z = bad
            self.send_for(t, 0.5)  # one burst of about 15 messages
        time.sleep(0.5)
        flown = self.states[start:]
        self.assertGreater(len(flown), 30)
        for s in flown:
            values = [s.position.x, s.position.y, s.position.z, s.velocity.x, s.velocity.y, s.velocity.z,
                      s.attitude.x, s.attitude.y, s.attitude.z]
            self.assertTrue(all(math.isfinite(v) for v in values), "non-finite state %s" % values)
            # hovering: no horizontal motion, no climb at 0.5 (the finite part of the bad command is dropped too)
            self.assertLess(abs(s.velocity.x) + abs(s.velocity.y), 1e-9)
            self.assertLess(abs(s.velocity.z), 0.05)
        self.assertEqual(len(self.warnings), 1,
                         "expected one warning for the burst, got %d" % len(self.warnings))

    def test_2_a_new_burst_warns_again(self):
        # A burst ends after nan_burst/quiet_period (1 s) without a NaN.
        self.send_for(Twist(), 1.5)
        self.assertTrue(self.wait_for(lambda: len(self.ends) >= 1, 2.0), "the first burst never ended")
        t = Twist()
        t.linear.y = float("nan")
        self.send_for(t, 0.3)
        self.assertTrue(self.wait_for(lambda: len(self.warnings) >= 2, 5.0), "no warning for the new burst")
        time.sleep(0.3)  # nothing more may come
        self.assertEqual(len(self.warnings), 2)

    def test_2b_valid_commands_in_between_do_not_end_a_burst(self):
        # A NaN publisher beside a controller still publishing valid commands:
        # one warning, summaries every nan_burst/summary_period (1 s here),
        # one end line once the NaNs stop (the old rule logged ~100 of each).
        self.send_for(Twist(), 1.5)
        warned, summarized = len(self.warnings), len(self.summaries)
        ended = len(self.ends)
        bad = Twist()
        bad.angular.z = float("nan")
        end = time.time() + 3.4
        while time.time() < end:
            self.pub.publish(bad)
            time.sleep(1.0 / 60.0)
            self.pub.publish(Twist())
            time.sleep(1.0 / 60.0)
        self.send_for(Twist(), 1.5)
        self.assertTrue(self.wait_for(lambda: len(self.ends) > ended, 2.0), "the burst never ended")
        self.assertEqual(len(self.warnings) - warned, 1, "expected one warning for the whole burst")
        summaries = self.summaries[summarized:]
        # one per second of NaNs (3.4 s), maybe one more in the quiet second after
        self.assertIn(len(summaries), (3, 4), [m.msg for m in summaries])
        end_line = self.ends[-1].msg
        rejected = int(end_line.split("after ")[1].split(" rejected")[0])
        self.assertGreater(rejected, 60, end_line)  # ~100 NaN commands in 3.4 s, all counted
        self.assertLess(rejected, 120, end_line)

    def test_3_out_of_range_is_clamped(self):
        start = len(self.states)
        t = Twist()
        t.linear.z = 5.0  # 5 m/s asked; the drivers clamp to 1 (= 1 m/s)
        self.send_for(t, 2.5)
        self.send_for(Twist(), 0.2)
        climb = [s.velocity.z for s in self.states[start:]]
        self.assertGreater(max(climb), 0.8, "the drone did not climb")
        self.assertLess(max(climb), 1.05, "climb rate above the clamped 1 m/s: command not clamped")

    def test_4_hovers_when_commands_stop(self):
        # cmd_timeout 0.2 s (bebop_autonomy's): a climb command that stops is
        # not held forever; the sim falls back to hover.
        t = Twist()
        t.linear.z = 1.0
        self.send_for(t, 0.6)
        stopped = len(self.states)
        self.assertGreater(self.states[-1].velocity.z, 0.5, "the climb command had no effect")
        time.sleep(1.0)
        later = self.states[stopped + 24:]  # from 0.8 s after the last command
        self.assertTrue(later)
        self.assertLess(max(abs(s.velocity.z) for s in later), 0.1, "still climbing: no hover after cmd_timeout")


if __name__ == "__main__":
    rospy.init_node("check_bad_input")
    rostest.rosrun("aurora_tests", "bad_cmd_vel", BadInputTest)
