#!/usr/bin/python3
"""Live delay raise beyond the history; live values refused by the start-up
rules; the link and the predictor changed live; the controller after a
landing."""
import math
import os
import sys
import time
import unittest

import dynamic_reconfigure
import dynamic_reconfigure.client
import rospy
import rostest
from aurora_msgs.msg import Control, DroneState
from rosgraph_msgs.msg import Log
from std_msgs.msg import Empty

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from ros_links import wait_linked  # noqa: E402


class LiveChangesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.controls, cls.states, cls.logs = [], [], []
        rospy.Subscriber("control", Control, cls.controls.append, queue_size=1000)
        rospy.Subscriber("state", DroneState, cls.states.append, queue_size=1000)
        rosout = rospy.Subscriber("/rosout", Log, cls.logs.append, queue_size=1000)
        cls.rosout_linked = wait_linked(rosout, rospy.get_namespace() + "controller")
        cls.land = rospy.Publisher("land", Empty, queue_size=1, latch=True)
        cls.reconfigure = dynamic_reconfigure.client.Client("controller", timeout=30)

    def wait_for(self, predicate, timeout):
        end = time.time() + timeout
        while not predicate() and time.time() < end:
            time.sleep(0.02)
        return predicate()

    def controller_logs(self, text, since=0):
        return [m for m in self.logs[since:] if m.name.endswith("/controller") and text in m.msg]

    def test_1_delay_raised_beyond_the_history_is_said(self):
        self.assertTrue(self.rosout_linked, "/rosout never linked to the controller")
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= 60, 20), "no control messages")
        logs_before = len(self.logs)
        # 1500 samples (50 s): shorter than mission4's 1801 iterations, longer
        # than the history kept after a few seconds.
        self.reconfigure.update_configuration({"delay_samples": 1500})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 30, 5))
        raised = [c for c in self.controls[start:] if c.delay_samples == 1500]
        self.assertGreater(len(raised), 20)
        for c in raised:
            self.assertEqual(c.delay_in_force, 0, "step %d" % c.step)
            self.assertTrue(0 < c.delay_pending < 1501, "step %d: pending %d" % (c.step, c.delay_pending))
        for a, b in zip(raised, raised[1:]):  # one state fewer to wait for per new state
            self.assertEqual(a.delay_pending - b.delay_pending, b.step - a.step)
        self.assertTrue(self.wait_for(lambda: self.controller_logs("delay raised live to 1500", logs_before), 3),
                        "no warning at the change")
        warning = self.controller_logs("delay raised live to 1500", logs_before)[0]
        self.assertEqual(warning.level, Log.WARN)
        self.assertIn("NO delay", warning.msg)
        kept = int(warning.msg.split("only ")[1].split(" states")[0])
        # the history held `kept` states at the change; 1501 are needed
        self.assertIn(1501 - kept - raised[0].delay_pending, (0, 1, 2), warning.msg)

        # back to a delay the history covers: in force at once, and said so
        self.reconfigure.update_configuration({"delay_samples": 10})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 30, 5))
        lowered = [c for c in self.controls[start:] if c.delay_samples == 10]
        self.assertTrue(lowered)
        for c in lowered:
            self.assertEqual((c.delay_in_force, c.delay_pending), (10, 0))
        self.assertTrue(self.wait_for(lambda: self.controller_logs("in force again", logs_before), 3))

    def refused(self, change, text):
        """A live change the start-up rules refuse: the call fails, the node
        says why with the value as given, and nothing changes."""
        logs_before = len(self.logs)
        before = self.controls[-1]
        with self.assertRaises(dynamic_reconfigure.DynamicReconfigureCallbackException, msg=str(change)):
            self.reconfigure.update_configuration(change)
        self.assertTrue(self.wait_for(lambda: self.controller_logs(text, logs_before), 3),
                        "no refusal naming %r for %r" % (text, change))
        self.assertEqual(self.controller_logs(text, logs_before)[0].level, Log.ERROR)
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 10, 5))
        for c in self.controls[start:]:
            self.assertEqual((c.delay_samples, list(c.gains)), (before.delay_samples, list(before.gains)), change)
            self.assertTrue(all(math.isfinite(u) for u in c.command), change)
        return self.controller_logs(text, logs_before)[0].msg

    def test_1b_a_delay_not_shorter_than_the_task_is_refused_live(self):
        # mission4: 1801 steps; 2047 would never take force (limits.h)
        msg = self.refused({"delay_samples": 2047}, "delay_samples = 2047 samples is not shorter")
        self.assertIn("accepted delays up to 1800 samples", msg)
        self.assertEqual(self.reconfigure.get_configuration(timeout=5)["delay_samples"],
                         self.controls[-1].delay_samples, "the server must show the delay kept")

    def test_1c_live_values_meet_the_start_up_rules(self):
        # Each was taken (NaN reached cmd_vel) or silently clamped before.
        self.refused({"kp": float("nan")}, "kp = nan is refused: accepted a gain in [0, 10]")
        self.refused({"kp": -3.0}, "kp = -3 is refused")
        self.refused({"kp": 50.0}, "kp = 50 is refused")
        self.refused({"kd": float("inf")}, "kd = inf is refused")
        self.refused({"delay_samples": -1}, "delay_samples = -1 is refused")
        self.refused({"delay_samples": 2.5}, "delay_samples = 2.5 is refused")
        self.refused({"delay_samples": 5000}, "delay_samples = 5000 is refused")
        self.refused({"k1_x": 0.7}, "k1_x = 0.7 is refused: a gain of the underactuated law, but this node flies")
        # A good change still works, and shows in Control.
        self.reconfigure.update_configuration({"kp": 0.6})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 10, 5))
        self.assertEqual(self.controls[-1].kp, 0.6)

    def test_1d_the_link_changes_live(self):
        # docs/links.md: a lossy uplink and a 3-sample command path, set live,
        # show in Control at once; bad values are refused with the files' rules.
        self.refused({"uplink_loss": 1.0}, "uplink_loss = 1 is refused: accepted a value in [0, 0.99]")
        self.refused({"downlink_delay": 2.5}, "downlink_delay = 2.5 is refused: accepted whole samples")
        self.reconfigure.update_configuration({"uplink_loss": 0.3, "uplink_burst": 2.0, "downlink_delay": 3})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 90, 10))
        later = [c for c in self.controls[start + 30:] if c.law_ran]
        self.assertGreater(later[-1].uplink_losses, 5, "no state packet lost at a 30 % loss")
        self.assertTrue(any(not c.state_arrived for c in later), "every state arrived at a 30 % loss")
        self.assertEqual(min(c.command_age for c in later if c.command_age >= 0), 3)
        config = self.reconfigure.get_configuration(timeout=5)
        self.assertEqual((config["uplink_loss"], config["downlink_delay"]), (0.3, 3.0))
        self.reconfigure.update_configuration({"uplink_loss": 0.0, "uplink_burst": 1.0, "downlink_delay": 0})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 30, 5))
        self.assertEqual(self.controls[-1].command_age, 0)

    def test_1e_the_predictor_switches_live(self):
        # Issue 35 (docs/predictor.md): dynparam predictor resimulate | smith | off; the node's vehicle file is
        # its model; Control says it at once; an unknown form is refused.
        self.refused({"predictor": "kalman"}, "predictor = 'kalman' is refused: accepted 'resimulate', 'smith', 'off'")
        self.assertEqual(self.controls[-1].predictor, "off")
        self.reconfigure.update_configuration({"predictor": "resimulate"})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 30, 5))
        later = [c for c in self.controls[start + 5:] if c.law_ran]
        self.assertTrue(later and all(c.predictor == "resimulate" for c in later))
        self.assertTrue(all(len(c.predicted_state) == 12 and c.prediction_step == c.step for c in later))
        self.assertEqual(self.reconfigure.get_configuration(timeout=5)["predictor"], "resimulate")
        self.reconfigure.update_configuration({"predictor": "off"})
        start = len(self.controls)
        self.assertTrue(self.wait_for(lambda: len(self.controls) >= start + 10, 5))
        self.assertEqual((self.controls[-1].predictor, len(self.controls[-1].predicted_state)), ("off", 0))

    def test_2_a_landed_drone_is_still_a_fresh_source(self):
        self.land.publish(Empty())
        self.assertTrue(self.wait_for(lambda: self.states and self.states[-1].position.z < 0.05, 30),
                        "the sim never landed")
        landed_at = len(self.controls)
        landed_state = len(self.states)
        time.sleep(1.5)  # three times hover_after (0.5 s)
        after = self.controls[landed_at:]
        self.assertGreater(len(after), 30, "the controller stopped publishing after the landing")
        steps = [s.step for s in self.states[landed_state:]]
        self.assertEqual(steps, sorted(set(steps)), "landed states must still be new samples")
        stale = [c.mode for c in after if "no fresh state" in c.mode]
        self.assertEqual(stale, [], "hover on a landed drone whose states still arrive")
        self.assertEqual(self.controller_logs("no fresh state"), [])


if __name__ == "__main__":
    rospy.init_node("check_live_changes")
    rostest.rosrun("aurora_tests", "live_changes", LiveChangesTest)
