#!/usr/bin/python3
"""The sweep at scale: MPI ranks, resume after SIGKILL, HDF5 output, folder rules."""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from tools import rosrun  # noqa: E402

MPIRUN = shutil.which("mpirun")


def sweep_cmd(sweep_file, out, *extra):
    return rosrun("aurora_sweep", "sweep") + ["--config", sweep_file, "--out", out, "--quiet",
            "--no-plots"] + list(extra)


def run(cmd, timeout=180):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                       universal_newlines=True)
    return p.returncode, p.stdout


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def read(path):
    with open(path, "rb") as f:
        return f.read()


class SweepScaleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="aurora_sweep_scale_")
        config = rospy.get_param("~config_dir")
        cls.thesis = os.path.join(config, "sweeps", "positioning_delay.yaml")
        # The thesis grid's first 16 x 32 x 64 (kd halved): 32,768 runs, 8 chunks of 4096.
        cls.grid = os.path.join(cls.tmp, "grid.yaml")
        with open(cls.thesis) as f:
            text = f.read().replace("vehicles/ardrone2.yaml", os.path.join(config, "vehicles", "ardrone2.yaml"))
            text = text.replace("tasks/positioning.yaml", os.path.join(config, "tasks", "positioning.yaml"))
        with open(cls.grid, "w") as f:
            f.write(text.replace("kd: {from: 0.0, to: 1.0, count: 32}", "kd: {from: 0.0, to: 1.0, count: 16}"))
        cls.other = os.path.join(cls.tmp, "other.yaml")
        with open(cls.other, "w") as f:
            f.write(text.replace("kd: {from: 0.0, to: 1.0, count: 32}", "kd: {from: 0.0, to: 1.0, count: 8}"))
        cls.single = os.path.join(cls.tmp, "single")
        rc, log = run(sweep_cmd(cls.grid, cls.single, "--backend", "cpu", "--threads", "1",
                                "--chunk-size", "4096", "--output", "both"))
        assert rc == 0, log

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @unittest.skipIf(MPIRUN is None, "mpirun not installed (Debian: openmpi-bin)")
    def test_0_a_rank_that_cannot_start_stops_every_rank(self):
        # Rank 1's start check fails (as a failed device check would): the
        # others used to wait for it forever in a collective call.
        out = os.path.join(self.tmp, "mpi_fail")
        env = dict(os.environ, AURORA_SWEEP_TEST_FAIL_RANK="1")
        p = subprocess.run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-x", "AURORA_SWEEP_TEST_FAIL_RANK",
                            "-np", "3"] + sweep_cmd(self.grid, out, "--backend", "cpu", "--threads", "1"),
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120, universal_newlines=True,
                           env=env)
        self.assertNotEqual(p.returncode, 0, p.stdout)
        self.assertIn("sweep: rank 1 (", p.stdout)
        self.assertIn("the device check fails (forced by AURORA_SWEEP_TEST_FAIL_RANK", p.stdout)
        self.assertIn("1 of 3 ranks cannot start: every rank stops, nothing was written", p.stdout)
        self.assertFalse(os.path.exists(os.path.join(out, "progress")), p.stdout)

    @unittest.skipIf(MPIRUN is None, "mpirun not installed (Debian: openmpi-bin)")
    def test_0b_ranks_on_different_backends_are_refused_unless_asked(self):
        # Ranks that compute on different backends (auto on hosts with and
        # without a GPU) give chunks that agree to rounding only.
        out = os.path.join(self.tmp, "mpi_mixed")
        cmd = [MPIRUN, "--allow-run-as-root", "--oversubscribe", "-np", "2", "bash", "-c",
               'exec "$0" "$@" --backend $([ "$OMPI_COMM_WORLD_RANK" = 0 ] && echo scalar || echo cpu)',
               ] + sweep_cmd(self.grid, out, "--threads", "1", "--chunk-size", "4096")
        rc, log = run(cmd)
        self.assertNotEqual(rc, 0, log)
        self.assertIn("the ranks would compute on different backends (cpu", log)
        self.assertIn("scalar: rank 0", log)
        rc, log = run(cmd + ["--mixed-backends"])
        self.assertEqual(rc, 0, log)
        by = summary(out)["chunks"]["computed_by"]
        self.assertEqual(sum(by.values()), 8, by)
        self.assertTrue(all(k == "scalar" or k.startswith("cpu (") for k in by), by)

    @unittest.skipIf(MPIRUN is None, "mpirun not installed (Debian: openmpi-bin)")
    def test_1_mpi_ranks_give_the_single_process_result(self):
        out = os.path.join(self.tmp, "mpi")
        # as root in CI: OpenMPI refuses root without --allow-run-as-root
        rc, log = run([MPIRUN, "--allow-run-as-root", "--oversubscribe", "-np", "3"] +
                      sweep_cmd(self.grid, out, "--backend", "cpu", "--threads", "1", "--chunk-size", "4096",
                                "--output", "both"))
        self.assertEqual(rc, 0, log)
        self.assertEqual(read(os.path.join(out, "results.csv")), read(os.path.join(self.single, "results.csv")))
        s = summary(out)
        self.assertEqual(s["mpi"]["ranks"], 3)
        ranks = s["mpi"]["per_rank"]
        self.assertEqual(sorted(r["rank"] for r in ranks), [0, 1, 2])
        self.assertEqual(sum(r["chunks_computed"] for r in ranks), 8)
        self.assertEqual(sum(r["combinations"] for r in ranks), 32768)
        self.assertEqual(s["chunks"]["computed"], 8)
        self.assertFalse(os.path.exists(os.path.join(out, "progress")))

    def test_2_a_killed_run_resumes_with_only_the_missing_chunks(self):
        out = os.path.join(self.tmp, "killed")
        proc = subprocess.Popen(sweep_cmd(self.grid, out, "--backend", "scalar", "--chunk-size", "4096",
                                          "--output", "both"), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        progress = os.path.join(out, "progress")
        deadline = time.time() + 60
        while time.time() < deadline:
            done = [f for f in os.listdir(progress) if f.endswith(".bin")] if os.path.isdir(progress) else []
            if len(done) >= 2:
                break
            time.sleep(0.01)
        proc.send_signal(signal.SIGKILL)  # rosrun execs the sweep: this is the sweep itself
        proc.wait(timeout=10)
        before = sorted(f for f in os.listdir(progress) if f.endswith(".bin"))
        self.assertGreaterEqual(len(before), 2)
        self.assertLess(len(before), 8, "the run finished before it was killed")
        self.assertEqual([f for f in os.listdir(progress) if ".tmp" in f and f in before], [])
        rc, log = run(sweep_cmd(self.grid, out, "--backend", "scalar", "--chunk-size", "4096", "--output", "both"))
        self.assertEqual(rc, 0, log)
        s = summary(out)
        self.assertEqual(s["chunks"]["resumed"], len(before))
        self.assertEqual(s["chunks"]["computed"], 8 - len(before))
        self.assertEqual(s["chunks"]["computed_combinations"], 32768 - 4096 * len(before))
        # scalar and cpu agree to 1e-13, not in every digit: compare with a scalar run
        fresh = os.path.join(self.tmp, "uninterrupted")
        rc, log = run(sweep_cmd(self.grid, fresh, "--backend", "scalar", "--chunk-size", "4096", "--output", "both"))
        self.assertEqual(rc, 0, log)
        self.assertEqual(read(os.path.join(out, "results.csv")), read(os.path.join(fresh, "results.csv")))

    def test_3_hdf5_equals_csv(self):
        import h5py
        with open(os.path.join(self.single, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        with h5py.File(os.path.join(self.single, "results.h5"), "r") as h5:
            self.assertEqual(len(h5["index"]), len(rows))
            cols = {k: h5[k][...] for k in rows[0]}
        for k in rows[0]:
            parse = float if k in ("kp", "kd", "iae", "itae", "iasc", "x", "y", "z") else int
            values = [parse(r[k]) for r in rows]
            got = cols[k].tolist()
            if k in ("x", "y", "z"):
                # float32 columns, written as the shortest text that reads back to the same float: the
                # CSV's number read as a float32 is the HDF5's, bit for bit.
                import numpy as np
                values = np.array([r[k] for r in rows], dtype=np.float32).tolist()
            self.assertEqual(got, values, "column %s differs" % k)

    def test_4_another_sweep_in_a_used_folder_is_refused(self):
        rc, log = run(sweep_cmd(self.other, self.single, "--backend", "cpu"))
        self.assertEqual(rc, 2, log)
        self.assertIn("holds another sweep", log)
        self.assertIn("--overwrite", log)
        self.assertTrue(os.path.exists(os.path.join(self.single, "results.h5")), "the refused run removed files")

    def test_5_a_reused_folder_keeps_no_old_outputs(self):
        out = os.path.join(self.tmp, "reused")
        rc, log = run(sweep_cmd(self.grid, out, "--backend", "cpu", "--output", "both"))
        self.assertEqual(rc, 0, log)
        rc, log = run(sweep_cmd(self.other, out, "--backend", "cpu", "--overwrite", "--output", "csv",
                                "--rows", "feasible"))
        self.assertEqual(rc, 0, log)
        self.assertFalse(os.path.exists(os.path.join(out, "results.h5")), "an old results.h5 stayed")
        s = summary(out)
        with open(os.path.join(out, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), s["feasible"])
        self.assertTrue(all(r["feasible"] == "1" for r in rows))
        self.assertEqual(s["output"]["files"]["results.csv"]["rows"], s["feasible"])


if __name__ == "__main__":
    rospy.init_node("check_sweep_scale")
    rostest.rosrun("aurora_tests", "sweep_scale", SweepScaleTest)
