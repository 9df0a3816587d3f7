#!/usr/bin/python3
"""aurora.simulate (the C++ core through pybind11, no roscore needed) flies
the `flight` tool's flight to the last bit, from shipped names, paths or
dicts, and refuses bad input with a ValueError naming the key."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import rostest
import yaml

import aurora

# The shared helpers sit beside this script (catkin's relay runs it with __file__ set to this path).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from refusals import expect_refusals  # noqa: E402
from tools import rosrun  # noqa: E402


def flight_csv(*args):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "f.csv")
        subprocess.run(rosrun("aurora_control", "flight") + ["--csv", path] + list(args), check=True,
                       stdout=subprocess.PIPE)
        return list(csv.DictReader(open(path)))


def column(rows, name):
    return np.array([float(r[name]) for r in rows])


STATE = ("x", "y", "z", "phi", "theta", "psi", "dx", "dy", "dz", "dphi", "dtheta", "dpsi")


class SimulateTest(unittest.TestCase):
    def assertSameFlight(self, f, rows, states=STATE, inputs=4):
        self.assertEqual(f.states.shape, (len(rows), len(states)))
        self.assertEqual(tuple(f.state_names), states)
        want = np.array([[float(r[c]) for c in states] for r in rows])
        self.assertTrue(np.array_equal(f.states, want), "states differ from flight --csv")
        commands = [[float(r["u%d" % i]) for i in range(1, inputs + 1)] for r in rows]
        self.assertTrue(np.array_equal(f.commands, np.array(commands)))
        self.assertTrue(np.array_equal(f.reference, np.array([[float(r[c]) for c in ("xd", "yd", "zd")] for r in rows])))
        self.assertTrue(np.array_equal(f.t, np.array([float(r["t"]) for r in rows])))
        self.assertTrue(np.array_equal(f.error, np.array([float(r["error"]) for r in rows])))

    def test_equals_the_flight_tool(self):
        cfg = aurora.simulation.config_dir()
        f = aurora.simulate("underactuated", "circle", delay=5)
        self.assertSameFlight(f, flight_csv("--controller", cfg + "/controllers/underactuated.yaml",
                                            "--task", cfg + "/tasks/circle.yaml", "--delay", "5"))
        k = np.arange(len(f.t))  # the delay rule: the current state until 5 are kept, then 5 samples old
        self.assertTrue(np.array_equal(f.delay_in_force, np.where(k < 5, 0, 5)))
        g = aurora.simulate("pd_saturated", "mission4", link="wifi_congested")
        self.assertSameFlight(g, flight_csv("--link", cfg + "/links/wifi_congested.yaml"))
        self.assertEqual(g.metrics["delay"], 2)  # the link's uplink delay
        # Over the link the age varies: at least the base delay once started, more with jitter and losses.
        self.assertEqual(g.delay_in_force.min(), 0)
        self.assertGreaterEqual(g.delay_in_force[10:].min(), 2)
        self.assertGreater(g.delay_in_force.max(), 2)
        self.assertGreater(g.metrics["iae"], 0.0)

    def test_the_bebop_2_equals_the_flight_tool(self):
        """Issue 33: the compensator's controller file chooses the Bebop 2 (its vehicle file by default), at
        its file's rate or `rate`, clamped or not, as flight flies it; the AR.Drone's laws refuse a rate."""
        f = aurora.simulate("bebop2_compensator", "bebop2_waypoints", rate=5, clamp=False)
        self.assertSameFlight(f, flight_csv("--controller", "bebop2_compensator", "--task", "bebop2_waypoints",
                                            "--rate", "5", "--no-clamp"))
        self.assertEqual(f.law, "bebop2_compensator")
        g = aurora.simulate("bebop2_compensator", "bebop2_lemniscate", delay=3, vehicle="bebop2")
        self.assertSameFlight(g, flight_csv("--controller", "bebop2_compensator", "--task", "bebop2_lemniscate",
                                            "--delay", "3"))
        expect_refusals(self, [
            (lambda: aurora.simulate("pd_saturated", "mission4", rate=10), "rate=10 is refused here"),
            (lambda: aurora.simulate("bebop2_compensator", "mission4", rate=7), "rate=7 Hz does not divide"),
            (lambda: aurora.simulate("bebop2_compensator", "mission4", rate=0), "rate: expected a number above 0"),
            (lambda: aurora.simulate("bebop2_compensator", "mission4", vehicle="ardrone2"),
             "but the controller 'bebop2_compensator' flies type 'bebop2'"),
        ])

    def test_the_pioneer_equals_the_flight_tool(self):
        """Issue 33: the Pioneer P3-DX's 14 states and 2 commands, the same bits as flight --csv."""
        f = aurora.simulate("pioneer_dynamic", "pioneer_lemniscate", delay=4)
        self.assertSameFlight(f, flight_csv("--controller", "pioneer_dynamic", "--task", "pioneer_lemniscate",
                                            "--delay", "4"), STATE + ("u", "omega"), 2)
        self.assertEqual((f.law, f.vehicle), ("pioneer_dynamic", "pioneer3dx"))
        g = aurora.simulate({"controller": {"name": "pioneer_kinematic", "k1": [0.35, 0.35], "k2": [0.8, 0.8]}},
                            "pioneer_lemniscate")
        self.assertSameFlight(g, flight_csv("--controller", "pioneer_kinematic", "--task", "pioneer_lemniscate"),
                              STATE + ("u", "omega"), 2)
        expect_refusals(self, [
            (lambda: aurora.simulate("pioneer_dynamic", "pioneer_lemniscate", clamp=False),
             "clamp=False is refused for the Pioneer P3-DX"),
            (lambda: aurora.simulate("pioneer_dynamic", "circle"), "'task.height' = 1.5 is outside the accepted range"),
            (lambda: aurora.simulate("pioneer_dynamic", "pioneer_lemniscate", rate=10), "is refused here"),
        ])

    def test_the_predictor_flies_the_delayed_loop_as_the_undelayed_one(self):
        """Issue 35: a controller file's predictor block, as flight flies it; with the nominal model as plant
        the delayed loop flies as the undelayed one, bit for bit (resimulate)."""
        f = aurora.simulate("pd_saturated_predictor", "mission4", delay=10)
        self.assertSameFlight(f, flight_csv("--controller", "pd_saturated_predictor", "--delay", "10"))
        plain = aurora.simulate("pd_saturated", "mission4", delay=0)
        self.assertTrue(np.array_equal(f.states, plain.states))
        self.assertTrue(np.array_equal(f.delay_in_force[10:], np.full(len(f.t) - 10, 10)))
        self.assertGreater(np.abs(aurora.simulate("pd_saturated", "mission4", delay=10).states - plain.states).max(),
                           0.1)

    def test_a_dict_is_its_file(self):
        cfg = aurora.simulation.config_dir()
        with open(cfg + "/controllers/pd_saturated.yaml") as fh:
            controller = yaml.safe_load(fh)
        with open(cfg + "/tasks/lemniscate.yaml") as fh:
            task = yaml.safe_load(fh)
        a = aurora.simulate(controller, task, delay=3)
        b = aurora.simulate(cfg + "/controllers/pd_saturated.yaml", "lemniscate", delay=3)
        self.assertTrue(np.array_equal(a.states, b.states))
        self.assertEqual(a.metrics, b.metrics)

    def test_bad_input_raises_value_error_naming_it(self):
        with open(aurora.simulation.config_dir() + "/controllers/pd_saturated.yaml") as fh:
            controller = yaml.safe_load(fh)
        top = next(iter(controller))
        bad_key = {top: dict(controller[top], kq=1.0)}
        cases = [
            (lambda: aurora.simulate(bad_key, "mission4"), "kq"),
            (lambda: aurora.simulate("pd_saturated", "mission4", delay=3000), "accepted integer samples in [0, 2047]"),
            (lambda: aurora.simulate("pd_saturated", "mission4", delay="3"), "delay: expected whole samples"),
            (lambda: aurora.simulate("pd_saturated", "nowhere"), "task 'nowhere' is not a shipped one: accepted"),
            (lambda: aurora.simulate("/no/such/file.yaml", "mission4"), "does not exist"),
            (lambda: aurora.simulate(3, "mission4"), "controller: expected a name, a path or a dict"),
            (lambda: aurora.simulate("pd_saturated", "mission4", link={"link": {"uplink": {"loss": 2}}}), "loss"),
            # Issue 31: a pybind11 TypeError, a truthy "no", an empty vehicle flown as the AR.Drone.
            (lambda: aurora.simulate("pd_saturated", "mission4", delay=2 ** 64), "delay = 18446744073709551616 is refused"),
            (lambda: aurora.simulate("pd_saturated", "mission4", delay=np.array([3])), "delay: expected whole samples"),
            (lambda: aurora.simulate("pd_saturated", "mission4", clamp="no"), "clamp: expected True or False, got 'no'"),
            (lambda: aurora.simulate("pd_saturated", "mission4", vehicle={}), "vehicle"),
            (lambda: aurora.simulate({"controller": {"name": "pd_saturated", "kp": object()}}, "mission4"),
             "controller.kp: <object"),
        ]
        expect_refusals(self, cases)

    def test_numpy_values_are_their_numbers(self):
        """Issue 31: numpy values in dicts raised yaml's RepresenterError,
        numpy integers as a delay were refused."""
        cfg = aurora.simulation.config_dir()
        with open(cfg + "/controllers/pd_saturated.yaml") as fh:
            controller = yaml.safe_load(fh)
        with open(cfg + "/tasks/lemniscate.yaml") as fh:
            task = yaml.safe_load(fh)
        top = next(iter(controller))
        numpy_controller = {top: dict(controller[top], kp=np.float64(controller[top]["kp"]))}
        numpy_task = {"task": {k: (np.array(v) if isinstance(v, list) else v) for k, v in task["task"].items()}}
        a = aurora.simulate(numpy_controller, numpy_task, delay=np.int64(3), clamp=np.bool_(True))
        b = aurora.simulate(controller, task, delay=3)
        self.assertTrue(np.array_equal(a.states, b.states))


