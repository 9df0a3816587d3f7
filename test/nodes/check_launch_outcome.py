#!/usr/bin/python3
"""aurora_launch's exit status and wording for a normal end and a failed node."""
import os
import subprocess
import sys
import tempfile
import time
import unittest

import rosgraph

import rospy
import rostest

# The shared helpers sit beside this script (catkin's relay runs it with
# __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from ros_links import free_port  # noqa: E402
from tools import rosrun  # noqa: E402


def aurora_launch(*launch_args, port=None, mode="lockstep", launch="sim.launch", package="aurora_bringup"):
    # Its own master on a free port: the rostest's master is left alone.
    cmd = rosrun("aurora_bringup", "aurora_launch") + ["-p", str(port or free_port()), package,
           launch, "mode:=" + mode, "sim_output:=log"] + list(launch_args)
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=90,
                          env=dict(os.environ), universal_newlines=True)
    return done.returncode, done.stdout


class LaunchOutcomeTest(unittest.TestCase):
    def test_normal_end_is_quiet_and_zero(self):
        rc, out = aurora_launch("stop_after:=3")
        self.assertEqual(rc, 0, out)
        self.assertNotIn("REQUIRED process", out)
        self.assertNotIn("FAILED", out)
        self.assertIn("/ardrone1/vehicle_sim finished normally", out)

    def test_failed_node_is_non_zero_and_named(self):
        rc, out = aurora_launch("stop_after:=3", "delay:=99999")
        self.assertEqual(rc, 1, out)
        self.assertIn("node /ardrone1/controller FAILED with exit status", out)
        self.assertIn("delay/samples' = 99999 is refused: accepted integer samples in [0, 2047]", out)

    def test_a_master_left_running_keeps_no_parameters_of_the_last_launch(self):
        # The ordinary way to work: one roscore, several launches. Each must
        # start from its own parameters: another law (the PD gains would be
        # unknown keys), another task kind (waypoint keys), a delay in samples
        # after one in seconds, and realtime after lockstep (/use_sim_time
        # stayed true: nobody publishes /clock, no cmd_vel, stop_after never).
        port = free_port()
        env = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % port)
        master = subprocess.Popen(["roscore", "-p", str(port)], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL, env=env)
        try:
            # The master is up (it has a run_id) before the first launch, as
            # a roscore a user keeps open would be.
            deadline = time.time() + 60
            while time.time() < deadline:
                try:
                    rosgraph.Master("/check", master_uri=env["ROS_MASTER_URI"]).getParam("/run_id")
                    break
                except Exception:
                    time.sleep(0.2)
            rc, out = aurora_launch("stop_after:=2", "delay_seconds:=0.2", port=port)
            self.assertEqual(rc, 0, out)
            rc, out = aurora_launch("stop_after:=2", "controller:=underactuated", "task:=circle", "delay:=3",
                                    port=port, mode="realtime")
            self.assertEqual(rc, 0, out)
            self.assertIn("/ardrone1/vehicle_sim finished normally", out)
        finally:
            master.terminate()
            master.wait(timeout=30)

    def test_a_launch_displaced_by_a_second_one_is_not_complete(self):
        """Issue 31: the first launch's sim was replaced by the second's (same
        node names on one master) and it said "finished normally", rc 0."""
        port = free_port()
        env = dict(os.environ, ROS_MASTER_URI="http://localhost:%d" % port)
        cmd = rosrun("aurora_bringup", "aurora_launch") + ["-p", str(port), "aurora_bringup", "sim.launch",
               "mode:=realtime", "sim_output:=screen", "stop_after:=60"]
        first = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                                 universal_newlines=True)
        try:
            master = rosgraph.Master("/check", master_uri=env["ROS_MASTER_URI"])
            deadline = time.time() + 60
            while time.time() < deadline:
                try:
                    master.lookupNode("/ardrone1/vehicle_sim")
                    break
                except Exception:
                    time.sleep(0.2)
            rc, second = aurora_launch("stop_after:=2", port=port, mode="realtime")
            out = first.communicate(timeout=60)[0]
        finally:
            if first.poll() is None:
                first.kill()
        self.assertEqual(rc, 0, second)  # the second run is complete
        self.assertNotEqual(first.returncode, 0, out)
        self.assertNotIn("finished normally", out)
        self.assertIn("shut down from outside before its run ended", out)

    def test_two_sims_owning_the_clock_are_refused(self):
        """Two lockstep sims publishing /clock set every node's time back and
        forth (a recorder stopped writing at its first steps: the registry
        formation test's flake). Refused, the other owner named."""
        rc, out = aurora_launch(package="aurora_tests", launch="two_clock_owners.launch")
        self.assertEqual(rc, 1, out)
        self.assertRegex(out, r"parameter '/drone[12]/sim/publish_clock' = true, but /drone[12]/sim publishes "
                              r"/clock too: in lockstep one sim owns the clock")

    def test_a_delay_beside_a_link_replaces_its_uplink_delay(self):
        """Issue 31: link:=wifi_congested delay:=3 refused to start; flight
        took the delay. One rule: the delay given replaces the link's."""
        rc, out = aurora_launch("stop_after:=1", "link:=wifi_congested", "delay:=3")
        self.assertEqual(rc, 0, out)
        self.assertIn("delay 3 samples (given; replaces the link's uplink delay 2)", out)
        self.assertIn("link wifi_congested (uplink delay 2", out)
        rc, out = aurora_launch("stop_after:=1", "link:=wifi_congested")
        self.assertEqual(rc, 0, out)
        self.assertIn("delay 2 samples (the link's uplink delay)", out)

    def test_file_arguments_take_a_path_and_numbers_are_named(self):
        config = subprocess.run(["rospack", "find", "aurora_config"], stdout=subprocess.PIPE,
                                universal_newlines=True).stdout.strip()
        rc, out = aurora_launch("stop_after:=1", "link:=" + config + "/links/wifi_lab.yaml")
        self.assertEqual(rc, 0, out)
        self.assertIn("delay 1 samples (the link's uplink delay)", out)
        for launch, arg in (("sim.launch", "delay:=abc"), ("sim.launch", "delay:=2.5"),
                            ("formation.launch", "delay_1:=abc"), ("formation.launch", "delay_2:=2.5")):
            rc, out = aurora_launch("stop_after:=1", arg, launch=launch)
            self.assertEqual(rc, 2, out)
            self.assertIn("%s is not whole samples" % arg, out)
            self.assertNotIn("invalid literal", out)

    def test_a_key_given_twice_is_refused(self):
        """Issue 31: roslaunch kept the last of a duplicated key, flight the first."""
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
            f.write("kp: 0.4\nkd: 0.8\nkp: 0.6\n")
        try:
            rc, out = aurora_launch("stop_after:=1", "overrides:=" + f.name)
        finally:
            os.remove(f.name)
        self.assertEqual(rc, 1, out)
        self.assertIn("'kp' is given twice, on lines 1 and 3", out)

    def test_a_bad_boolean_argument_is_one_line(self):
        rc, out = aurora_launch("stop_after:=3", "record:=maybe")
        self.assertEqual(rc, 2, out)
        self.assertNotIn("Traceback", out)
        self.assertIn("record:=maybe is not a boolean: use record:=true or record:=false", out)
        self.assertNotIn("Arg xml is", out)  # the reason alone, not roslaunch's XML dump

    def test_a_namespace_that_is_no_ros_name_is_one_line(self):
        rc, out = aurora_launch("stop_after:=3", "ns:=my drone")
        self.assertNotEqual(rc, 0, out)
        self.assertNotIn("terminate called", out)
        self.assertNotIn("Traceback", out)
        self.assertIn("Namespace [/my drone] is invalid", out)
        self.assertIn("(ns:=my_drone)", out)


if __name__ == "__main__":
    rospy.init_node("check_launch_outcome")
    rostest.rosrun("aurora_tests", "launch_outcome", LaunchOutcomeTest)
