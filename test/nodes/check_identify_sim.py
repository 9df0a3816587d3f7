#!/usr/bin/python3
"""identify_sim.test, identify_sim_pioneer.test, identify_sim_ardrone.test
(issue 52, item 3): a lockstep flight of a Bebop 2 (a drive of a Pioneer, a
flight of an AR.Drone) whose vehicle file
differs from the nominal one by -20 % .. +20 % (~vehicle_file), with a
feedback delay (~feedback) over a link whose downlink delay is ~actuation,
recorded; `rosrun aurora identify` finds both delays and the modified
parameters, writes a link file and a vehicle file that flight takes, and
aurora.identify returns the same (unless ~same_as_api is false: the tool is
that function, and the AR.Drone's fit would run twice); with ~bad_input, bad bags are refused
naming what is missing, with nothing written."""
import json
import os
import sys
import tempfile
import unittest

import rospy
import rostest
import yaml

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool  # noqa: E402
from tools import rosrun  # noqa: E402



def edited(bag, folder, name, last_step=None, vehicle=None, formation=False, drop=None, zero_commands=False):
    """A copy of `bag` cut after `last_step`, its Control.vehicle renamed, a
    formation topic added, a topic dropped, or every command sent zero."""
    import rosbag
    from aurora_msgs.msg import Formation
    path = os.path.join(folder, name + ".bag")
    with rosbag.Bag(bag) as src, rosbag.Bag(path, "w") as dst:
        for topic, msg, t in src.read_messages():
            if topic == drop or (last_step is not None and getattr(msg, "step", 0) > last_step):
                continue
            if topic.endswith("/control"):
                if vehicle:
                    msg.vehicle = vehicle
                if zero_commands:  # as sent and as applied
                    msg.command_sent = [0.0] * 4
                    msg.command = [0.0] * 4
            dst.write(topic, msg, t)
            if formation:
                dst.write("/formation/formation", Formation(), t)
                formation = False
    return path


