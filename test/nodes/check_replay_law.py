#!/usr/bin/python3
"""A recorded lockstep flight of any law and task: replay reproduces every
command; the report names the law and measures tracking per lap."""
import json
import os
import re
import sys
import tempfile
import unittest

import rospy
import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402


class ReplayLawTest(unittest.TestCase):
    def test_replay_identical_and_report_per_lap(self):
        bag = record_until(rospy.get_param("~steps"), rospy.get_param("~bag_dir"), rospy.get_param("~prefix"))
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--expect-identical"])
        rospy.loginfo(log)
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        # Another delay gives other commands: the comparison can fail.
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--delay", "1"])
        self.assertNotIn(" 0 differ", log)
        if rospy.get_param("~controller") == "underactuated":
            # A PD gain on an underactuated bag would be ignored: refused.
            rc, log = run(rosrun("aurora_control", "replay") + [bag, "--kp", "0.5"])
            self.assertEqual(rc, 2, log)
            self.assertIn("--kp is a gain of the pd_saturated law, but the bag's controller is underactuated", log)
        # Issue 51 (8): another vehicle's law is named as such (it blamed the sample time), and shipped
        # NAMEs are taken as flight takes them.
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--controller", "pioneer_dynamic"])
        self.assertEqual(rc, 2, log)
        self.assertIn("its law 'pioneer_dynamic' flies the pioneer3dx, but the bag's controller '%s' flew the ardrone2"
                      % rospy.get_param("~controller"), log)
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--controller", rospy.get_param("~controller"),
                       "--link", "ideal", "--expect-identical"])
        self.assertEqual(rc, 0, log)
        out = tempfile.mkdtemp(prefix="aurora_replay_law_")
        rc, log = run(rosrun("aurora", "report") + [bag, "--out", out, "--no-video"])
        self.assertEqual(rc, 0, log)
        m = json.load(open(os.path.join(out, "metrics.json")))["drones"][0]
        self.assertEqual(m["controller"], rospy.get_param("~controller"))
        self.assertEqual(sorted(m["gains"]), sorted(rospy.get_param("~gain_names")))
        self.assertEqual(m["task_kind"], "trajectory")
        self.assertTrue(m["metrics_match_controller"], m)
        laps = m["segments"]
        self.assertEqual([s["lap"] for s in laps], list(range(1, len(laps) + 1)))
        self.assertGreaterEqual(len(laps), 2)
        for s in laps:
            self.assertGreater(s["max_tracking_error_m"], s["rms_tracking_error_m"] - 1e-12)
        # The second lap, past the start transient, is tracked closely.
        self.assertLess(laps[1]["rms_tracking_error_m"], 0.2)
        self.flight_tool_agrees(laps)
        png = os.path.join(out, "ardrone1_tracking.png")
        self.assertGreater(os.path.getsize(png), 10000)
        os.remove(bag)

    def flight_tool_agrees(self, laps):
        """The flight tool flies the same lockstep flight offline: its tracking
        error per lap is the report's (one definition, docs/controllers.md)."""
        config = rospy.get_param("~config_dir")
        rc, log = run(rosrun("aurora_control", "flight") + [
                       "--controller", os.path.join(config, "controllers", rospy.get_param("~controller") + ".yaml"),
                       "--task", os.path.join(config, "tasks", rospy.get_param("~task") + ".yaml"),
                       "--delay", str(rospy.get_param("~delay"))])
        self.assertEqual(rc, 0, log)
        flown = re.findall(r"lap (\d+): RMS tracking error ([0-9.]+) m, max ([0-9.]+) m", log)
        self.assertEqual(len(flown), len(laps), log)
        self.assertIn(" %d steps in " % rospy.get_param("~task_steps"), log)
        for (lap, rms, peak), s in zip(flown, laps):
            self.assertEqual(int(lap), s["lap"])
            self.assertEqual(rms, "%.4f" % s["rms_tracking_error_m"], log)
            self.assertEqual(peak, "%.4f" % s["max_tracking_error_m"], log)


if __name__ == "__main__":
    rospy.init_node("check_replay_law")
    rostest.rosrun("aurora_tests", "replay_law", ReplayLawTest)
