#!/usr/bin/python3
"""report and replay on a bag recorded from a rostest run of the mission."""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospy
import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import frames_moved, record_until  # noqa: E402
from tools import rosrun  # noqa: E402

BAG = None


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=180)
    return p.returncode, p.stdout.decode(errors="replace")


class ReportReplayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        global BAG
        if BAG is None:
            BAG = record_until(rospy.get_param("~steps"), rospy.get_param("~bag_dir"), rospy.get_param("~prefix"))
        cls.bag = BAG
        cls.tmp = tempfile.mkdtemp(prefix="aurora_report_test_")

    def test_1_report_writes_figures_video_and_controller_metrics(self):
        out = os.path.join(self.tmp, "report")
        rc, log = run(rosrun("aurora", "report") + [self.bag, "--out", out])
        self.assertEqual(rc, 0, log)
        self.assertNotIn("Traceback", log)
        metrics = json.load(open(os.path.join(out, "metrics.json")))
        self.assertEqual(len(metrics["drones"]), 1)
        m = metrics["drones"][0]
        self.assertEqual(m["namespace"], "/ardrone1")
        # The report's metrics equal those the controller computed during the run.
        self.assertTrue(m["metrics_match_controller"], m)
        self.assertEqual(m["iae"], m["controller_iae"])
        self.assertEqual(m["itae"], m["controller_itae"])
        self.assertEqual(m["iasc"], m["controller_iasc"])
        self.assertGreater(m["iae"], 0.5)
        self.assertEqual(m["delay_samples"], 6)
        self.assertAlmostEqual(m["state_rate_hz"], 30.0, places=3)
        # The bag holds at least 20 s of the mission (waypoints 1 and 2); on a busy
        # machine the recorder may take a few steps more before it closes, so the
        # segments are those the bag reaches: waypoint i + 1 once t > end_times[i].
        self.assertGreaterEqual(m["duration_s"], 20.0 - 1e-9)
        reached = 1 + sum(1 for end in (15.0, 30.0, 45.0) if m["duration_s"] > end + 1e-9)
        self.assertEqual(len(m["segments"]), reached, m["duration_s"])
        self.assertEqual([s["waypoint_index"] for s in m["segments"]], list(range(reached)))
        for name in ("route3d", "position", "attitude", "velocities", "commands"):
            for ext in ("png", "pdf"):
                path = os.path.join(out, "ardrone1_%s.%s" % (name, ext))
                self.assertTrue(os.path.exists(path), path)
                self.assertGreater(os.path.getsize(path), 10000, path)
        video = os.path.join(out, "ardrone1_flight.mp4")
        self.assertGreater(os.path.getsize(video), 20000)
        rc, frames = run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                          "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0", video])
        self.assertEqual(rc, 0, frames)
        expected = int(math.floor(m["duration_s"] * 10.0 + 1e-9)) + 1  # 10 fps of flight time
        self.assertEqual(int(frames.strip()), expected)
        self.assertEqual(m["video_frames"], expected)
        self.assertGreater(frames_moved(video, expected), 500)  # the drone, its trail and the clock drawn
        md = open(os.path.join(out, "report.md")).read()
        self.assertIn("ardrone1_route3d.png", md)
        self.assertIn("IAE", md)
        # 20 s of the 60 s mission were recorded: the report says so.
        self.assertFalse(m["task_complete"])
        self.assertEqual(m["task_duration_s"], 60.0)
        recorded = m["task_time_recorded_s"][1] - m["task_time_recorded_s"][0]
        self.assertAlmostEqual(recorded, m["duration_s"], places=6)
        self.assertIn("TRUNCATED: only %.1f s of the 60.0 s task were recorded" % recorded, md)
        self.assertIn("warning: TRUNCATED", log)

    def test_2_replay_same_configuration_is_identical(self):
        rc, log = run(rosrun("aurora_control", "replay") + [self.bag, "--expect-identical"])
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)

    def test_3_replay_with_another_delay_differs(self):
        csv_path = os.path.join(self.tmp, "replay.csv")
        rc, log = run(rosrun("aurora_control", "replay") + [self.bag, "--delay", "2", "--out", csv_path])
        self.assertEqual(rc, 0, log)
        self.assertIn("(changed configuration)", log)
        rows = open(csv_path).read().splitlines()[1:]
        differing = [r for r in rows if float(r.split(",")[-1]) > 0]
        self.assertGreater(len(differing), len(rows) // 2, log)
        rc, _ = run(rosrun("aurora_control", "replay") + [self.bag, "--delay", "2", "--expect-identical"])
        self.assertEqual(rc, 1)

    def test_3b_replay_delay_not_shorter_than_the_task_is_refused(self):
        # The recorded task (mission4, 60 s = 1801 iterations) bounds the delay
        # as in the node and the sweep.
        rc, log = run(rosrun("aurora_control", "replay") + [self.bag, "--delay", "2000"])
        self.assertEqual(rc, 2, log)
        self.assertIn("--delay: 2000 samples is not shorter than the run's 1801 steps", log)
        rc, log = run(rosrun("aurora_control", "replay") + [self.bag, "--delay", "1800"])
        self.assertEqual(rc, 0, log)

    def test_4_bag_without_control_is_refused(self):
        stripped = os.path.join(self.tmp, "no_control.bag")
        with rosbag.Bag(self.bag) as src, rosbag.Bag(stripped, "w") as dst:
            for topic, msg, t in src.read_messages():
                if not topic.endswith("/control"):
                    dst.write(topic, msg, t)
        rc, log = run(rosrun("aurora", "report") + [stripped, "--no-video"])
        self.assertEqual(rc, 2, log)
        self.assertIn("missing /ardrone1/control", log)
        self.assertIn("present: ", log)
        self.assertIn("/ardrone1/state", log)
        self.assertNotIn("Traceback", log)
        rc, log = run(rosrun("aurora_control", "replay") + [stripped])
        self.assertEqual(rc, 2, log)

    def test_5_truncated_bag_is_refused(self):
        truncated = os.path.join(self.tmp, "truncated.bag")
        with open(self.bag, "rb") as f:
            data = f.read()
        with open(truncated, "wb") as f:
            f.write(data[: len(data) // 2])
        rc, log = run(rosrun("aurora", "report") + [truncated, "--no-video"])
        self.assertEqual(rc, 2, log)
        self.assertIn("report: error:", log)
        self.assertIn("reindex", log)
        self.assertNotIn("Traceback", log)
        rc, log = run(rosrun("aurora_control", "replay") + [truncated])
        self.assertEqual(rc, 2, log)
        self.assertIn("cannot be read", log)

    def test_6_two_drones_give_two_sections(self):
        two = os.path.join(self.tmp, "two_drones.bag")
        with rosbag.Bag(self.bag) as src, rosbag.Bag(two, "w") as dst:
            for topic, msg, t in src.read_messages():
                dst.write(topic, msg, t)
                if topic.startswith("/ardrone1/"):
                    dst.write(topic.replace("/ardrone1/", "/ardrone2/"), msg, t)
        out = os.path.join(self.tmp, "two")
        rc, log = run(rosrun("aurora", "report") + [two, "--out", out, "--no-video", "--no-pdf"])
        self.assertEqual(rc, 0, log)
        drones = json.load(open(os.path.join(out, "metrics.json")))["drones"]
        self.assertEqual([d["namespace"] for d in drones], ["/ardrone1", "/ardrone2"])
        md = open(os.path.join(out, "report.md")).read()
        self.assertIn("## /ardrone1", md)
        self.assertIn("## /ardrone2", md)
        self.assertTrue(os.path.exists(os.path.join(out, "ardrone2_position.png")))
        rc, log = run(rosrun("aurora_control", "replay") + [two])
        self.assertEqual(rc, 2, log)
        self.assertIn("--ns", log)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)


if __name__ == "__main__":
    rospy.init_node("check_report_replay")
    rostest.rosrun("aurora_tests", "report_replay", ReportReplayTest)