class SimulateFormationTest(unittest.TestCase):
    def test_formation_equals_flight_formation(self):
        cfg = aurora.simulation.config_dir()
        g = aurora.simulate_formation("line_lemniscate_ik", delays=(3, 9))
        rows = flight_csv("--formation", cfg + "/formations/line_lemniscate_ik.yaml", "--delay", "3", "9")
        self.assertEqual(g.states.shape, (len(rows), 2, 12))
        self.assertTrue(np.array_equal(g.t, column(rows, "t")))
        for d in range(2):
            for i, c in enumerate(STATE):
                self.assertTrue(np.array_equal(g.states[:, d, i], column(rows, "d%d_%s" % (d + 1, c))), (d, c))
            for i in range(4):
                self.assertTrue(np.array_equal(g.commands[:, d, i], column(rows, "d%d_u%d" % (d + 1, i + 1))))
        for i, c in enumerate(("xF", "yF", "zF", "rho", "alpha", "beta")):
            self.assertTrue(np.array_equal(g.Q[:, i], column(rows, "Q_" + c)), c)
            self.assertTrue(np.array_equal(g.Qd[:, i], column(rows, "Qd_" + c)), c)
        self.assertEqual(g.metrics["delays"], (3, 9))
        h = aurora.simulate_formation("line_lemniscate_ik", delays=np.array([3, 9]))
        self.assertTrue(np.array_equal(h.states, g.states))
        self.assertTrue(g.metrics["feasible"])
        self.assertEqual(g.drones, ("ardrone1", "ardrone2"))

    def test_formation_dict_is_its_file(self):
        with open(aurora.simulation.config_dir() + "/formations/line_lemniscate.yaml") as fh:
            formation = yaml.safe_load(fh)
        a = aurora.simulate_formation(formation)
        b = aurora.simulate_formation("line_lemniscate")
        self.assertTrue(np.array_equal(a.Q, b.Q))
        self.assertEqual(a.metrics, b.metrics)

    def test_formation_bad_input_raises_value_error(self):
        with open(aurora.simulation.config_dir() + "/formations/line_lemniscate.yaml") as fh:
            formation = yaml.safe_load(fh)
        formation["formation"]["period"] = -1
        cases = [
            (lambda: aurora.simulate_formation(formation), "period"),
            (lambda: aurora.simulate_formation("line_lemniscate", delays=(3,)), "one delay per drone"),
            (lambda: aurora.simulate_formation("line_lemniscate", delays=(3, 5000)), "drone 2"),
            (lambda: aurora.simulate_formation("line_lemniscate", delays="39"), "delays: expected"),
            (lambda: aurora.simulate_formation("line_triangle"), "formation 'line_triangle' is not a shipped one"),
            # Issue 31: a dict's keys were flown as the delays (0, 1), an empty vehicle as the AR.Drone.
            (lambda: aurora.simulate_formation("line_lemniscate", delays={0: 3, 1: 9}), "delays: expected a list"),
            (lambda: aurora.simulate_formation("line_lemniscate", delays={3, 9}), "delays: expected a list"),
            (lambda: aurora.simulate_formation("line_lemniscate", vehicle={}), "vehicle"),
        ]
        expect_refusals(self, cases)


