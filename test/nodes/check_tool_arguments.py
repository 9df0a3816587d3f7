#!/usr/bin/python3
"""replay and flight refuse what the node refuses, with the same limits
(limits.h): gains outside [0, 10], two delays, two clamp choices, a delay
beyond 2047 or not shorter than the task."""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from tools import rosrun  # noqa: E402


def config_dir():
    return subprocess.run(["rospack", "find", "aurora_config"], stdout=subprocess.PIPE).stdout.decode().strip()


def flight(*args):
    p = subprocess.run(rosrun("aurora_control", "flight") + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, timeout=120)
    return p.returncode, p.stdout.decode(errors="replace")


def formation_file(folder, edit, name="line_lemniscate"):
    """config/formations/NAME.yaml with `edit` (old, new) applied."""
    text = open(os.path.join(config_dir(), "formations", name + ".yaml")).read()
    assert edit[0] in text, edit
    path = os.path.join(folder, "formation.yaml")
    with open(path, "w") as f:
        f.write(text.replace(edit[0], edit[1]))
    return path


def replay(*args):
    p = subprocess.run(rosrun("aurora_control", "replay") + ["/nonexistent.bag"] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    return p.returncode, p.stdout.decode(errors="replace")


class ToolArgumentsTest(unittest.TestCase):
    def assert_refused(self, args, text):
        rc, out = replay(*args)
        self.assertEqual(rc, 2, out)
        self.assertIn(text, out)
        self.assertNotIn("cannot", out.split(text)[0][-40:])  # refused before the bag is opened

    def test_negative_gain(self):
        self.assert_refused(["--kp", "-1"], "--kp -1 is outside the accepted range [0, 10]")

    def test_gain_above_range(self):
        self.assert_refused(["--kd", "12"], "--kd 12 is outside the accepted range [0, 10]")

    def test_two_delays(self):
        self.assert_refused(["--delay", "5", "--delay-seconds", "0.2"], "--delay and --delay-seconds exclude each other")

    def test_two_clamp_choices(self):
        self.assert_refused(["--clamp", "--no-clamp"], "--clamp and --no-clamp exclude each other")

    def test_a_predictor_block_for_replay(self):
        # Issue 35: replay follows the predictor the bag records; a file's block would be a second source.
        self.assert_refused(["--controller", config_dir() + "/controllers/pd_saturated_predictor.yaml"],
                            "its 'predictor' block is refused here: replay follows the predictor the bag's Control")

    def test_shipped_names_as_flight_takes_them(self):
        # Issue 51 (8): replay --controller NAME read config/controllers/NAME.yaml ("cannot be read" before).
        self.assert_refused(["--controller", "pd_saturated_predictor"],
                            "/controllers/pd_saturated_predictor.yaml: its 'predictor' block is refused here")
        rc, out = replay("--controller", "pd_saturated", "--link", "wifi_lab")
        self.assertIn("bag '/nonexistent.bag' does not exist", out)

    def test_the_kernels_register_table_reads_todays_names(self):
        """Issue 51 (9): bench/cuda_registers.sh printed its header only (the kernels' names had changed).
        Its table, on ptxas output of today's kernels (a single robot's and a formation's, test/data), names
        each instantiation; output with no sweep kernel fails instead of printing an empty table."""
        root = os.path.abspath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))
        table = os.path.join(root, "bench", "ptxas_table.py")
        if not os.path.exists(table):  # run from an install space
            self.skipTest("no source tree next to this script")
        with open(os.path.join(root, "test", "data", "ptxas_sample.log")) as log:
            p = subprocess.run(["python3", table], stdin=log, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               universal_newlines=True)
        self.assertEqual(p.returncode, 0, p.stdout)
        rows = p.stdout.splitlines()
        self.assertEqual(rows[1].split(), ["ArdroneLaw<underactuated>", "-", "float", "512", "model", "no", "227",
                                           "41328", "0/0"], p.stdout)
        self.assertEqual(rows[2].split(), ["ArdroneLaw<underactuated>", "LineFormation", "float", "512", "model", "no",
                                           "255", "85280", "260/260"], p.stdout)
        self.assertEqual(rows[3], "2 kernel instantiations")
        p = subprocess.run(["python3", table], input="ptxas info    : Compiling entry function '_Z6helperv' for 'sm_90'\n"
                           "ptxas info    : Used 8 registers\n", stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           universal_newlines=True)
        self.assertEqual(p.returncode, 1, p.stdout)
        self.assertIn("no sweep kernel (sweepKernel, formationKernel) among the 1 entry functions", p.stdout)

    def test_delay_beyond_the_node_limit(self):
        self.assert_refused(["--delay", "2048"], "--delay 2048 is refused: accepted integer samples in [0, 2047]")


    def test_missing_bag_is_named_as_missing(self):
        rc, out = replay()
        self.assertEqual(rc, 2, out)
        self.assertIn("bag '/nonexistent.bag' does not exist", out)
        self.assertNotIn("still recording", out)

    def test_flight_refuses_a_delay_not_shorter_than_the_task(self):
        # It flew such a delay as no delay at all; node, replay, sweep refuse it.
        for task, delay, longest in (("mission4", 2000, 1800), ("circle", 1201, 1200)):
            rc, out = flight("--delay", str(delay), "--task", config_dir() + "/tasks/%s.yaml" % task)
            self.assertEqual(rc, 2, out)
            self.assertIn("--delay %d samples is not shorter than the run's %d steps" % (delay, longest + 1), out)
            self.assertIn("accepted delays up to %d samples" % longest, out)

    def test_flight_refuses_a_negative_delay_by_its_limits(self):
        # A value starting with '-' is the option's value, not an unknown option.
        cfg = config_dir()
        for args, said in ((["--delay", "-4"], "--delay -4 is refused: accepted integer samples in [0, 2047]"),
                           (["--formation", cfg + "/formations/line_lemniscate.yaml", "--delay", "3", "-4"],
                            "--delay -4 (drone 2) is refused: accepted integer samples in [0, 2047]")):
            p = subprocess.run(rosrun("aurora_control", "flight") + args, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, timeout=60)
            out = p.stdout.decode(errors="replace")
            self.assertEqual(p.returncode, 2, out)
            self.assertIn(said, out)
            self.assertNotIn("unrecognised option", out)


