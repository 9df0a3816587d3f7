#!/usr/bin/python3
"""report on a bag of formation.launch (lockstep, each robot its delay) gives
the formation's errors exactly as `flight --formation` computes them from
its own run (its --csv: Q and Qd per tick), each robot's tracking, the
smallest distance, the figures and the video of the robots; for the
two-drone line and the UAV-UGV line (~formation_file, ~robots)."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import rospy
import rostest

import aurora

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import frames_moved, record_until, report_on  # noqa: E402
from tools import rosrun  # noqa: E402


def flight_errors(formation_file, delays, first, last, ts, names, skipped=()):
    """RMS after 10 s of the shape's variables (rho, alpha, beta), the
    horizontal position and the height over ticks first..last but the
    `skipped` ones (those the bag lacks), the smallest distance, the rows
    so taken and flight's last tick (the formation's end), from flight's
    CSV."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "f.csv")
        subprocess.run(rosrun("aurora_control", "flight") + ["--formation", formation_file, "--delay"] +
                       [str(d) for d in delays] + ["--csv", path], check=True, stdout=subprocess.PIPE)
        every = list(csv.DictReader(open(path)))
        rows = [r for r in every if first <= int(r["step"]) <= last and int(r["step"]) not in skipped]
    sums, n, closest = [0.0] * 5, 0, 1e300
    for r in rows:
        closest = min(closest, float(r["Q_rho"]))
        if int(r["step"]) * ts < 10.0:
            continue
        e = [float(r["Qd_" + v]) - float(r["Q_" + v]) for v in names]
        for i, term in enumerate((e[3] ** 2, e[4] ** 2, e[5] ** 2, e[0] ** 2 + e[1] ** 2, e[2] ** 2)):
            sums[i] += term
        n += 1
    return [math.sqrt(s / n) for s in sums], closest, len(rows), int(every[-1]["step"])


