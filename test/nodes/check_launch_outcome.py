#!/usr/bin/python3
"""aurora_launch's exit status and wording for a normal end and a failed node."""
import os
import subprocess
import sys
import unittest

import rospy
import rostest

# The shared helpers sit beside this script (catkin's relay runs it with
# __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from ros_links import free_port  # noqa: E402


def aurora_launch(*launch_args):
    # Its own master on a free port: the rostest's master is left alone.
    cmd = ["rosrun", "aurora_bringup", "aurora_launch", "-p", str(free_port()), "aurora_bringup",
           "sim.launch", "mode:=lockstep", "sim_output:=log"] + list(launch_args)
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=90,
                          env=dict(os.environ), universal_newlines=True)
    return done.returncode, done.stdout


class LaunchOutcomeTest(unittest.TestCase):
    def test_normal_end_is_quiet_and_zero(self):
        rc, out = aurora_launch("stop_after:=3")
        self.assertEqual(rc, 0, out)
        self.assertNotIn("REQUIRED process", out)
        self.assertNotIn("FAILED", out)
        self.assertIn("/ardrone1/ardrone_sim finished normally", out)

    def test_failed_node_is_non_zero_and_named(self):
        rc, out = aurora_launch("stop_after:=3", "delay:=99999")
        self.assertEqual(rc, 1, out)
        self.assertIn("node /ardrone1/controller FAILED with exit status", out)
        self.assertIn("delay/samples' = 99999 is invalid", out)


if __name__ == "__main__":
    rospy.init_node("check_launch_outcome")
    rostest.rosrun("aurora_tests", "launch_outcome", LaunchOutcomeTest)
