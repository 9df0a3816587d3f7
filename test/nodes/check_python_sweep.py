#!/usr/bin/python3
"""aurora.sweep runs the sweep program from Python: its DataFrame holds
results.csv's columns and values, a structured array too; Ctrl-C leaves the
finished chunks and the same call resumes them; bad input raises ValueError
with the program's message, and nothing is left behind."""
import copy
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
import pandas as pd
import rostest
import yaml

import aurora

# The shared helpers sit beside this script (catkin's relay runs it with __file__ set to this path).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from refusals import expect_refusals  # noqa: E402
from tools import rosrun  # noqa: E402


def shipped(name):
    with open(os.path.join(aurora.simulation.config_dir(), "sweeps", name + ".yaml")) as f:
        return yaml.safe_load(f)


def thesis_cut():
    """The thesis grid cut to 8 x 8 x 8."""
    d = shipped("positioning_delay")
    p = d["sweep"]["parameters"]
    p["kp"]["count"], p["kd"]["count"] = 8, 8
    p["delay"] = {"from": 0, "to": 63, "count": 8}
    return d


def formation_cut(repeats):
    d = shipped("formation_delay")
    d["sweep"]["repeats"] = repeats
    for k in ("delay_1", "delay_2"):
        d["sweep"]["parameters"][k] = {"from": 0, "to": 28, "count": 8}
    return d


