#!/usr/bin/python3
"""The report's settling time: an oscillation that ends its segment in a
trough is not settled (issue: settling of an oscillation); a response that
stays in its band for the hold time is, from the time it entered."""
import importlib.machinery
import importlib.util
import math
import os
import subprocess
import unittest

import rostest


def load_report():
    path = subprocess.run(["rospack", "find", "aurora_control"], stdout=subprocess.PIPE,
                          check=True).stdout.decode().strip() + "/scripts/report"
    loader = importlib.machinery.SourceFileLoader("aurora_report", path)
    spec = importlib.util.spec_from_loader("aurora_report", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def segment(errors, ts=1.0 / 30.0):
    """One waypoint segment, 1 m step along x, with the given error series."""
    n = len(errors)
    return {"t": [k * ts for k in range(n)], "err": list(errors), "wp": [0] * n,
            "xd": [1.0] * n, "yd": [0.0] * n, "zd": [1.0] * n,
            "x": [1.0 - e for e in errors], "y": [0.0] * n, "z": [1.0] * n}


class SettlingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.report = load_report()

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


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "report_settling", SettlingTest)