class IdentifySimTest(unittest.TestCase):
    def test_identifies_the_delays_and_the_modified_vehicle(self):
        p = lambda name: rospy.get_param("~" + name)  # noqa: E731
        bag = record_until(p("steps"), p("bag_dir"), p("prefix"))
        out = tempfile.mkdtemp(prefix="identify_")
        rc, text = run_tool(rosrun("aurora", "identify") + [bag, "--out", out])
        self.assertEqual(rc, 0, text)
        self.assertIn("feedback delay %d samples, actuation delay %d samples" % (p("feedback"), p("actuation")), text)
        j = json.load(open(os.path.join(out, "identify.json")))
        modified = yaml.safe_load(open(p("vehicle_file")))
        self.assertEqual(j["vehicle"], modified["type"])
        self.assertEqual(j["feedback_delay_samples"], p("feedback"))
        self.assertEqual(j["actuation_delay_samples"], p("actuation"))
        for key, par in j["parameters"].items():
            group, name = key.split(".")
            want = modified[group][name]
            self.assertTrue(par["identified"], (key, par))
            self.assertLess(abs(par["value"] - want), 0.05 * abs(want), (key, par["value"], want, par["nominal"]))
            self.assertGreater(abs(par["nominal"] - want), 0.15 * abs(want), key)  # the nominal one is far off
        # The recorded commands flown open loop (2 s segments from the recorded states): the identified model
        # follows the recording (this flight's plant is the simulator's: to its rounding), the nominal not.
        rms = j["open_loop_rms"]
        for axis in ("x", "y", "yaw"):
            self.assertLess(rms["identified"][axis], 1e-6, (axis, rms))
            self.assertGreater(rms["nominal"][axis], 1e-4, (axis, rms))
        self.assertEqual(j["link"]["uplink"]["delay"], p("feedback"))
        self.assertEqual(j["link"]["downlink"]["delay"], p("actuation"))
        # The controller's own downlink (eq. I2c, from the commands' ages): its jitter exactly, its loss within
        # two standard errors (none: an ideal one's).
        jitter, loss = rospy.get_param("~downlink_jitter", 0), rospy.get_param("~downlink_loss", 0.0)
        self.assertEqual(j["link"]["downlink"].get("jitter", {"max": 0})["max"], jitter, j["link"])
        self.assertLessEqual(abs(j["downlink_loss"] - loss), 2 * (j["downlink_loss_stderr"] or 0.0) + 1e-9,
                             (j["downlink_loss"], j["downlink_loss_stderr"]))
        for f in ("link.yaml", "vehicle.yaml", "report.md", "timing.png", "fit.png"):
            self.assertTrue(os.path.isfile(os.path.join(out, f)), f)
        # The files are the product's own: flight takes them as they are.
        rc, text = run_tool(rosrun("aurora_control", "flight") + ["--vehicle", os.path.join(out, "vehicle.yaml"),
                             "--controller", p("controller"), "--task", p("task"),
                             "--link", os.path.join(out, "link.yaml")])
        self.assertEqual(rc, 0, text)
        if rospy.get_param("~same_as_api", True):
            import aurora
            self.assertEqual(aurora.identify(bag)["parameters"], j["parameters"])
        if p("study"):
            self.check_study(bag, p("study"))
        if p("bad_input"):
            self.check_bad_input(bag)

    def check_study(self, bag, study):
        """--study: the study as shipped and with the identified vehicle and link, side by side."""
        out = tempfile.mkdtemp(prefix="identify_study_")
        rc, text = run_tool(rosrun("aurora", "identify") + [bag, "--out", out, "--study", study])
        self.assertEqual(rc, 0, text)
        self.assertIn("identify: study %s.yaml: " % study, text)
        s = json.load(open(os.path.join(out, "identify.json")))["study"]
        identified = yaml.safe_load(open(s["sweep_file"]))["sweep"]
        self.assertEqual(identified["vehicle"], os.path.join(out, "vehicle.yaml"))
        self.assertEqual(identified["link"], os.path.join(out, "link.yaml"))
        self.assertEqual(s["nominal"]["combinations"], s["identified"]["combinations"])
        self.assertNotEqual(s["nominal"]["feasible"], s["identified"]["feasible"])  # the modified vehicle and link count
        for f in ("compare_max_tolerable_delay.png", "compare_feasible_share.png"):
            self.assertTrue(os.path.isfile(os.path.join(out, "study_compare", f)), f)
        for other, said in (("pioneer_delay", "flies a pioneer3dx, the bag a bebop2"),
                            ("triangle_delay", "is a formation's sweep"), ("no_such_study", "is neither a file")):
            refused = os.path.join(out, "refused")  # refused before the fit: nothing written
            rc, text = run_tool(rosrun("aurora", "identify") + [bag, "--out", refused, "--study", other])
            self.assertEqual(rc, 2, text)
            self.assertIn(said, text)
            self.assertFalse(os.path.exists(refused), other)

    def check_bad_input(self, bag):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            for name, edit, said in (
                    ("short", {"last_step": 200}, "holds 201 states of /bebop1 (6.7 s): identify needs 300"),
                    ("unknown", {"vehicle": "crazyflie"}, "vehicle 'crazyflie' (the bag's Control.vehicle) is unknown"),
                    ("formation", {"formation": True}, "is a formation's: identify one robot at a time with --ns"),
                    ("nostate", {"drop": "/bebop1/state"}, "lacks the topics identify needs: missing /bebop1/state")):
                rc, text = run_tool(rosrun("aurora", "identify") + [edited(bag, tmp, name, **edit), "--out", out])
                self.assertEqual(rc, 2, text)
                self.assertIn(said, text)
                self.assertFalse(os.path.exists(out), name)
            # A hover (no command moves the drone): the timing is measured, no parameter is identified and
            # no vehicle file is written; each parameter says why.
            rc, text = run_tool(rosrun("aurora", "identify") + [edited(bag, tmp, "hover", zero_commands=True),
                                 "--out", out])
            self.assertEqual(rc, 0, text)
            self.assertIn("nothing identifiable: input_gain.x: its axis was not excited", text)
            self.assertFalse(os.path.exists(os.path.join(out, "vehicle.yaml")))
            self.assertTrue(os.path.exists(os.path.join(out, "link.yaml")))
            out = os.path.join(tmp, "args")
            for args, said in (([os.path.join(tmp, "none.bag")], "does not exist"),
                               ([bag, "--ns", "ardrone7"], "missing /ardrone7/state"),
                               ([bag, "--max-delay", "-1"], "--max-delay -1 is refused"),
                               ([bag, "--window", "0"], "--window 0 is refused")):
                rc, text = run_tool(rosrun("aurora", "identify") + args + ["--out", out])
                self.assertEqual(rc, 2, text)
                self.assertIn(said, text)
                self.assertFalse(os.path.exists(os.path.join(out, "identify.json")), args)


if __name__ == "__main__":
    rospy.init_node("check_identify_sim")
    rostest.rosrun("aurora_tests", "identify_sim", IdentifySimTest)