class ShapedFormationTest(unittest.TestCase):
    """Issue 34: AuRoRA's UAV-UGV line and triangle from Python: flight --formation's CSV as an array, to the
    bit, with each robot's delay and the triangle's law; bad input refused naming it."""

    def test_a_robots_predictor_is_flown(self):
        """Issue 51 (1): the triangle's drones on their controller file's predictor (the exact model): the delayed
        flight is the undelayed one, to the bit; without the predictor it is not."""
        undelayed = aurora.simulate_formation("triangle_ardrones", delays=(0, 0, 0))
        predicted = aurora.simulate_formation("triangle_ardrones_predictor", delays=(6, 6, 6))
        self.assertTrue(np.array_equal(predicted.table, undelayed.table))
        self.assertFalse(np.array_equal(aurora.simulate_formation("triangle_ardrones", delays=(6, 6, 6)).table,
                                        undelayed.table))

    def test_the_uav_ugv_line_and_the_triangle_equal_flight_formation(self):
        for name, args, kwargs in (("line_pioneer_ardrone", ["--delay", "0", "10"], {"delays": (0, 10)}),
                                   ("triangle_ardrones", ["--law", "PSO", "--delay", "6", "0", "3"],
                                    {"law": "PSO", "delays": np.array([6, 0, 3])})):
            g = aurora.simulate_formation(name, **kwargs)
            rows = flight_csv("--formation", name, *args)
            self.assertEqual(g.columns, list(rows[0].keys()))
            self.assertEqual(g.table.shape, (len(rows), len(g.columns)))
            for c in g.columns:
                self.assertTrue(np.array_equal(g.column(c), column(rows, c)), (name, c))
        self.assertEqual(g.shape, "triangle")
        self.assertEqual((g.errors["delay_1"], g.errors["delay_2"], g.errors["delay_3"]), (6, 0, 3))
        h = aurora.simulate_formation("line_pioneer_ardrone")
        self.assertAlmostEqual(h.errors["rms_rho"], 0.0039, places=4)  # AuRoRA's, as flight prints it
        self.assertEqual(h.column("r1_omega").shape, (3900,))

    def test_bad_input_is_refused_naming_it(self):
        expect_refusals(self, [
            (lambda: aurora.simulate_formation("triangle_kinematic", delays=(1, 2)), "one delay per robot (3)"),
            (lambda: aurora.simulate_formation("line_pioneer_ardrone", delays=(1, 5000)), "(robot 2)"),
            (lambda: aurora.simulate_formation("triangle_kinematic", law="NSB"), "'NSB' is not a triangle law"),
            (lambda: aurora.simulate_formation("triangle_kinematic", law=3), "law: expected a shape law's name (triangle: "),
            (lambda: aurora.simulate_formation("triangle_kinematic", law=""), "law: expected a shape law's name (triangle: "),
            (lambda: aurora.simulate_formation("line_lemniscate", law="N"), "law= is refused for the line"),
            (lambda: aurora.simulate_formation("line_pioneer_ardrone", vehicle="ardrone2"), "vehicle= is refused"),
        ])
        with self.assertRaises(KeyError) as e:
            aurora.simulate_formation("triangle_kinematic").column("r1_u")
        self.assertIn("'r1_u' is not a column", str(e.exception))


