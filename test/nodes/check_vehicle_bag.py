#!/usr/bin/python3
"""A recorded flight of another vehicle than the AR.Drone (a Bebop 2, a
Pioneer P3-DX): the bag holds its driver's odometry topic and its states
(a Pioneer's u, omega in DroneState.extra, named by Control); replay gives
every command again (over the flight's link file where it had one), also
when the recorder dropped a state; the report names the vehicle and labels
its own commands."""
import csv
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


class VehicleBagTest(unittest.TestCase):
    def test_record_replay_report(self):
        p = lambda key: rospy.get_param("~" + key)  # noqa: E731
        bag = record_until(p("steps"), p("bag_dir"), p("prefix"))
        ns = rospy.get_namespace().rstrip("/")
        extra = p("extra_state_names")
        with rosbag.Bag(bag) as b:
            topics = b.get_type_and_topic_info().topics
            self.assertIn(ns + "/" + p("odometry"), topics)
            states = [m for _, m, _ in b.read_messages(topics=[ns + "/state"])]
            controls = [m for _, m, _ in b.read_messages(topics=[ns + "/control"])]
        self.assertGreater(len(states), p("steps"))
        self.assertTrue(all(len(s.extra) == len(extra) for s in states))
        last = controls[-1]
        self.assertEqual(last.vehicle, p("vehicle"))
        self.assertEqual(list(last.command_names), p("command_names"))
        self.assertEqual(list(last.extra_state_names), extra)
        if extra:  # the robot moved: its own states are not left at 0
            self.assertGreater(max(abs(v) for s in states for v in s.extra), 0.05)
        replay = rosrun("aurora_control", "replay") + [bag, "--expect-identical"]
        if rospy.has_param("~link_file"):
            replay += ["--link", p("link_file")]
        with tempfile.TemporaryDirectory() as tmp:
            commands = os.path.join(tmp, "commands.csv")
            rc, log = run(replay + ["--out", commands])
            rospy.loginfo(log)
            self.assertEqual(rc, 0, log)
            self.assertIn(" 0 differ, max |dU| = 0 ", log)
            self.check_the_commands_csv(commands, controls)
        self.check_a_dropped_state_is_taken_from_its_control(bag, replay, states, controls)
        drone = self.report_metrics(bag)
        self.assertEqual(drone["vehicle"], p("vehicle"))
        self.assertEqual(drone["command_names"], p("command_names"))
        self.assertTrue(drone["metrics_match_controller"])
        os.remove(bag)

    def check_the_commands_csv(self, path, controls):
        """replay --out's CSV: the vehicle's commands only (a Pioneer's two:
        four columns each side, two of them zeros, looked like commands), the
        recorded ones the bag's, the replayed ones the same (identical)."""
        names = rospy.get_param("~command_names")
        with open(path) as f:
            rows = list(csv.DictReader(f))
        n = len(names)
        self.assertEqual(list(rows[0]), ["step"] + ["recorded_u%d" % i for i in range(1, n + 1)] +
                         ["replayed_u%d" % i for i in range(1, n + 1)] + ["max_abs_diff"])
        recorded = {c.step: c.command[:n] for c in controls}
        compared = [r for r in rows if int(r["step"]) in recorded]
        self.assertGreater(len(compared), 100)
        for r in compared:
            got = [float(r["recorded_u%d" % i]) for i in range(1, n + 1)]
            self.assertEqual(got, list(recorded[int(r["step"])]), r["step"])
            self.assertEqual([float(r["replayed_u%d" % i]) for i in range(1, n + 1)], got, r["step"])
            self.assertEqual(float(r["max_abs_diff"]), 0.0)

    def check_a_dropped_state_is_taken_from_its_control(self, bag, replay, states, controls):
        """A state the recorder dropped (a loaded machine): replay takes it
        from the control message that used it (Control.state_used) and gives
        every command again; with those control messages dropped too it
        cannot, and says from where. A control message the
        recorder dropped (header.seq skips it): replay compares the cycles
        before it, the report the controller's metrics up to it."""
        ns = rospy.get_namespace().rstrip("/")
        # A state some cycle used: on a loaded machine two states can come
        # between two cycles, and the controller never uses the first.
        recorded = set(s.step for s in states)
        used = sorted(set(c.state_used.step for c in controls if c.law_ran) & recorded)
        self.assertTrue(used, "no control cycle used a recorded state")
        dropped = used[len(used) // 2]
        users = [c.step for c in controls if c.state_used.step == dropped]
        lost = sum(1 for c in controls if c.step in users)
        after = min(c.step for c in controls if c.step > min(users) and c.step not in users)
        gap = "%d control messages missing from the bag (the recorder dropped them, first before step %d)" % (
            lost, after)
        # The state alone, the state and its users, its users alone. With
        # both gone the state keeps its place in the history and on the link
        # (the node received it), so the cycles between it and its users, which
        # did not use it, come out identical.
        for drop_state, drop_controls in ((True, ()), (True, users), (False, users)):
            thinned = bag[:-len(".bag")] + "_dropped.bag"
            with rosbag.Bag(bag) as b, rosbag.Bag(thinned, "w") as out:
                for topic, m, t in b.read_messages():
                    if not ((drop_state and topic == ns + "/state" and m.step == dropped)
                            or (topic == ns + "/control" and m.step in drop_controls)):
                        out.write(topic, m, t)
            try:
                rc, log = run([thinned if word == bag else word for word in replay])
                self.assertEqual(rc, 0, log)
                self.assertIn(" 0 differ, max |dU| = 0 ", log)
                if not drop_controls:
                    self.assertIn("state steps missing from the bag (the recorder dropped them, first %d) were taken "
                                  "from the control messages that used them" % dropped, log)
                elif drop_state:
                    self.assertIn("missing from the bag and from its control messages (the recorder dropped them, "
                                  "first %d) kept their places in the history and on the link, the state before each "
                                  "standing in; 0 replayed cycles ran the law on a stand-in\n" % dropped, log)
                else:
                    self.assertIn(gap, log)
                    self.check_the_report_compares_up_to_the_gap(thinned, lost, min(users))
            finally:  # also when a check failed: the next run's bag_dir stays clean
                os.remove(thinned)

    def report_metrics(self, bag):
        """The report's metrics.json of the bag's vehicle; its report.md speaks of the vehicle as it is
        (issue 51: a Pioneer's said its commands were clamped and spoke of a drone hovering)."""
        out = tempfile.mkdtemp(prefix="vehicle_report_")
        rc, log = run(rosrun("aurora", "report") + [bag, "--out", out, "--no-video"])
        self.assertEqual(rc, 0, log)
        with open(os.path.join(out, "metrics.json")) as f:
            metrics = json.load(f)
        drone = metrics["drones"][0] if "drones" in metrics else metrics
        with open(os.path.join(out, "report.md")) as f:
            md = f.read()
        flies = rospy.get_param("~vehicle") != "pioneer3dx"
        self.assertEqual(drone["flies"], flies)
        if not flies:
            self.assertIn("commands saturated by the law", md)
            self.assertNotIn("clamped", md)
            self.assertNotIn("hover", md)
        return drone

    def check_the_report_compares_up_to_the_gap(self, bag, missing, first_missing):
        drone = self.report_metrics(bag)
        self.assertEqual(drone["control_messages_missing"], missing)
        self.assertLess(drone["metrics_compared_up_to_step"], first_missing)
        self.assertTrue(drone["metrics_match_controller"])
        # Over the whole flight the recomputed metrics lack the dropped terms.
        self.assertLess(drone["iae"], drone["controller_iae"])


if __name__ == "__main__":
    rospy.init_node("check_vehicle_bag")
    rostest.rosrun("aurora_tests", "vehicle_bag", VehicleBagTest)