class PythonSweepTest(unittest.TestCase):
    def test_the_results_are_the_programs(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "cut.yaml"), "w") as f:
                yaml.safe_dump(thesis_cut(), f)
            subprocess.run(rosrun("aurora_sweep", "sweep") + ["--config", f.name, "--out", tmp + "/cli",
                            "--backend", "cpu", "--output", "csv", "--no-plots", "--quiet"], check=True,
                           stdout=subprocess.PIPE)
            cli = pd.read_csv(tmp + "/cli/results.csv", float_precision="round_trip")
        from_csv, summary = aurora.sweep(thesis_cut(), backend="cpu", output="csv", progress=False)
        self.assertEqual(list(from_csv.columns), list(cli.columns))
        for c in cli.columns:
            self.assertTrue(np.array_equal(from_csv[c].to_numpy(), cli[c].to_numpy()), c)
        self.assertEqual(summary["combinations"], 512)
        self.assertEqual(summary["feasible"], int(cli.feasible.sum()))
        from_h5, _ = aurora.sweep(thesis_cut(), backend="cpu", progress=False)  # results.h5: the stored types
        self.assertEqual(list(from_h5.columns), list(cli.columns))
        for c in cli.columns:
            a, b = from_h5[c].to_numpy(), cli[c].to_numpy()
            if a.dtype.kind == "f" and a.dtype.itemsize == 4:  # float columns: the CSV prints 9 digits
                self.assertTrue(np.array_equal(a, b.astype(np.float32)), c)
            else:
                self.assertTrue(np.array_equal(a, b), c)
        # Issue 31: numpy values (an axis from np.linspace, a numpy count) raised yaml's RepresenterError.
        numpy_cut = thesis_cut()
        kp = numpy_cut["sweep"]["parameters"]["kp"]
        numpy_cut["sweep"]["parameters"]["kp"] = {"values": list(np.linspace(kp["from"], kp["to"], kp["count"]))}
        numpy_cut["sweep"]["parameters"]["kd"]["count"] = np.int64(8)
        from_numpy, _ = aurora.sweep(numpy_cut, backend="cpu", output="csv", progress=False)
        self.assertTrue(np.array_equal(from_numpy.feasible.to_numpy(), cli.feasible.to_numpy()))
        arr, _ = aurora.sweep(thesis_cut(), backend="scalar", as_frame=False, progress=False)
        self.assertEqual(arr.dtype.names, tuple(cli.columns))
        self.assertTrue(np.array_equal(arr["feasible"], cli.feasible.to_numpy()))

    def test_ctrl_c_leaves_chunks_and_the_same_call_resumes(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            script = os.path.join(tmp, "run.py")
            with open(script, "w") as f:
                f.write("import aurora, sys, yaml\nd = yaml.safe_load(open(sys.argv[1]))\ntry:\n"
                        "    aurora.sweep(d, backend='scalar', out=sys.argv[2], chunk_size=64, progress=False)\n"
                        "except aurora.SweepInterrupted as e:\n    print(e)\n    sys.exit(3)\n")
            with open(os.path.join(tmp, "f.yaml"), "w") as f:
                yaml.safe_dump(formation_cut(repeats=64), f)
            child = subprocess.Popen([sys.executable, script, f.name, out], stdout=subprocess.PIPE, text=True,
                                     preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
            progress = os.path.join(out, "progress")
            deadline = time.time() + 60
            while time.time() < deadline and not (os.path.isdir(progress) and
                                                   any(n.endswith(".bin") for n in os.listdir(progress))):
                time.sleep(0.05)
            child.send_signal(signal.SIGINT)  # Ctrl-C
            said, _ = child.communicate(timeout=60)
            self.assertEqual(child.returncode, 3, said)
            self.assertIn("finished chunk", said)
            self.assertIn("computes only the missing ones", said)
            results, summary = aurora.sweep(formation_cut(repeats=64), backend="scalar", out=out, chunk_size=64,
                                            progress=False)
            self.assertGreater(summary["chunks"]["resumed"], 0)
            self.assertGreater(summary["chunks"]["computed"], 0)
            self.assertEqual(len(results), 4096)
            self.assertTrue(np.array_equal(results["index"].to_numpy(), np.arange(4096)))

    def test_a_study_with_and_without_the_predictor(self):
        """Issue 35: aurora.sweep runs a sweep file's predictor (with the nominal model every delay flies as
        none), and plot_sweep --compare draws the two side by side."""
        with_predictor = thesis_cut()
        with_predictor["sweep"]["predictor"] = {"form": "smith"}
        with tempfile.TemporaryDirectory() as tmp:
            plain, _ = aurora.sweep(thesis_cut(), out=tmp + "/plain", backend="cpu", progress=False)
            predicted, summary = aurora.sweep(with_predictor, out=tmp + "/predicted", backend="cpu", progress=False)
            self.assertEqual(summary["predictor"]["form"], "smith")
            at_zero = predicted[predicted.delay == 0].feasible.sum()
            self.assertEqual(predicted.feasible.sum(), 8 * at_zero)  # every delay as delay 0
            self.assertGreater(predicted.feasible.sum(), 2 * plain.feasible.sum())
            rc = subprocess.run(rosrun("aurora_sweep", "plot_sweep") + ["--compare", tmp + "/plain",
                                 tmp + "/predicted", tmp + "/cmp"]).returncode
            self.assertEqual(rc, 0)
            self.assertEqual(sorted(os.listdir(tmp + "/cmp")),
                             ["compare_feasible_share.png", "compare_max_tolerable_delay.png"])
            bad = subprocess.run(rosrun("aurora_sweep", "plot_sweep") + ["--compare", tmp + "/plain"],
                                 stderr=subprocess.PIPE, text=True)
            self.assertEqual(bad.returncode, 2)
            self.assertIn("give two sweeps' output folders and a folder for the figures", bad.stderr)

    def test_studies_of_other_sample_times_compare_in_seconds(self):
        """Issue 51 (8): plot_sweep --compare of a Bebop (1/30 s) and a Pioneer (0.1 s) study put both on one
        "delay [samples]" axis; summary.json now gives each sweep's sample time, and the two are drawn in
        seconds (said on the way); two of one sample time stay in samples."""
        from aurora_sweep.plot_sweep import delay_scales
        cuts = {}
        for name in ("bebop2_delay", "pioneer_delay"):
            d = shipped(name)
            for k, v in d["sweep"]["parameters"].items():
                if isinstance(v, dict) and "count" in v:
                    v["count"] = 4
            d["sweep"]["parameters"]["delay"] = {"values": [0, 5, 10, 15]}
            cuts[name] = d
        with tempfile.TemporaryDirectory() as tmp:
            summaries = {}
            for name, d in cuts.items():
                _, summaries[name] = aurora.sweep(d, out=tmp + "/" + name, backend="cpu", progress=False)
            self.assertEqual(summaries["bebop2_delay"]["sample_time_s"], 1.0 / 30.0)
            self.assertEqual(summaries["pioneer_delay"]["sample_time_s"], 0.1)
            p = subprocess.run(rosrun("aurora_sweep", "plot_sweep") + ["--compare", tmp + "/bebop2_delay",
                                tmp + "/pioneer_delay", tmp + "/cmp"], stdout=subprocess.PIPE, universal_newlines=True)
            self.assertEqual(p.returncode, 0)
            self.assertIn("the sample times differ (0.0333333, 0.1 s): delays drawn in seconds", p.stdout)
            self.assertIn("compare_feasible_share.png", os.listdir(tmp + "/cmp"))
        self.assertEqual(delay_scales([summaries["bebop2_delay"], summaries["pioneer_delay"]]), ([1.0 / 30.0, 0.1], "s"))
        self.assertEqual(delay_scales([summaries["bebop2_delay"]] * 2), ([1.0, 1.0], "samples"))
        self.assertEqual(delay_scales([{}, summaries["pioneer_delay"]]), ([1.0, 1.0], "samples"))

    def test_share_contours_draw_only_the_levels_crossed(self):
        """Issue 31: a grid all feasible printed matplotlib's "No contour
        levels were found" warning with its source line."""
        import warnings
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from aurora_sweep.plot_sweep import share_contours
        x, y = np.arange(4.0), np.arange(3.0)
        for grid, lines in ((np.ones((3, 4)), []), (np.full((3, 4), np.nan), []),
                            (np.array([[0.0, 0.6, 1.0, 1.0]] * 3), [0.5, 0.9]), (np.array([[0.0, 0.6, 0.7, 0.8]] * 3), [0.5])):
            fig, ax = plt.subplots()
            with warnings.catch_warnings(record=True) as said:
                warnings.simplefilter("always")
                drawn = share_contours(ax, x, y, grid)
            plt.close(fig)
            self.assertEqual([str(w.message) for w in said], [], grid)
            self.assertEqual(drawn, lines, grid)

    def test_bad_input_raises_value_error_with_the_programs_message(self):
        bad_key = copy.deepcopy(thesis_cut())
        bad_key["sweep"]["parameters"]["kq"] = 1
        out_of_range = copy.deepcopy(thesis_cut())
        out_of_range["sweep"]["parameters"]["kp"] = {"from": 0, "to": 50, "count": 4}
        cases = [
            (lambda: aurora.sweep(bad_key), "'sweep.parameters.kq' is not a parameter of the pd_saturated controller"),
            (lambda: aurora.sweep(thesis_cut(), backend="gpu"), "--backend 'gpu' is unknown: accepted scalar, cpu"),
            (lambda: aurora.sweep(thesis_cut(), precision="half"), "--precision 'half' is unknown"),
            (lambda: aurora.sweep(thesis_cut(), threads="2"), "threads: expected a whole number"),
            (lambda: aurora.sweep("nowhere"), "sweep 'nowhere' is not a shipped one: accepted"),
            (lambda: aurora.sweep("/no/such/sweep.yaml"), "does not exist"),
            (lambda: aurora.sweep(3), "config: expected a shipped sweep's name"),
            (lambda: aurora.sweep(out_of_range), "'sweep.parameters.kp.to' = 50 is outside the accepted range"),
            (lambda: aurora.read_results("/no/such/folder"), "holds no summary.json"),
            # Issue 31: a RuntimeError, a TypeError.
            (lambda: aurora.sweep(thesis_cut(), backend="cuda"), "--backend cuda"),
            (lambda: aurora.read_bag(None), "path: expected a bag file's path, got None"),
        ]
        # Nothing left behind: aurora.sweep's folders go to a temporary
        # directory of this test's own (the other tests share /tmp and run
        # sweeps at the same time: a clean clone's run once saw one of theirs).
        private = tempfile.mkdtemp(prefix="check_python_sweep_")
        shared, tempfile.tempdir = tempfile.tempdir, private
        try:
            expect_refusals(self, cases)
        finally:
            tempfile.tempdir = shared
        self.assertEqual(os.listdir(private), [])
        os.rmdir(private)


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "python_sweep", PythonSweepTest)
