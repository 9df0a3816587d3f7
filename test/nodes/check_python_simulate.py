#!/usr/bin/python3
"""aurora.simulate (the C++ core through pybind11, no roscore needed) flies
the `flight` tool's flight to the last bit, from shipped names, paths or
dicts, and refuses bad input with a ValueError naming the key."""
import csv
import os
import subprocess
import tempfile
import unittest

import numpy as np
import rostest
import yaml

import aurora


def flight_csv(*args):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "f.csv")
        subprocess.run(["rosrun", "aurora_control", "flight", "--csv", path] + list(args), check=True,
                       stdout=subprocess.PIPE)
        return list(csv.DictReader(open(path)))


STATE = ("x", "y", "z", "phi", "theta", "psi", "dx", "dy", "dz", "dphi", "dtheta", "dpsi")


class SimulateTest(unittest.TestCase):
    def assertSameFlight(self, f, rows):
        self.assertEqual(f.states.shape, (len(rows), 12))
        want = np.array([[float(r[c]) for c in STATE] for r in rows])
        self.assertTrue(np.array_equal(f.states, want), "states differ from flight --csv")
        self.assertTrue(np.array_equal(f.commands, np.array([[float(r["u%d" % i]) for i in range(1, 5)] for r in rows])))
        self.assertTrue(np.array_equal(f.reference, np.array([[float(r[c]) for c in ("xd", "yd", "zd")] for r in rows])))
        self.assertTrue(np.array_equal(f.t, np.array([float(r["t"]) for r in rows])))
        self.assertTrue(np.array_equal(f.error, np.array([float(r["error"]) for r in rows])))

    def test_equals_the_flight_tool(self):
        cfg = aurora.simulation.config_dir()
        f = aurora.simulate("underactuated", "circle", delay=5)
        self.assertSameFlight(f, flight_csv("--controller", cfg + "/controllers/underactuated.yaml",
                                            "--task", cfg + "/tasks/circle.yaml", "--delay", "5"))
        g = aurora.simulate("pd_saturated", "mission4", link="wifi_congested")
        self.assertSameFlight(g, flight_csv("--link", cfg + "/links/wifi_congested.yaml"))
        self.assertEqual(g.metrics["delay"], 2)  # the link's uplink delay
        self.assertGreater(g.metrics["iae"], 0.0)

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
        ]
        for call, text in cases:
            with self.assertRaises(ValueError) as e:
                call()
            self.assertIn(text, str(e.exception))


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "python_simulate", SimulateTest)