class ShortFormationReportTest(unittest.TestCase):
    def test_a_bag_shorter_than_the_settle_time_is_said_to_be(self):
        """Issue 51 (2): a formation bag that ends before the checks' 10 s reported every RMS as 0."""
        from aurora import formation_report
        s = {"k": [0, 1], "t": [0.0, 5.0], "Qtil": [[0.1] * 6, [0.2] * 6], "e_position": [0.1, 0.2],
             "e_shape": [0.1, 0.2], "distance": [1.0, 1.1], "missing": [], "d1": {"track": [0.1, 0.2]}}
        m = formation_report.metrics_of(["d1"], s, 5.0)
        self.assertEqual(m["ticks_judged"], 0)
        self.assertTrue(all(v is None for v in m["rms_after_settle"].values()), m)
        self.assertIsNone(m["max_position_error_m"])
        self.assertIsNone(m["iae_shape_m_s"])
        text = "\n".join(formation_report.markdown(dict(m, shape="line"), []))
        self.assertIn("none: the bag ends at 5.00 s, before the 10 s the errors are judged from", text)
        self.assertNotIn("0.0000", text)
        s["t"] = [0.0, 12.0]
        judged = formation_report.metrics_of(["d1"], s, 12.0)
        self.assertEqual(judged["ticks_judged"], 1)
        self.assertAlmostEqual(judged["rms_after_settle"]["rho_m"], 0.2)


