#!/usr/bin/python3
"""A flight with the state predictor (docs/predictor.md), recorded: every
Control says the predictor and the step it predicted, and with the nominal
model as the simulated vehicle each predicted state is the state that
later arrives for that step, exactly; the report measures that error (0)
and draws it; replay follows the predictor the bag says the node ran and
gives every command again (and not with another model)."""
import json
import os
import sys
import tempfile
import unittest

import rosbag
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402


class PredictorBagTest(unittest.TestCase):
    def test_record_report_replay(self):
        p = lambda key: rospy.get_param("~" + key)  # noqa: E731
        bag = record_until(p("steps"), p("bag_dir"), p("prefix"))
        ns = rospy.get_namespace().rstrip("/")
        with rosbag.Bag(bag) as b:
            states = {m.step: m for _, m, _ in b.read_messages(topics=[ns + "/state"])}
            controls = [m for _, m, _ in b.read_messages(topics=[ns + "/control"])]
        flown = [c for c in controls if c.law_ran]
        self.assertGreater(len(flown), p("steps") - 5)
        delay = p("delay")
        checked = 0
        for c in flown:
            self.assertEqual(c.predictor, "resimulate")
            self.assertEqual(c.prediction_step, c.step, "no command delay: it predicts the newest step")
            # It starts from the newest state received: the delay rule sends the current one until `delay`
            # are kept, then the one `delay` old, older at first than the newest of the start.
            newest = c.step if c.step < delay else max(delay - 1, c.step - delay)
            self.assertEqual(c.prediction_horizon, c.step - newest, c.step)
            self.assertEqual(len(c.predicted_state), 12)
            s = states.get(c.prediction_step)
            if s is not None:
                arrived = (s.position.x, s.position.y, s.position.z, s.velocity.x, s.velocity.y, s.velocity.z)
                self.assertEqual(tuple(c.predicted_state[i] for i in (0, 1, 2, 6, 7, 8)), arrived, c.step)
                checked += 1
        self.assertGreater(checked, p("steps") - 5)
        # Not vacuous: the law's state is the prediction, not the delayed one.
        late = [c for c in flown if c.step > delay + 30]
        self.assertTrue(any(c.predicted_state[0] != c.state_used.position.x for c in late))
        out = tempfile.mkdtemp(prefix="predictor_report_")
        rc, log = run(rosrun("aurora", "report") + [bag, "--out", out, "--no-video"])
        self.assertEqual(rc, 0, log)
        with open(os.path.join(out, "metrics.json")) as f:
            drone = json.load(f)["drones"][0]
        self.assertEqual(drone["predictor"]["form"], "resimulate")
        self.assertEqual(drone["predictor"]["rms_prediction_error_m"], 0.0)
        self.assertEqual(drone["predictor"]["max_prediction_horizon_samples"], delay)
        self.assertGreater(drone["predictor"]["predictions_checked"], p("steps") - 5)
        self.assertTrue(os.path.exists(os.path.join(out, ns.strip("/") + "_prediction.png")))
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--expect-identical"])
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        # Not vacuous: with another model the predictions, and so the commands, differ.
        heavy = os.path.join(out, "heavy.yaml")
        with open(os.path.join(p("config_dir"), "vehicles", "ardrone2.yaml")) as f:
            text = f.read()
        with open(heavy, "w") as f:
            f.write(text.replace("mass: 0.429 ", "mass: 0.5 "))
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--predictor-model", heavy, "--expect-identical"])
        self.assertEqual(rc, 1, log)
        os.remove(bag)


if __name__ == "__main__":
    rospy.init_node("check_predictor_bag")
    rostest.rosrun("aurora_tests", "predictor_bag", PredictorBagTest, sys.argv)