class FormationAndLinkArgumentsTest(unittest.TestCase):
    """Issue 31: what flight, the formation files and the sweep program
    refused or did silently wrong."""

    def refused(self, args, *texts):
        rc, out = flight(*args)
        self.assertEqual(rc, 2, out)
        for t in texts:
            self.assertIn(t, out)

    def test_a_level_or_buried_formation_start_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            for edit, said in ((("start: [1.0, 0.0, 1.0]", "start: [1.0, 0.0, 0.75]"), "0 m apart in height"),
                               (("start: [1.0, 0.0, 1.0]", "start: [-1.0, 0.0, 0.75]"), "0 m apart and 0 m apart"),
                               (("start: [1.0, 0.0, 1.0]", "start: [1.0, 0.0, -0.2]"), "has z = -0.2 m, below the ground")):
                self.refused(["--formation", formation_file(tmp, edit)], said)
            # Issue 51 (7): one start check for every shape (the triangle took z = -1 m).
            self.refused(["--formation", formation_file(tmp, ("[0.0, 1.0, 0.75]]", "[0.0, 1.0, -1.0]]"), "triangle_ardrones")],
                         "'formation.robots.starts[2]' = [0, 1, -1] has z = -1 m, below the ground: accepted heights [0, 100] m")
            self.refused(["--formation", formation_file(tmp, ("[0.0, 1.0, 0.0]]", "[0.0, 1.0, -1.0]]"), "triangle_kinematic")],
                         "'formation.robots.starts[2]' = [0, 1, -1] has z = -1 m, below the ground")
            self.refused(["--formation", formation_file(tmp, ("start: [0.0, 0.0, 0.75]", "start: [0.0, 0.0, -1.0]"),
                                                        "line_pioneer_ardrone")],
                         "'formation.robots[1].start' = [0, 0, -1] has z = -1 m, below the ground: accepted heights [0, 100] m")

    def test_a_formation_too_short_to_judge_is_refused_on_every_shape(self):
        """Issue 51 (2): the checks judge from 10 s on; a 5 s UAV-UGV line or triangle printed RMS 0 and feasible."""
        with tempfile.TemporaryDirectory() as tmp:
            for name, edit, key in (("triangle_ardrones", ("duration: 50", "duration: 5"), "formation.duration"),
                                    ("triangle_kinematic", ("duration: 50", "duration: 0.01"), "formation.duration"),
                                    ("line_pioneer_ardrone", ("duration: 130", "duration: 5"), "formation.duration"),
                                    ("line_lemniscate", ("duration: 90", "duration: 10"), "formation.reference.duration")):
                value = edit[1].split(": ")[1]
                self.refused(["--formation", formation_file(tmp, edit, name)],
                             "'%s' = %s s is refused: the formation checks judge a flight from 10 s on" % (key, value),
                             "accepted durations > 10 s")
            # Past 10 s but short of 20 s: the RMS window is empty, and flight says so instead of printing 0.
            for name, edit in (("triangle_ardrones", ("duration: 50", "duration: 15")),
                               ("line_pioneer_ardrone", ("duration: 130", "duration: 15"))):
                rc, out = flight("--formation", formation_file(tmp, edit, name))
                self.assertEqual(rc, 0, out)
                self.assertIn("RMS after 20 s: none, the flight ends at 15 s", out)
                self.assertNotIn("0.0000", out)

    def test_a_formation_robots_predictor_is_flown_not_dropped(self):
        """Issue 51 (1): a formation robot's controller file with a predictor flew the plain law in silence."""
        def rms(*args):
            rc, out = flight("--formation", *args)
            self.assertEqual(rc, 0, out)
            return [line for line in out.splitlines() if "RMS after" in line or "rho" in line]
        # The exact model predicts the present: the delayed triangle flies as the undelayed one.
        self.assertEqual(rms("triangle_ardrones_predictor", "--delay", "6", "6", "6"),
                         rms("triangle_ardrones", "--delay", "0", "0", "0"))
        self.assertNotEqual(rms("triangle_ardrones", "--delay", "6", "6", "6"),
                            rms("triangle_ardrones", "--delay", "0", "0", "0"))
        with tempfile.TemporaryDirectory() as tmp:
            with_predictor = formation_file(tmp, ("controller: *lab_gains", "controller: controllers/underactuated_predictor.yaml"),
                                            "line_lemniscate_ik")
            predicted = rms(with_predictor, "--delay", "6", "6")
            plain = rms(formation_file(tmp, ("controller: *lab_gains", "controller: controllers/underactuated.yaml"),
                                       "line_lemniscate_ik"), "--delay", "6", "6")
            self.assertNotEqual(predicted, plain)

    def test_a_formation_too_short_to_judge_or_with_a_delay_beyond_it_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            for duration in ("0.01", "10"):
                self.refused(["--formation", formation_file(tmp, ("duration: 90", "duration: " + duration))],
                             "'formation.reference.duration' = %s s" % duration, "accepted durations > 10 s")
            # 12 s: 360 ticks; a drone's delay of 400 samples would never reach its law.
            text = open(formation_file(tmp, ("duration: 90", "duration: 12"))).read()
            last = text.rfind("delay: 0")
            path = os.path.join(tmp, "late.yaml")
            with open(path, "w") as f:
                f.write(text[:last] + "delay: 400" + text[last + len("delay: 0"):])
            self.refused(["--formation", path], "formation.drones[1].delay = 400 samples is not shorter than the run's 360")
            self.refused(["--formation", formation_file(tmp, ("duration: 90", "duration: 12")), "--delay", "3", "400"],
                         "--delay (drone 2) = 400 samples is not shorter than the run's 360")

    def test_flight_options_a_formation_ignored_are_refused(self):
        f = os.path.join(config_dir(), "formations", "line_lemniscate.yaml")
        self.refused(["--formation", f, "--link", os.path.join(config_dir(), "links", "wifi_lab.yaml")],
                     "--link is refused with --formation")
        self.refused(["--formation", f, "--link", "/missing.yaml"], "--link is refused with --formation")
        self.refused(["--formation", f, "--no-clamp"], "--no-clamp is refused with --formation")
        link = os.path.join(config_dir(), "links", "wifi_lab.yaml")
        # Each shape's file names its robots' links and controllers its own way.
        for name, link_key, controller_key in (
                ("line_lemniscate", "formation.drones[i].link", "formation.drones[i].controller"),
                ("triangle_ardrones", "formation.robots.links (one file per drone)", "formation.robots.controller"),
                ("line_pioneer_ardrone", "formation.robots[i].link", "formation.robots[i].controller")):
            f = os.path.join(config_dir(), "formations", name + ".yaml")
            self.refused(["--formation", f, "--link", link], "--link is refused with --formation", link_key)
            self.refused(["--formation", f, "--controller", "underactuated"], "--controller is refused", controller_key)
            # The line's file names no vehicle (--vehicle is its drones'); the other shapes' files name theirs.
            shape = {"triangle_ardrones": "triangle", "line_pioneer_ardrone": "uav_ugv_line"}.get(name)
            if shape:
                self.refused(["--formation", f, "--vehicle", "ardrone2"], "--vehicle is refused with --formation",
                             "shape '%s' names its robots' vehicles" % shape)
        self.refused(["--formation", os.path.join(config_dir(), "formations", "line_pioneer_ardrone.yaml"), "--law", "N"],
                     "the UAV-UGV line has one law")

    def test_a_delay_beside_a_link_replaces_its_uplink_delay(self):
        link = os.path.join(config_dir(), "links", "wifi_lab.yaml")  # uplink delay 1
        for args, said in ((["--delay", "3"], "delay 3 samples (given; replaces the link's uplink delay 1)"),
                           (["--delay", "0"], "delay 0 samples (given; replaces the link's uplink delay 1)"),
                           ([], "delay 1 samples (the link's uplink delay)")):
            rc, out = flight("--link", link, *args)
            self.assertEqual(rc, 0, out)
            self.assertIn(said, out)
            self.assertIn("link '%s' (uplink delay 1" % link, out)

    def test_a_jitter_beyond_the_run_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            link = os.path.join(tmp, "late.yaml")
            with open(link, "w") as f:
                f.write("link:\n  uplink: {delay: 0, jitter: {kind: uniform, max: 1900}}\n")
            self.refused(["--link", link], "--link %s: its latest packet" % link,
                         "1900 samples is not shorter than the run's 1801 steps")

    def test_link_paths_that_are_no_file_are_named(self):
        self.refused(["--link", config_dir()], "link file '%s' is a folder" % config_dir())
        self.refused(["--link", ""], "--link '' is refused")

    def test_a_key_given_twice_is_refused_naming_both_lines(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "pd.yaml")
            with open(path, "w") as f:
                f.write("controller:\n  name: pd_saturated\n  kp: 0.5\n  kd: 0.85\n  kp: 0.7\n")
            self.refused(["--controller", path], "'controller.kp' is given twice, on lines 3 and 5")

    def test_a_vehicle_file_says_which_vehicle_it_describes(self):
        """Issue 32: a vehicle file's `type:` is read first, by flight as by the nodes."""
        text = open(os.path.join(config_dir(), "vehicles", "ardrone2.yaml")).read()
        with tempfile.TemporaryDirectory() as tmp:
            for old, new, said in (("type: ardrone2", "", "lacks the key 'type'"),
                                   ("type: ardrone2", "type: bebop", "type 'bebop' is not a vehicle this build knows")):
                path = os.path.join(tmp, "vehicle.yaml")
                with open(path, "w") as f:
                    f.write(text.replace(old, new))
                self.refused(["--vehicle", path], "vehicle file '%s'" % path, said, "accepted: ardrone2")

    def test_the_controller_chooses_the_vehicle_and_a_mismatch_is_refused(self):
        """Issue 33: the Bebop 2's compensator flies config/vehicles/bebop2.yaml by default; either
        law given the other vehicle's file is refused naming both types; its rate must divide 30 Hz."""
        c = config_dir()
        bebop = os.path.join(c, "controllers", "bebop2_compensator.yaml")
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "bebop.csv")
            rc, out = flight("--controller", bebop, "--task", os.path.join(c, "tasks", "lemniscate.yaml"),
                             "--csv", csv)
            self.assertEqual(rc, 0, out)
            self.assertIn("flight: bebop2_compensator at 30 Hz, lemniscate task of 60.0 s", out)
            rows = open(csv).read().splitlines()
            self.assertEqual(len(rows), 1 + 1801)
            lap2 = float(out.split("lap 2: RMS tracking error ")[1].split(" m")[0])
            self.assertLess(lap2, 0.01, out)  # it tracks the figure-eight (its model is the plant)
            self.refused(["--controller", bebop, "--vehicle", os.path.join(c, "vehicles", "ardrone2.yaml")],
                         "is of type 'ardrone2', but the controller 'bebop2_compensator' flies type 'bebop2'",
                         "config/vehicles/bebop2.yaml")
            self.refused(["--vehicle", os.path.join(c, "vehicles", "bebop2.yaml")],
                         "is of type 'bebop2', but the controller 'pd_saturated' flies type 'ardrone2'",
                         "config/vehicles/ardrone2.yaml")
            path = os.path.join(tmp, "slow.yaml")
            with open(path, "w") as f:
                f.write(open(bebop).read().replace("rate: 30 ", "rate: 7 "))
            self.refused(["--controller", path], "'controller.rate' = 7 Hz does not divide the vehicle's 30 Hz",
                         "accepted 30, 15, 10, 7.5, 6, 5")
        # Shipped files by NAME; --rate instead of the file's, refused where no law has a rate of its own.
        rc, out = flight("--controller", "bebop2_compensator", "--task", "bebop2_lemniscate", "--rate", "5")
        self.assertEqual(rc, 0, out)
        self.assertIn("flight: bebop2_compensator at 5 Hz, lemniscate task of 60.0 s", out)
        self.refused(["--controller", "bebop2_compensator", "--rate", "7"], "--rate 7 Hz does not divide")
        self.refused(["--controller", "underactuated", "--rate", "10"], "--rate is refused here")

    def test_the_bebop_scenarios_fly_as_the_spec_computed(self):
        """Issue 33: the standard waypoint scenario's first step, unclamped (AuRoRA's simulation), through
        flight: the compensator's command and the state after one step are the values of AuRoRA's code."""
        c = config_dir()
        bebop = os.path.join(c, "controllers", "bebop2_compensator.yaml")
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "wp.csv")
            rc, out = flight("--controller", bebop, "--task", os.path.join(c, "tasks", "bebop2_waypoints.yaml"),
                             "--no-clamp", "--csv", csv)
            self.assertEqual(rc, 0, out)
            rows = [r.split(",") for r in open(csv).read().splitlines()]
            col = {name: i for i, name in enumerate(rows[0])}
            self.assertEqual(len(rows), 1 + 901)  # steps 0..900 of 30 s
            self.assertAlmostEqual(float(rows[1][col["u3"]]), -5.8913868868668304, places=12)
            for u in ("u1", "u2", "u4"):
                self.assertEqual(float(rows[1][col[u]]), 0.0)
            self.assertAlmostEqual(float(rows[2][col["z"]]), 0.72403862178520684, places=14)
            self.assertAlmostEqual(float(rows[2][col["dz"]]), -0.77884134644379499, places=14)
            # It reaches each waypoint; the second one's yaw (pi/2) is the reference from step 120 (4 s).
            self.assertEqual([float(rows[1 + k][col["xd"]]) for k in (119, 120)], [0.0, 0.5])
            psi = float(rows[1 + 239][col["psi"]])
            self.assertAlmostEqual(psi, 1.5707963267948966, places=2)
            rc, out = flight("--controller", bebop, "--task", os.path.join(c, "tasks", "bebop2_lemniscate.yaml"))
            self.assertEqual(rc, 0, out)
            lap2 = float(out.split("lap 2: RMS tracking error ")[1].split(" m")[0])
            self.assertLess(lap2, 0.01, out)

    def test_the_pioneer_drives_the_specs_scenario(self):
        """Issue 33: flight --controller pioneer_dynamic --task pioneer_lemniscate flies the Pioneer P3-DX
        (its vehicle by default): the CSV names its 14 states and 2 commands; the first command and the
        state after one step are the values of AuRoRA's code; it tracks within 5 cm after 20 s. A drone's
        task, a take-off height, --no-clamp and --rate are refused naming why."""
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "pioneer.csv")
            rc, out = flight("--controller", "pioneer_dynamic", "--task", "pioneer_lemniscate", "--csv", csv)
            self.assertEqual(rc, 0, out)
            self.assertIn("flight: pioneer_dynamic, lemniscate task of 125.7 s", out)
            rows = [r.split(",") for r in open(csv).read().splitlines()]
            self.assertEqual(rows[0], ["step", "t", "x", "y", "z", "phi", "theta", "psi", "dx", "dy", "dz", "dphi",
                                       "dtheta", "dpsi", "u", "omega", "u1", "u2", "xd", "yd", "zd", "error"])
            self.assertEqual(len(rows), 1 + 1258)  # k = 0..1257: AuRoRA's 0..1256 and one more
            col = {name: i for i, name in enumerate(rows[0])}
            first, second = rows[1], rows[2]
            self.assertEqual(float(first[col["x"]]), 0.15)  # rSetPose([0 0 0 0]): the control point a ahead
            self.assertAlmostEqual(float(first[col["u1"]]), 0.05843564625337886, places=14)
            self.assertEqual(float(first[col["u2"]]), 1.0)  # omega_ref saturates
            for name, value in (("x", 0.15109471049556722), ("y", 0.0069188191881918827),
                                ("psi", 0.046125461254612553), ("u", 0.010947104955672323),
                                ("omega", 0.46125461254612549)):
                self.assertAlmostEqual(float(second[col[name]]), value, places=14, msg=name)
            after20 = [float(r[col["error"]]) for r in rows[1:] if float(r[col["t"]]) > 20.0]
            self.assertLess(max(after20), 0.05)
        rc, out = flight("--controller", "pioneer_kinematic", "--task", "pioneer_lemniscate")
        self.assertEqual(rc, 0, out)
        self.assertIn("flight: pioneer_kinematic", out)
        with tempfile.TemporaryDirectory() as tmp:  # refused before anything is written
            csv = os.path.join(tmp, "never.csv")
            self.refused(["--controller", "pioneer_dynamic", "--task", "lemniscate", "--csv", csv],
                         "'task.height' = 1.5 is outside the accepted range [0, 0] m (a ground robot's task lies on "
                         "the floor)")
            self.assertFalse(os.path.exists(csv))
        self.refused(["--controller", "pioneer_dynamic", "--task", "mission4"],
                     "'task.waypoints[0]' has z = 1.5 m: accepted heights [0, 0] m")
        self.refused(["--controller", "pd_saturated", "--task", "pioneer_lemniscate"],
                     "'task.height' = 0 is outside the accepted range [0.2, 100] m")
        self.refused(["--controller", "pioneer_dynamic", "--task", "pioneer_lemniscate", "--no-clamp"],
                     "--no-clamp is refused for the Pioneer P3-DX")
        self.refused(["--controller", "pioneer_dynamic", "--task", "pioneer_lemniscate", "--rate", "5"],
                     "--rate is refused here")
        self.refused(["--controller", "pioneer_dynamic", "--task", "pioneer_lemniscate", "--vehicle", "bebop2"],
                     "is of type 'bebop2', but the controller 'pioneer_dynamic' flies type 'pioneer3dx'")

    def test_the_uav_ugv_line_flies_as_auroras(self):
        """Issue 34: flight --formation line_pioneer_ardrone (a Pioneer leading an AR.Drone, AuRoRA's
        LineFormation3D) writes each robot's state and commands (r1_ the Pioneer's, d2_ the drone's), Q and
        Qd; its first tick and the states after it are AuRoRA's; its errors are printed; each robot flies its own
        feedback delay (--delay D1 D2), a wrong count or range refused."""
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "line.csv")
            rc, out = flight("--formation", "line_pioneer_ardrone", "--csv", csv)
            self.assertEqual(rc, 0, out)
            self.assertIn("flight: UAV-UGV line (dynamic pioneer3dx + ardrone2), 3900 ticks", out)
            self.assertIn("RMS after 20 s: xf, yf 0.0069 m, rho 0.0039 m, alpha 0.0071 rad, beta 0.0034 rad", out)
            rows = [r.split(",") for r in open(csv).read().splitlines()]
            header = rows[0]
            self.assertEqual(header[:4], ["step", "t", "r1_x", "r1_y"])
            for name in ("r1_u", "r1_omega", "r1_u1", "r1_u2", "d2_z", "d2_dpsi", "d2_u4", "Q_xf", "Q_beta",
                         "Qd_rho", "Qd_beta"):
                self.assertIn(name, header)
            self.assertEqual(len(rows), 1 + 3900)
            col = {name: i for i, name in enumerate(header)}
            first, second = rows[1], rows[2]
            for name, value in (("Q_rho", 1.25), ("Q_beta", 0.6435011088), ("r1_u1", 0.3736396088),
                                ("r1_u2", 0.7097933116), ("d2_u3", 0.8810137624)):
                self.assertAlmostEqual(float(first[col[name]]), value, places=9, msg=name)
            for name, value in (("r1_x", -0.9992222646667399), ("r1_psi", 0.0036377270992680156),
                                ("r1_omega", 0.10913181297804046), ("d2_z", 0.7458057587350768)):
                self.assertAlmostEqual(float(second[col[name]]), value, places=14, msg=name)
            # Each robot its own feedback delay: 0 0 is the same flight to the bit; the drone's delay shakes
            # the line's shape (rho, beta) and the drone, the Pioneer's its position (xf, yf); 1 s each loses it.
            zero = os.path.join(tmp, "zero.csv")
            rc, out = flight("--formation", "line_pioneer_ardrone", "--delay", "0", "0", "--csv", zero)
            self.assertEqual(rc, 0, out)
            self.assertEqual(open(zero).read(), open(csv).read())
        rc, out = flight("--formation", "line_pioneer_ardrone", "--delay", "0", "10")
        self.assertIn("delays 0 and 10 ticks", out)
        self.assertIn("RMS after 20 s: xf, yf 0.0069 m, rho 0.0185 m, alpha 0.0172 rad, beta 0.0164 rad, "
                      "drone position 0.0405 m", out)
        rc, out = flight("--formation", "line_pioneer_ardrone", "--delay", "10", "0")
        self.assertIn("RMS after 20 s: xf, yf 0.0277 m, rho 0.0131 m", out)
        rc, out = flight("--formation", "line_pioneer_ardrone_kinematic")
        self.assertEqual(rc, 0, out)
        self.assertIn("RMS after 20 s: xf, yf 0.0093 m, rho 0.0093 m", out)
        self.refused(["--formation", "line_pioneer_ardrone", "--delay", "3"],
                     "--delay: give one delay per robot (2 for the UAV-UGV line), or none: got 1")
        self.refused(["--formation", "line_pioneer_ardrone", "--delay", "3", "3900"],
                     "--delay 3900 (robot 2) is refused: accepted integer samples in [0, 2047]")
        # Each robot its own link (a link file in its entry): the congested link on the drone changes the
        # flight, the same draws every run; --delay replaces the link's uplink delay.
        with tempfile.TemporaryDirectory() as tmp:
            linked = formation_file(tmp, ("      start: [0.0, 0.0, 0.75]", "      start: [0.0, 0.0, 0.75]\n"
                                          "      link: links/wifi_congested.yaml"), "line_pioneer_ardrone")
            runs = []
            for args in ([], [], ["--delay", "0", "0"]):
                csv = os.path.join(tmp, "run%d.csv" % len(runs))
                rc, out = flight("--formation", linked, "--csv", csv, *args)
                self.assertEqual(rc, 0, out)
                runs.append((out, open(csv).read()))
            self.assertIn("delays 0 and 2 ticks", runs[0][0])  # wifi_congested's uplink delay
            self.assertEqual(runs[0][1], runs[1][1])
            ideal = os.path.join(tmp, "ideal.csv")
            flight("--formation", "line_pioneer_ardrone", "--delay", "0", "2", "--csv", ideal)
            self.assertNotEqual(runs[0][1], open(ideal).read())  # losses and jitter, not only the delay
            self.assertIn("delays 0 and 0 ticks", runs[2][0])
            self.assertNotEqual(runs[2][1], open(ideal).read())
            bad = formation_file(tmp, ("      start: [0.0, 0.0, 0.75]", "      start: [0.0, 0.0, 0.75]\n"
                                       "      link: links/wifi_nowhere.yaml"), "line_pioneer_ardrone")
            rc, out = flight("--formation", bad)
            self.assertNotEqual(rc, 0, out)
            self.assertIn("wifi_nowhere.yaml", out)

    def test_the_triangle_flies_as_auroras(self):
        """Issue 34: flight --formation triangle_kinematic | triangle_ardrones [--law NAME] flies AuRoRA's triangle:
        one row per layer period with each robot's position (r{i}_) or state and commands (d{i}_), Q and Qd by the
        spec's names; the second period's variables and the printed errors are AuRoRA's; each robot flies its own
        feedback delay (--delay D1 D2 D3); a wrong law or delay count is refused."""
        with tempfile.TemporaryDirectory() as tmp:
            csv = os.path.join(tmp, "triangle.csv")
            rc, out = flight("--formation", "triangle_kinematic", "--csv", csv)
            self.assertEqual(rc, 0, out)
            self.assertIn("flight: triangle, law N, kinematic robots, 1000 periods", out)
            rows = [r.split(",") for r in open(csv).read().splitlines()]
            self.assertEqual(rows[0][:5], ["step", "t", "r1_x", "r1_y", "r1_z"])
            self.assertEqual(rows[0][-9:], ["Qd_xF", "Qd_yF", "Qd_zF", "Qd_p", "Qd_q", "Qd_beta", "Qd_phi", "Qd_theta",
                                            "Qd_psi"])
            self.assertEqual(len(rows), 1 + 1000)
            col = {name: i for i, name in enumerate(rows[0])}
            for name, value in (("Q_yF", 0.2851064227), ("Q_zF", 0.1382502832), ("Q_p", 1.946429472),
                                ("Q_q", 1.442023204), ("Q_beta", 0.8257879404), ("Q_psi", -0.2884694979)):
                self.assertAlmostEqual(float(rows[2][col[name]]), value, places=9, msg=name)
            zero = os.path.join(tmp, "zero.csv")  # each robot's delay 0: AuRoRA's flight to the bit
            rc, out = flight("--formation", "triangle_kinematic", "--delay", "0", "0", "0", "--csv", zero)
            self.assertEqual(open(zero).read(), open(csv).read())
        # Each robot its own feedback delay (kinematic: layer periods; drones: their steps).
        rc, out = flight("--formation", "triangle_kinematic", "--delay", "3", "0", "0")
        self.assertIn("delays 3, 0, 0 periods", out)
        self.assertIn("RMS after 20 s: position 0.0093 m, p 0.0130 m, q 0.0172 m, beta 0.0056", out)
        rc, out = flight("--formation", "triangle_ardrones", "--delay", "6", "6", "6")
        self.assertIn("delays 6, 6, 6 steps", out)
        self.assertIn("RMS after 20 s: position 0.0741 m, p 0.0598 m, q 0.0404 m, beta 0.0179", out)
        self.refused(["--formation", "triangle_ardrones", "--delay", "1", "2"],
                     "--delay: give one delay per robot (3 for the triangle), or none: got 2")
        # Issue 51 (8): the node's rule: the triangle flies 1,499 steps, so 1499 is refused as the node refuses it.
        self.refused(["--formation", "triangle_ardrones", "--delay", "0", "0", "1499"],
                     "--delay (robot 3) = 1499 samples is not shorter than the run's 1499 steps")
        rc, out = flight("--formation", "triangle_ardrones", "--delay", "0", "0", "1498")
        self.assertEqual(rc, 0, out)
        # Each drone over its own link (robots.links: one link file per drone).
        with tempfile.TemporaryDirectory() as tmp:
            starts = "    starts: [[1.0, 0.0, 0.75], [-1.0, 0.0, 0.75], [0.0, 1.0, 0.75]]"
            linked = formation_file(tmp, (starts, starts + "\n    links: [links/wifi_congested.yaml, links/ideal.yaml, "
                                                   "links/ideal.yaml]"), "triangle_ardrones")
            outs = [flight("--formation", linked)[1] for _ in range(2)]
            self.assertIn("delays 2, 0, 0 steps", outs[0])  # wifi_congested's uplink delay
            # The same draws: the same errors (the lines after the first, which ends with the wall time).
            self.assertEqual(outs[0].split("RMS", 1)[1], outs[1].split("RMS", 1)[1])
            rc, delayed = flight("--formation", "triangle_ardrones", "--delay", "2", "0", "0")
            self.assertNotEqual(delayed.split("RMS")[1], outs[0].split("RMS")[1])  # losses and jitter beyond the delay
            kinematic = formation_file(tmp, ("    starts:", "    links: [links/ideal.yaml, links/ideal.yaml, "
                                             "links/ideal.yaml]\n    starts:"), "triangle_kinematic")
            rc, out = flight("--formation", kinematic)
            self.assertNotEqual(rc, 0, out)
            self.assertIn("'formation.robots.links' is refused without a vehicle", out)
        rc, out = flight("--formation", "triangle_kinematic", "--law", "OSP")
        self.assertEqual(rc, 0, out)
        self.assertIn("RMS after 20 s: position 0.0006 m, p 0.0761 m, q 0.0721 m", out)
        rc, out = flight("--formation", "triangle_ardrones", "--law", "PSO")
        self.assertEqual(rc, 0, out)
        self.assertIn("three AR.Drones", out)
        self.assertIn("psi 1.1914 rad", out)
        self.refused(["--formation", "triangle_kinematic", "--law", "NSB"], "--law = 'NSB' is not a triangle law")
        self.refused(["--formation", "line_lemniscate", "--law", "N"], "--law is refused for a formation of shape 'line'")
        self.refused(["--law", "N"], "--law N is refused without --formation")
        self.refused(["--formation", "triangle_kinematic", "--law", ""], "--law '' is refused: give a shape law's name (triangle: ")

    def test_a_compensator_period_longer_than_the_task_is_refused(self):
        """Issue 51 (8): --rate 1e-9 ran the law once and held its command for the whole task."""
        for rate in ("1e-9", str(30.0 / 1800)):
            self.refused(["--controller", "bebop2_compensator", "--task", "bebop2_lemniscate", "--rate", rate],
                         "as long as the task (60 s) or longer: its first command would be held for the whole flight",
                         "accepted rates above 0.0166667 Hz")
        rc, out = flight("--controller", "bebop2_compensator", "--task", "bebop2_lemniscate", "--rate", str(30.0 / 1799))
        self.assertEqual(rc, 0, out)  # the law runs at steps 0 and 1799

    def test_two_sweeps_on_one_folder_and_an_interrupted_sweep(self):
        with tempfile.TemporaryDirectory() as out:
            cmd = rosrun("aurora_sweep", "sweep") + [
                "--config", os.path.join(config_dir(), "sweeps", "positioning_delay.yaml"),
                "--backend", "scalar", "--out", out, "--no-plots", "--output", "csv"]
            first = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            deadline = time.time() + 60
            while not os.path.isdir(os.path.join(out, "progress")) and time.time() < deadline:
                time.sleep(0.1)
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
            second = p.stdout.decode(errors="replace")
            self.assertEqual(p.returncode, 2, second)
            self.assertIn("output folder '%s' is in use by another sweep (pid %d on host" % (out, first.pid), second)
            first.send_signal(signal.SIGINT)
            said = first.communicate(timeout=60)[1].decode(errors="replace")
            self.assertEqual(first.returncode, -signal.SIGINT, said)
            self.assertIn("sweep: interrupted: every finished chunk stays in %s/progress" % out, said)
            self.assertIn(" ".join(cmd), said)

    def test_a_sweep_with_repeats_counts_runs_and_combinations(self):
        """Issue 31: "21,504 combinations" where the docs say 1,344 combinations x 16 repeats."""
        with tempfile.TemporaryDirectory() as out:
            p = subprocess.Popen(rosrun("aurora_sweep", "sweep") + [
                "--config", os.path.join(config_dir(), "sweeps", "link_margin.yaml"), "--out", out, "--no-plots"],
                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, universal_newlines=True)
            lines = []
            for line in p.stderr:
                lines.append(line)
                if line.startswith("sweep: link_margin:"):
                    break
            p.send_signal(signal.SIGINT)
            p.communicate(timeout=60)
        self.assertIn("sweep: link_margin: 21,504 runs (1,344 combinations x 16 repeats) in ", "".join(lines))


class AllToolArgumentsTest(ToolArgumentsTest, FormationAndLinkArgumentsTest):
    """Both classes in one rostest (rostest.rosrun takes one class)."""


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "tool_arguments", AllToolArgumentsTest)