class FormationFiguresTest(unittest.TestCase):
    def test_the_figures_show_what_docs_say(self):
        from aurora import formation_figures
        with tempfile.TemporaryDirectory() as tmp:
            self.assertEqual(formation_figures.main([tmp]), 0)
            for name in ("formation_laws.png", "formation_mirror.png"):
                self.assertGreater(os.path.getsize(os.path.join(tmp, name)), 20000, name)
        # docs/formation.md: the mirror's layer errors vanish, drone 2 ends
        # below drone 1, 1.5 m from where eq. F2 wants it.
        g = formation_figures.mirror_flight()
        self.assertLess(np.abs(g.Qd[-1, 3:] - g.Q[-1, 3:]).max(), 1e-3)
        self.assertLess(g.states[-1, 1, 2], g.states[-1, 0, 2] - 0.7)
        self.assertAlmostEqual(formation_figures.shape_error(g)[-1], 1.5, places=2)
        # ... and position priority's shape error is ten times inverse kinematics'.
        p, ik = aurora.simulate_formation("line_lemniscate"), aurora.simulate_formation("line_lemniscate_ik")
        self.assertGreater(p.metrics["rms_rho"], 10 * ik.metrics["rms_rho"])


class PythonSimulateTests(SimulateTest, SimulateFormationTest, ShapedFormationTest, ShortFormationReportTest,
                          FormationFiguresTest):
    """Both, for rostest (which runs one TestCase class)."""


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "python_simulate", PythonSimulateTests)