class FormationReportTest(unittest.TestCase):
    def test_the_report_counts_the_formations_ticks(self):
        """A bag runs past the formation's end (the sims go on until
        stop_after): the report measures ticks 0 .. ticks - 1 only, as flight
        --formation does (2,700 ticks of a 90 s formation, not 2,701)."""
        from types import SimpleNamespace as NS
        from aurora import formation_report
        point = lambda x, y, z: NS(position=NS(x=x, y=y, z=z))  # noqa: E731
        ticks, states = {}, {"a": {}, "b": {}}
        for k in range(8):
            ticks[k] = NS(step=k, ticks=5, Qd=[0.0, 0.0, 1.0, 1.5, 0.5, 0.0], reference_position=[0.0] * 6)
            states["a"][k] = point(0.1 * k, 0.0, 1.0)
            states["b"][k] = point(0.1 * k + 0.5, 0.0, 2.0)
        s = formation_report.series_of(["a", "b"], ticks, states, 1.0 / 30)
        self.assertEqual(s["k"], [0, 1, 2, 3, 4])
        m = formation_report.metrics_of(["a", "b"], s, 1.0 / 30)
        self.assertEqual((m["ticks"], m["last_tick"], m["ticks_missing"]), (5, 4, []))
        self.assertNotIn("missing", formation_report.missing_text(m))
        # Messages the recorder dropped (a loaded machine): a robot's state
        # at tick 1, the Formation message of tick 3. The report skips those
        # ticks and says which.
        del states["b"][1], ticks[3]
        s = formation_report.series_of(["a", "b"], ticks, states, 1.0 / 30)
        self.assertEqual(s["k"], [0, 2, 4])
        m = formation_report.metrics_of(["a", "b"], s, 1.0 / 30)
        self.assertEqual((m["ticks"], m["last_tick"], m["ticks_missing"]), (3, 4, [1, 3]))
        self.assertIn("2 ticks missing from the bag, first 1: the recorder dropped", formation_report.missing_text(m))

    def test_report_of_a_formation_bag(self):
        bag = record_until(900, rospy.get_param("~bag_dir"), rospy.get_param("~prefix"),
                           state="/ardrone2/state", recorder="/recorder")
        out, rc, said = report_on(bag)
        self.assertEqual(rc, 0, said)
        # Issue 31: it said nothing while it rendered the video (80 s for a whole flight).
        self.assertIn("report: formation: rendering the video: frame 1 of", said)
        m = json.load(open(os.path.join(out, "metrics.json")))["formation"]
        self.assertEqual(m["first_tick"], 0)
        self.assertGreaterEqual(m["last_tick"], 900)
        robots = rospy.get_param("~robots")
        ts = rospy.get_param("/%s/vehicle/sample_time" % robots[0])
        delays = [rospy.get_param("~delay_1"), rospy.get_param("~delay_2")]
        names = m["variables"]
        self.assertEqual(names, rospy.get_param("~variables"))
        # A tick the recorder dropped (a loaded machine) is skipped by the report, which says which.
        # The bag may run past the formation's end (the recorder stops after the
        # sims' tick 900, however far a fast lockstep has gone by then): the
        # report stops at flight's last tick, whatever the shape's duration.
        rms, closest, rows, flight_last = flight_errors(rospy.get_param("~formation_file"), delays, 0,
                                                        m["last_tick"], ts, names, set(m["ticks_missing"]))
        self.assertLessEqual(m["last_tick"], flight_last, "the report measures ticks after the formation's end")
        self.assertEqual(rows, m["ticks"], "the report's ticks are not flight's")
        got = m["rms_after_settle"]
        for name, want in zip(("rho_m", "alpha_rad", "beta_rad", "position_xy_m", "height_m"), rms):
            self.assertAlmostEqual(got[name], want, delta=1e-12 + 1e-9 * abs(want), msg=name)
        self.assertAlmostEqual(m["smallest_distance_m"], closest, delta=1e-12)
        for d in robots:
            self.assertGreater(m["drones"][d]["rms_tracking_error_m"], 0.0)
            self.assertLess(m["drones"][d]["max_tracking_error_m"], rospy.get_param("~max_tracking_error", 1.0))
        for f in ("formation_shape.png", "formation_position.png", "formation_errors.png", "formation_top_view.png",
                  "formation_flight.mp4"):
            self.assertGreater(os.path.getsize(os.path.join(out, f)), 10000, f)
        # One frame per 0.1 s of flight (report's default --fps 10), from tick 0.
        self.assertEqual(m["video_frames"], int(math.floor(m["last_tick"] * ts * 10 + 1e-9)) + 1)
        # The robots, their trails and the clock drawn over the axes drawn once.
        self.assertGreater(frames_moved(os.path.join(out, "formation_flight.mp4"), m["video_frames"]), 500)
        self.assertIn("## Formation", open(os.path.join(out, "report.md")).read())
        self.check_readers(bag, delays, m)

    def check_readers(self, bag, delays, m):
        """aurora.read_formation_bag: the ticks' Q and Qd and positions are
        aurora.simulate_formation's (lockstep), its metrics the report's."""
        frame, metrics = aurora.read_formation_bag(bag)
        g = aurora.simulate_formation(rospy.get_param("~formation_file"), delays=tuple(delays))
        k = frame.step.to_numpy()
        held = [i for i in range(m["last_tick"] + 1) if i not in set(m["ticks_missing"])]  # the report's ticks
        self.assertTrue(np.array_equal(k, held))
        if hasattr(g, "Q"):  # the two-drone line's FormationFlight
            Q, Qd = (lambda j, v: g.Q[k, j]), (lambda j, v: g.Qd[k, j])  # noqa: E731
            position = lambda d, j, a: g.states[k, d, j]  # noqa: E731
        else:  # a ShapedFormationFlight: flight --formation's columns
            Q, Qd = (lambda j, v: g.column("Q_" + v)[k]), (lambda j, v: g.column("Qd_" + v)[k])  # noqa: E731
            robot = lambda d, a: next(c for c in g.columns if c in ("r%d_%s" % (d + 1, a), "d%d_%s" % (d + 1, a)))  # noqa: E731
            position = lambda d, j, a: g.column(robot(d, a))[k]  # noqa: E731
        for j, v in enumerate(m["variables"]):
            self.assertTrue(np.allclose(frame["Q_" + v], Q(j, v), rtol=0, atol=1e-12), v)  # asin of the same positions
            self.assertTrue(np.array_equal(frame["Qd_" + v].to_numpy(), Qd(j, v)), v)
        for d in range(len(rospy.get_param("~robots"))):
            for j, a in enumerate("xyz"):
                self.assertTrue(np.array_equal(frame["d%d_%s" % (d + 1, a)].to_numpy(), position(d, j, a)))
        self.assertEqual(metrics["rms_after_settle"], m["rms_after_settle"])
        with self.assertRaises(ValueError) as e:  # no drone's control topic: not a single-drone flight
            aurora.read_bag(bag)
        self.assertIn("control", str(e.exception))
        self.assertIn("is a formation's", str(e.exception))  # issue 51: it pointed nowhere
        self.assertIn("aurora.read_formation_bag(path)", str(e.exception))


if __name__ == "__main__":
    rospy.init_node("check_formation_report")
    rostest.rosrun("aurora_tests", "formation_report", FormationReportTest)
