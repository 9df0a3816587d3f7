#!/usr/bin/python3
"""The report's settling time: an oscillation that ends its segment in a
trough is not settled (issue: settling of an oscillation); a response that
stays in its band for the hold time is, from the time it entered."""
import math
import os
import unittest

import rostest

from aurora import report


def segment(errors, ts=1.0 / 30.0):
    """One waypoint segment, 1 m step along x, with the given error series."""
    n = len(errors)
    return {"t": [k * ts for k in range(n)], "err": list(errors), "wp": [0] * n,
            "xd": [1.0] * n, "yd": [0.0] * n, "zd": [1.0] * n,
            "x": [1.0 - e for e in errors], "y": [0.0] * n, "z": [1.0] * n, "in_task": [True] * n}


class SettlingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.report = report

    def test_oscillation_ending_in_a_trough_is_not_settled(self):
        # The demo's waypoint 4: swinging between 0.015 and 0.151 m (band
        # 0.05 m) with a 2 s period until the segment ends, in a trough.
        n = 15 * 30
        errs = [0.083 - 0.068 * math.cos(2 * math.pi * (k / 30.0) / 2.0) for k in range(n)]
        errs[-1] = 0.015
        s = self.report.segment_metrics(segment(errs))[0]
        self.assertIsNone(s["settling_time_s"], s)
        self.assertTrue(s["still_oscillating"])
        self.assertGreater(s["final_swing_m"], 0.1)

    def test_damped_response_settles_when_it_enters_its_band(self):
        errs = [math.exp(-k / 30.0) for k in range(15 * 30)]  # 1 m, time constant 1 s
        s = self.report.segment_metrics(segment(errs))[0]
        # exp(-t) <= 0.05 from t = ln 20 = 2.996 s on.
        self.assertAlmostEqual(s["settling_time_s"], math.ceil(30 * math.log(20)) / 30.0, places=9)
        self.assertFalse(s["still_oscillating"])
        self.assertEqual(s["settling_hold_s"], 1.0)

    def test_entering_the_band_just_before_the_end_is_not_enough(self):
        errs = [0.5] * (10 * 30) + [0.01] * 15  # 0.5 s inside: shorter than the hold
        s = self.report.segment_metrics(segment(errs))[0]
        self.assertIsNone(s["settling_time_s"])


    def test_steps_after_the_task_are_in_no_segment(self):
        # The bag goes on after the task (the reference holds its end): the
        # segments cover the task's steps 0..N only, as the flight tool's.
        seg = segment([0.5] * 30 + [0.0] * 30)
        seg["in_task"] = [True] * 30 + [False] * 30
        s = self.report.segment_metrics(seg)[0]
        self.assertEqual(s["rms_tracking_error_m"], 0.5)


def mission_series():
    """Two waypoint segments of 2 s each, with made-up but consistent data."""
    n, ts = 120, 1.0 / 30.0
    series = {k: [0.0] * n for k in ("x", "y", "z", "roll", "pitch", "yaw", "vx", "vy", "vz", "p", "q", "r")}
    series.update({"t": [k * ts for k in range(n)], "wp": [0] * 60 + [1] * 60, "in_task": [True] * n,
                   "xd": [1.0] * 60 + [1.0] * 60, "yd": [0.0] * 60 + [1.5] * 60, "zd": [1.5] * n,
                   "err": [1.0] * n, "yaw_d": [0.0] * n, "r": [0.5] * n, "label": "/d (test)",
                   "trajectory": False})
    return series


class FiguresTest(unittest.TestCase):
    """What the report's figures show (issue: figures): units, the step
    reference, labels, the yaw command's sign, the desired yaw."""

    @classmethod
    def setUpClass(cls):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.figure
        import tempfile
        cls.figs = {}
        original = matplotlib.figure.Figure.savefig

        def keep(fig, path, **kwargs):
            cls.figs[os.path.basename(path).split("_", 1)[1].rsplit(".", 1)[0]] = fig
        matplotlib.figure.Figure.savefig = keep
        try:
            n = 120
            cmd = {"t": [k / 30.0 for k in range(n)], "u": [[0.0] * n for _ in range(4)]}
            report.figures("/d", mission_series(), cmd, tempfile.mkdtemp(), False)
        finally:
            matplotlib.figure.Figure.savefig = original

    def test_attitude_rates_in_degrees_like_the_attitude(self):
        rates = self.figs["velocities"].axes[1]
        self.assertEqual(rates.get_ylabel(), "attitude rate [deg/s]")
        self.assertAlmostEqual(max(rates.lines[2].get_ydata()), math.degrees(0.5))

    def test_the_top_view_shows_waypoints_not_lines_between_them(self):
        top = self.figs["tracking"].axes[0]
        self.assertEqual([l.get_label() for l in top.lines], ["flown"])
        self.assertEqual(len(top.collections), 1)  # the waypoints, as points

    def test_every_segment_is_labelled(self):
        err = self.figs["tracking"].axes[1]
        self.assertEqual([t.get_text().strip() for t in err.texts], ["waypoint 1", "waypoint 2"])

    def test_command_signs_are_said(self):
        cmds = self.figs["commands"].axes
        self.assertIn("negative", cmds[3].get_ylabel())
        self.assertIn("negative", cmds[1].get_ylabel())

    def test_attitude_shows_the_desired_yaw(self):
        yaw = self.figs["attitude"].axes[2]
        self.assertIn("yaw desired", [l.get_label() for l in yaw.lines])


class ReportTest(SettlingTest, FiguresTest):
    """Both, in one rostest."""

    @classmethod
    def setUpClass(cls):
        SettlingTest.setUpClass.__func__(cls)
        FiguresTest.setUpClass.__func__(cls)


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "report_settling", ReportTest)
