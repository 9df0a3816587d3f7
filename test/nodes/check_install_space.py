#!/usr/bin/python3
"""Installs the workspace and runs the mission, the report, a sweep and the
flight tool from the install space alone."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest

# The shared helpers sit beside this script (catkin's relay runs it with
# __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from ros_links import free_port  # noqa: E402

NOETIC = "/opt/ros/noetic/setup.bash"


class InstallSpaceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.build = rospy.get_param("~build_dir")
        cls.prefix = rospy.get_param("~install_dir")
        cls.tmp = tempfile.mkdtemp(prefix="aurora_install_test_")
        # Only into a prefix inside the build folder: never over a system one.
        cls.refused = not os.path.realpath(cls.prefix).startswith(os.path.realpath(cls.build) + os.sep)
        if not cls.refused:
            shutil.rmtree(cls.prefix, ignore_errors=True)
            cls.installed = subprocess.run(["cmake", "--install", cls.build], stdout=subprocess.PIPE,
                                           stderr=subprocess.STDOUT, universal_newlines=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def sh(self, script, source=True, timeout=180, extra_env=None):
        """Runs `script` in a clean environment with only the install space (and
        Noetic's underlay, where there is one) sourced."""
        env = {"HOME": os.environ.get("HOME", "/root"), "PATH": "/usr/bin:/bin",
               "ROS_LOG_DIR": os.path.join(self.tmp, "ros_log"), "LANG": "C.UTF-8"}
        env.update(extra_env or {})
        setup = ""
        if source:
            setup = ("[ -f %s ] && source %s; " % (NOETIC, NOETIC)) + "source %s/setup.bash && " % self.prefix
        done = subprocess.run(["bash", "-c", setup + script], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, universal_newlines=True, timeout=timeout)
        return done.returncode, done.stdout

    def setUp(self):
        self.assertFalse(self.refused, "install prefix %s is not inside the build folder %s: configure with "
                         "-DCMAKE_INSTALL_PREFIX=<build>/install (make does)" % (self.prefix, self.build))
        self.assertEqual(self.installed.returncode, 0, self.installed.stdout[-3000:])

    def test_1_packages_resolve_to_the_install_space(self):
        for pkg in ("aurora_config", "aurora_bringup", "aurora_common", "aurora_sim", "aurora", "aurora_control", "aurora_sweep"):
            rc, out = self.sh("rospack find %s" % pkg)
            self.assertEqual((rc, out.strip()), (0, os.path.join(self.prefix, "share", pkg)), out)

    def test_2_mission_and_report(self):
        bags = os.path.join(self.tmp, "bags")
        rc, out = self.sh("rosrun aurora_bringup aurora_launch -p %d aurora_bringup sim.launch mode:=lockstep "
                          "delay:=5 record:=true bag_dir:=%s bag_name:=inst stop_after:=20 sim_output:=log"
                          % (free_port(), bags))
        self.assertEqual(rc, 0, out[-3000:])
        self.assertIn("finished normally", out)
        bag = [f for f in os.listdir(bags) if f.endswith(".bag")]
        self.assertEqual(len(bag), 1, os.listdir(bags))
        report = os.path.join(self.tmp, "report")
        rc, out = self.sh("rosrun aurora report %s --out %s --no-video --no-pdf"
                          % (os.path.join(bags, bag[0]), report))
        self.assertEqual(rc, 0, out)
        m = json.load(open(os.path.join(report, "metrics.json")))["drones"][0]
        self.assertEqual(m["delay_samples"], 5)
        self.assertTrue(m["metrics_match_controller"])
        self.assertGreater(m["steps"], 590)
        # identify from the install space: the AR.Drone's timing (its model is not fitted yet).
        identified = os.path.join(self.tmp, "identify")
        rc, out = self.sh("rosrun aurora identify %s --out %s" % (os.path.join(bags, bag[0]), identified))
        self.assertEqual(rc, 0, out)
        self.assertIn("feedback delay 5 samples", out)
        self.assertEqual(json.load(open(os.path.join(identified, "identify.json")))["link"]["uplink"]["delay"], 5)

    def test_3_sweep_finds_vehicle_and_plot_script(self):
        out_dir = os.path.join(self.tmp, "sweep")
        sweep_file = os.path.join(self.prefix, "share", "aurora_config", "sweeps", "positioning_delay.yaml")
        rc, out = self.sh("rosrun aurora_sweep sweep --config %s --out %s --backend cpu --quiet" % (sweep_file, out_dir))
        self.assertEqual(rc, 0, out)
        pngs = [f for f in os.listdir(out_dir) if f.endswith(".png")]
        self.assertTrue(pngs, "plot_sweep did not run from the install space: %s" % os.listdir(out_dir))

    def test_4_flight_tool_finds_its_config(self):
        rc, out = self.sh("rosrun aurora_control flight --delay 5")
        self.assertEqual(rc, 0, out)
        self.assertIn("IAE", out)

    def test_4b_python_simulates_from_the_install_space(self):
        rc, out = self.sh("cd %s && /usr/bin/python3 -c 'import aurora; f = aurora.simulate(\"pd_saturated\", "
                          "\"mission4\", delay=5); print(aurora.__file__, aurora._core.__file__, f.metrics[\"iae\"])'"
                          % self.tmp)
        self.assertEqual(rc, 0, out)
        self.assertIn(self.prefix, out.split()[1], "aurora._core is not the install space's: %s" % out)
        # aurora.sweep finds the install space's sweep program; the formation flight and figures module too.
        rc, out = self.sh("cd %s && /usr/bin/python3 -c 'import aurora; r, s = aurora.sweep(\"positioning_delay\", "
                          "backend=\"cpu\", progress=False); g = aurora.simulate_formation(\"line_lemniscate\"); "
                          "import aurora.formation_figures; print(aurora.sweep_program(), len(r), s[\"feasible\"], "
                          "g.metrics[\"ticks\"])'" % self.tmp)
        self.assertEqual(rc, 0, out)
        self.assertIn(self.prefix, out.split()[0], "aurora.sweep did not run the install space's program: %s" % out)
        self.assertEqual(out.split()[1:], ["65536", "10466", "2700"], out)

    def test_5_without_the_setup_the_error_says_what_to_source(self):
        sweep = os.path.join(self.prefix, "lib", "aurora_sweep", "sweep")
        sweep_file = os.path.join(self.prefix, "share", "aurora_config", "sweeps", "positioning_delay.yaml")
        # Its libraries found, but no package path holding aurora_config (a
        # shell that sourced another workspace, or none).
        rc, out = self.sh("%s --config %s --out %s" % (sweep, sweep_file, os.path.join(self.tmp, "x")),
                          source=False, extra_env={"LD_LIBRARY_PATH": os.path.join(self.prefix, "lib")})
        self.assertEqual(rc, 2, out)
        self.assertIn("'aurora_config' is not on the ROS package path", out)
        self.assertIn("setup.bash", out)


if __name__ == "__main__":
    rospy.init_node("check_install_space")
    rostest.rosrun("aurora_tests", "install_space", InstallSpaceTest)
