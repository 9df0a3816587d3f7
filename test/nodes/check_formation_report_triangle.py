#!/usr/bin/python3
"""report on a bag of AuRoRA's triangle of three AR.Drones (formation.launch
formation:=triangle_ardrones record:=true, lockstep, each drone its delay):
its nine variables, the RMS errors after 10 s as the triangle's layer takes
them (Qd - Q with the shape's wraps: psi follows the carrousel past -pi
about 25 s in, while Q's psi stays within [-pi, pi]), the smallest
distance, each drone's tracking, the figures and the video."""
import json
import math
import os
import sys
import unittest

import rospy
import rostest

import aurora
from aurora import _core

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, report_on  # noqa: E402

VARIABLES = ["xF", "yF", "zF", "p", "q", "beta", "phi", "theta", "psi"]


class TriangleReportTest(unittest.TestCase):
    def test_report_of_a_triangle_bag(self):
        bag = record_until(900, rospy.get_param("~bag_dir"), rospy.get_param("~prefix"),
                           state="/ardrone3/state", recorder="/recorder")
        out, rc, said = report_on(bag)
        self.assertEqual(rc, 0, said)
        m = json.load(open(os.path.join(out, "metrics.json")))["formation"]
        self.assertEqual(m["variables"], VARIABLES)
        self.assertEqual(m["first_tick"], 0)
        self.assertGreaterEqual(m["last_tick"], 900)
        self.assertEqual(sorted(m["drones"]), ["ardrone1", "ardrone2", "ardrone3"])
        frame, _ = aurora.read_formation_bag(bag)
        ts = rospy.get_param("/ardrone1/vehicle/sample_time")
        after = frame[frame.step * ts >= 10.0]
        self.assertEqual(len(after) + len(frame[frame.step * ts < 10.0]), m["ticks"])
        # The scenario crosses the wrap: Q's psi and Qd's part by 2 pi after it.
        raw = (after["Qd_psi"] - after["Q_psi"]).abs().max()
        self.assertGreater(raw, math.pi, "the recorded flight never took psi past -pi")
        # The report's RMS: of the shape's own Q~ (the C++ shape's error), tick by tick.
        sums, n = [0.0] * 9, 0
        for _, row in after.iterrows():
            X = [row["d%d_%s" % (d, a)] for d in (1, 2, 3) for a in "xyz"]
            e = _core.formation_error("triangle", X, [row["Qd_" + v] for v in VARIABLES],
                                      [row["Q_" + v] for v in VARIABLES])
            for i in range(9):
                sums[i] += e[i] * e[i]
            n += 1
        got = m["rms_after_settle"]
        for i, v in enumerate(VARIABLES[3:], start=3):
            key = "%s_%s" % (v, "m" if v in ("p", "q") else "rad")
            self.assertAlmostEqual(got[key], math.sqrt(sums[i] / n), delta=1e-12, msg=key)
        # A drone's lag, not a wrap: psi within a few tenths of a radian (2 pi off with the raw difference).
        self.assertLess(got["psi_rad"], 0.5)
        self.assertLess(got["position_xy_m"], 0.5)
        self.assertGreater(m["smallest_distance_m"], 0.6)
        for d in m["drones"].values():
            self.assertGreater(d["rms_tracking_error_m"], 0.0)
            self.assertLess(d["max_tracking_error_m"], 1.5)
        for f in ("formation_shape.png", "formation_position.png", "formation_errors.png", "formation_top_view.png",
                  "formation_flight.mp4"):
            self.assertGreater(os.path.getsize(os.path.join(out, f)), 10000, f)
        self.assertIn("## Formation", open(os.path.join(out, "report.md")).read())

    def test_formation_error_refuses_what_it_cannot_take(self):
        with self.assertRaises(ValueError) as e:
            _core.formation_error("hexagon", [0.0] * 9, [0.0] * 9, [0.0] * 9)
        self.assertIn("shape 'hexagon' is unknown", str(e.exception))
        with self.assertRaises(ValueError) as e:
            _core.formation_error("triangle", [0.0] * 6, [0.0] * 9, [0.0] * 9)
        self.assertIn("must hold 9 values", str(e.exception))
        # The triangle's psi wrapped into [-pi, pi]; the line wraps nothing.
        e = _core.formation_error("triangle", [1, 0, 0.75, -1, 0, 0.75, 0, 1, 0.75], [0] * 8 + [-3.5], [0] * 8 + [3.0])
        self.assertAlmostEqual(e[8], -6.5 + 2 * math.pi, delta=1e-12)
        self.assertEqual(_core.formation_error("line", [0] * 6, [0] * 5 + [4.0], [0] * 6)[5], 4.0)


if __name__ == "__main__":
    rospy.init_node("check_formation_report_triangle")
    rostest.rosrun("aurora_tests", "formation_report_triangle", TriangleReportTest)
