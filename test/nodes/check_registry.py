#!/usr/bin/python3
"""Issue 53 (6): the registry test's vehicle and law (registry/test_quad/),
known only to a test build of the nodes, fly the mission in lockstep with
their delay, are recorded as any vehicle is, and replay of the bag (the test
build's) reproduces every command; the shipped replay refuses the law by
name. The law's gains, declared by its header alone, are live settings of
the test build's Controller.cfg rows (controller_live_settings built with the
test's lists), and of no shipped build's."""
import math
import os
import sys
import tempfile
import unittest

import yaml

import rosbag
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402


class RegistryTest(unittest.TestCase):
    def test_the_test_vehicle_flies_is_recorded_and_replays(self):
        ts = 1.0 / 30.0
        end_times = rospy.get_param("~task/end_times")
        waypoints = rospy.get_param("~task/waypoints")
        bag = record_until(int(round(end_times[-1] / ts)), rospy.get_param("~bag_dir"), rospy.get_param("~prefix"))
        ns = rospy.get_namespace()
        with rosbag.Bag(bag) as b:
            states = [m for _, m, _ in b.read_messages(topics=[ns + "state"])]
            controls = [m for _, m, _ in b.read_messages(topics=[ns + "control"])]
        self.assertGreater(len(controls), 100)
        last = controls[-1]
        self.assertEqual(last.vehicle, "test_quad")
        self.assertEqual(last.controller, "test_quad_pd")
        self.assertEqual(list(last.gain_names), ["k_position", "k_heading"])
        self.assertEqual(list(last.gains), [1.5, 1.0])
        self.assertEqual(list(last.command_names), ["u_x [-1, 1]", "u_y [-1, 1]", "u_z [-1, 1]", "u_yaw [-1, 1]"])
        self.assertEqual(last.sample_time, ts)
        delay = rospy.get_param("~delay")
        self.assertEqual(last.delay_samples, delay)
        self.assertEqual(last.delay_in_force, delay)
        self.assertEqual(last.step - last.state_used.step, delay)
        self.check_waypoints(states, end_times, waypoints, ts)
        self.check_replay(bag)
        os.remove(bag)

    def check_waypoints(self, states, end_times, waypoints, ts):
        best = [float("inf")] * len(waypoints)
        for m in states:
            i = next((k for k, end in enumerate(end_times) if m.step * ts <= end), None)
            if i is not None:
                p, wp = m.position, waypoints[i]
                best[i] = min(best[i], math.sqrt((p.x - wp[0]) ** 2 + (p.y - wp[1]) ** 2 + (p.z - wp[2]) ** 2))
        tol = rospy.get_param("~tolerance")
        for i, err in enumerate(best):
            rospy.loginfo("waypoint %d: closest approach %.4f m", i + 1, err)
            self.assertLess(err, tol, "waypoint %d %s: closest %.4f m" % (i + 1, waypoints[i], err))

    def check_replay(self, bag):
        vehicle = ["--vehicle", rospy.get_param("~vehicle_file")]
        rc, log = run(rosrun("aurora_tests", "registry_replay") + [bag, "--expect-identical"] + vehicle)
        rospy.loginfo(log)
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        # Another delay gives other commands: the comparison can fail.
        rc, log = run(rosrun("aurora_tests", "registry_replay") + [bag, "--delay", "1"] + vehicle)
        self.assertNotIn(" 0 differ", log)
        # The shipped replay does not know the law: refused by its name.
        rc, log = run(rosrun("aurora_control", "replay") + [bag])
        self.assertEqual(rc, 2, log)
        self.assertIn("test_quad_pd", log)

    def live_settings(self, package, tool):
        """The rows with a live name a build's Controller.cfg is generated from, by name."""
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "live_settings.yaml")
            rc, log = run(rosrun(package, tool) + [path])
            self.assertEqual(rc, 0, log)
            with open(path) as f:
                return {s["name"]: s for s in yaml.safe_load(f)}

    def test_the_test_laws_gains_are_live_settings(self):
        test_build = self.live_settings("aurora_tests", "registry_live_settings")
        shipped = self.live_settings("aurora_control", "controller_live_settings")
        for name, preset in (("k_position", 1.5), ("k_heading", 1.0)):
            row = test_build[name]
            self.assertEqual((row["type"], row["default"], row["min"], row["max"]), ("double", preset, 0.0, 20.0))
            self.assertEqual(row["description"], "test_quad_pd law: gain " + name)
            self.assertNotIn(name, shipped)
        # Every shipped setting is the test build's too, alike (its laws come first, then the table).
        for name, row in shipped.items():
            self.assertEqual(test_build[name], row)


if __name__ == "__main__":
    rospy.init_node("check_registry")
    rostest.rosrun("aurora_tests", "registry_lockstep", RegistryTest)
