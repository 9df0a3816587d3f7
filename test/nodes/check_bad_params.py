#!/usr/bin/python3
"""Each bad parameter makes the node exit non-zero, naming the key and what is accepted."""
import os
import subprocess
import sys
import unittest

import rosparam
import rospy
import rostest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from tools import rosrun  # noqa: E402


def load_yaml(path, ns):
    for params, sub_ns in rosparam.load_file(path, default_namespace=ns):
        rosparam.upload_params(sub_ns, params)


class BadParamsTest(unittest.TestCase):
    def setUp(self):
        self.config = rospy.get_param("~config_dir")

    def run_node(self, pkg, node, ns, timeout=15.0):
        proc = subprocess.run(rosrun(pkg, node) + ["__ns:=" + ns, "__name:=" + node],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                              env=dict(os.environ))
        return proc.returncode, proc.stdout.decode(errors="replace")

    def controller_case(self, ns, edit):
        rospy.set_param(ns, {})
        load_yaml(os.path.join(self.config, "vehicles/ardrone2.yaml"), ns + "/vehicle")
        load_yaml(os.path.join(self.config, "controllers/pd_saturated.yaml"), ns + "/controller")
        load_yaml(os.path.join(self.config, "tasks/mission4.yaml"), ns + "/controller")
        edit(ns + "/controller/")
        return self.run_node("aurora_control", "controller", ns)

    def assert_refused(self, rc, out, key, accepted):
        self.assertNotEqual(rc, 0, "node did not exit with an error:\n" + out)
        self.assertIn(key, out, "message does not name %s:\n%s" % (key, out))
        self.assertIn(accepted, out, "message does not say what is accepted (%s):\n%s" % (accepted, out))

    def test_negative_delay_samples(self):
        rc, out = self.controller_case("/bad_delay", lambda p: rospy.set_param(p + "delay/samples", -3))
        self.assert_refused(rc, out, "/bad_delay/controller/delay/samples", "accepted integer samples in [0, 2047]")

    def test_delay_not_shorter_than_the_task(self):
        # mission4 is 60 s = 1801 iterations: a delay of 2000 would never take force
        rc, out = self.controller_case("/long_delay", lambda p: rospy.set_param(p + "delay/samples", 2000))
        self.assert_refused(rc, out, "/long_delay/controller/delay/samples",
                            "accepted delays up to 1800 samples for this task")

    def test_negative_delay_seconds(self):
        # The refusal echoes the value given.
        rc, out = self.controller_case("/bad_delay_s", lambda p: rospy.set_param(p + "delay/seconds", -0.1))
        self.assert_refused(rc, out, "'/bad_delay_s/controller/delay/seconds' = -0.1", "accepted range [0,")

    def test_unknown_controller(self):
        rc, out = self.controller_case("/bad_name", lambda p: rospy.set_param(p + "controller/name", "lqr"))
        self.assert_refused(rc, out, "/bad_name/controller/controller/name", "accepted controllers: pd_saturated, underactuated, bebop2_compensator")
        self.assertIn("'lqr'", out)

    def test_unknown_controller_key(self):
        rc, out = self.controller_case("/typo", lambda p: rospy.set_param(p + "controller/kpp", 0.6))
        self.assert_refused(rc, out, "/typo/controller/controller/kpp", "is not a known key: accepted name, kp, kd")

    def test_unknown_override_key(self):
        # An overrides file loaded into the controller's namespace with a typo.
        rc, out = self.controller_case("/typo_top", lambda p: rospy.set_param(p + "clamp_comands", False))
        self.assert_refused(rc, out, "/typo_top/controller/clamp_comands", "is not a known key: accepted controller, task")

    def test_unknown_task_key(self):
        rc, out = self.controller_case("/typo_task", lambda p: rospy.set_param(p + "task/radius", 1.0))
        self.assert_refused(rc, out, "/typo_task/controller/task/radius",
                            "is not a known key: accepted name, type, duration, waypoints, end_times")

    def test_gain_of_the_wrong_type(self):
        rc, out = self.controller_case("/str_gain", lambda p: rospy.set_param(p + "controller/kp", "0.5"))
        self.assert_refused(rc, out, "/str_gain/controller/controller/kp", "has the wrong type: expected a number")

    def test_boolean_given_as_a_string(self):
        # An overrides file with clamp_commands: "false" (a string) was
        # ignored (the node still clamped): one boolean rule, refused.
        for value in ("false", "yes please"):
            rc, out = self.controller_case("/str_bool", lambda p: rospy.set_param(p + "clamp_commands", value))
            self.assert_refused(rc, out, "'/str_bool/controller/clamp_commands' = '%s' is not a boolean" % value,
                                "accepted true or false, unquoted")

    def test_waypoint_below_the_ground(self):
        rc, out = self.controller_case(
            "/low_wp", lambda p: rospy.set_param(p + "task/waypoints", [[1, 0, 1.5], [1, 0, -2], [1, 1, 1], [0, 0, 1]]))
        self.assert_refused(rc, out, "'/low_wp/controller/task/waypoints[1]' has z = -2 m",
                            "accepted heights [0.2, 100] m")

    def test_exponent_read_as_a_string_says_how_to_write_it(self):
        # YAML 1.1 (rosparam) reads 1.0e9 as a string: say to write 1.0e+9.
        rc, out = self.controller_case("/exp_gain", lambda p: rospy.set_param(p + "controller/kp", "1.0e9"))
        self.assert_refused(rc, out, "/exp_gain/controller/controller/kp", "write 1.0e+9")

    def test_underactuated_missing_gain(self):
        def edit(p):
            rospy.delete_param(p + "controller")
            load_yaml(os.path.join(self.config, "controllers/underactuated.yaml"), p[:-1])
            rospy.delete_param(p + "controller/k2_psi")
        rc, out = self.controller_case("/no_k2_psi", edit)
        self.assert_refused(rc, out, "/no_k2_psi/controller/controller/k2_psi", "accepted: a number in [0.001, 100]")

    def test_missing_gain(self):
        rc, out = self.controller_case("/no_kd", lambda p: rospy.delete_param(p + "controller/kd"))
        self.assert_refused(rc, out, "/no_kd/controller/controller/kd", "accepted: a number in [0, 10]")

    def test_whole_number_with_a_fraction(self):
        # A fraction is refused naming the key (it was once truncated silently).
        rc, out = self.controller_case(
            "/half_subs", lambda p: rospy.set_param(p + "lockstep_subscribers/cmd_vel", 1.5))
        self.assert_refused(rc, out, "'/half_subs/controller/lockstep_subscribers/cmd_vel' = ",
                            "accepted a whole number from 0 to 100")

    def sim_case(self, ns, edit, vehicle="ardrone2"):
        load_yaml(os.path.join(self.config, "vehicles/%s.yaml" % vehicle), ns + "/vehicle")
        edit(ns + "/")
        return self.run_node("aurora_sim", "vehicle_sim", ns)

    def other_controller_case(self, ns, vehicle, controller, task, edit=lambda p: None):
        """The controller node with another vehicle's files (sim.launch vehicle:=...)."""
        rospy.set_param(ns, {})
        load_yaml(os.path.join(self.config, "vehicles/%s.yaml" % vehicle), ns + "/vehicle")
        load_yaml(os.path.join(self.config, "controllers/%s.yaml" % controller), ns + "/controller")
        load_yaml(os.path.join(self.config, "tasks/%s.yaml" % task), ns + "/controller")
        edit(ns + "/controller/")
        return self.run_node("aurora_control", "controller", ns)

    def test_pioneer_given_a_drones_task(self):
        rc, out = self.other_controller_case("/pioneer_up", "pioneer3dx", "pioneer_dynamic", "mission4")
        self.assert_refused(rc, out, "/pioneer_up/controller/task", "a ground robot's task lies on the floor")

    def test_a_law_given_another_vehicles_file(self):
        rc, out = self.other_controller_case("/bebop_law", "ardrone2", "bebop2_compensator", "bebop2_waypoints")
        self.assert_refused(rc, out, "is of type 'ardrone2', but the controller 'bebop2_compensator' flies type "
                            "'bebop2'", "give a vehicle file of type 'bebop2'")

    def test_compensator_rate_that_does_not_divide(self):
        rc, out = self.other_controller_case("/bebop_rate", "bebop2", "bebop2_compensator", "bebop2_waypoints",
                                             lambda p: rospy.set_param(p + "controller/rate", 7))
        self.assert_refused(rc, out, "'/bebop_rate/controller/controller/rate' = 7 Hz does not divide",
                            "accepted 30, 15, 10, 7.5, 6, 5")

    def test_pioneer_gain_out_of_range(self):
        rc, out = self.other_controller_case("/pioneer_gain", "pioneer3dx", "pioneer_dynamic", "pioneer_lemniscate",
                                             lambda p: rospy.set_param(p + "controller/kc1", [0.35, -1.0]))
        self.assert_refused(rc, out, "/pioneer_gain/controller/controller/kc1", "a list of 2 numbers in [0, 10]")

    def test_pioneer_given_a_take_off(self):
        rc, out = self.other_controller_case("/pioneer_takeoff", "pioneer3dx", "pioneer_dynamic", "pioneer_lemniscate",
                                             lambda p: rospy.set_param(p + "safety/takeoff_altitude", 0.75))
        self.assert_refused(rc, out, "/pioneer_takeoff/controller/safety/takeoff_altitude",
                            "a pioneer3dx is a ground robot")

    def test_predictor_of_an_unknown_form_or_another_vehicle(self):
        """Issue 35, item 6: the node refuses a bad ~predictor block naming the key."""
        rc, out = self.controller_case("/pred_form", lambda p: rospy.set_param(p + "predictor", {
            "form": "kalman", "model": self.config + "/vehicles/ardrone2.yaml"}))
        self.assert_refused(rc, out, "'/pred_form/controller/predictor/form' = 'kalman' is unknown",
                            "accepted 'resimulate', 'smith', 'off'")
        rc, out = self.controller_case("/pred_model", lambda p: rospy.set_param(p + "predictor", {
            "form": "smith", "model": self.config + "/vehicles/pioneer3dx.yaml"}))
        self.assert_refused(rc, out, "predictor.model", "give a vehicle file of type 'ardrone2'")
        rc, out = self.controller_case("/pred_rel", lambda p: rospy.set_param(p + "predictor", {
            "form": "resimulate", "model": "../vehicles/ardrone2.yaml"}))
        self.assert_refused(rc, out, "'/pred_rel/controller/predictor/model' = '../vehicles/ardrone2.yaml' is "
                            "relative", "give an absolute path, or ~controller_file")

    def test_drone_given_a_ground_robots_speed_limit(self):
        rc, out = self.controller_case("/drone_speed", lambda p: rospy.set_param(p + "safety/max_speed", 0.5))
        self.assert_refused(rc, out, "/drone_speed/controller/safety/max_speed", "leave it out (0) for a drone")

    def test_pioneer_sim_started_off_the_floor(self):
        rc, out = self.sim_case("/pioneer_air", lambda p: rospy.set_param(p + "vehicle_sim/start", [0.0, 0.0, 1.0]),
                                vehicle="pioneer3dx")
        self.assert_refused(rc, out, "/pioneer_air/vehicle_sim/start", "a ground robot: accepted [x, y, 0] in m")

    def test_sim_missing_vehicle_constant(self):
        rc, out = self.sim_case("/no_mass", lambda p: rospy.delete_param(p + "vehicle/mass"))
        self.assert_refused(rc, out, "/no_mass/vehicle/mass", "config/vehicles/ardrone2.yaml")

    def test_sim_vehicle_without_its_type(self):
        rc, out = self.sim_case("/no_type", lambda p: rospy.delete_param(p + "vehicle/type"))
        self.assert_refused(rc, out, "'/no_type/vehicle/': lacks the key 'type'", "add 'type: ardrone2'")

    def test_sim_out_of_range_vehicle_constant(self):
        rc, out = self.sim_case("/neg_mass", lambda p: rospy.set_param(p + "vehicle/mass", -0.4))
        self.assert_refused(rc, out, "/neg_mass/vehicle/mass", "accepted range")

    def test_sim_negative_stop_after(self):
        # The range has no upper end: "inf)", not DBL_MAX's 309 digits.
        rc, out = self.sim_case("/neg_stop", lambda p: rospy.set_param(p + "vehicle_sim/stop_after", -5.0))
        self.assert_refused(rc, out, "'/neg_stop/vehicle_sim/stop_after' = -5 is invalid", "accepted range [0, inf) s")
        self.assertNotIn("179769", out)

    def test_sim_whole_number_with_a_fraction(self):
        # A fraction is refused naming the key (it once fell back silently to the default).
        rc, out = self.sim_case("/half_path", lambda p: rospy.set_param(p + "vehicle_sim/path_decimation", 2.5))
        self.assert_refused(rc, out, "'/half_path/vehicle_sim/path_decimation' = ", "accepted a whole number from 1")

    def test_sim_unknown_mode(self):
        rc, out = self.sim_case("/bad_mode", lambda p: rospy.set_param(p + "vehicle_sim/mode", "fast"))
        self.assert_refused(rc, out, "'/bad_mode/vehicle_sim/mode' = 'fast' is invalid", "'realtime', 'lockstep'")

    def formation_case(self, ns, edit):
        rospy.set_param(ns, {})
        p = ns + "/formation_controller/"
        rospy.set_param(p + "formation_file", os.path.join(self.config, "formations/line_pioneer_ardrone.yaml"))
        edit(p)  # no ~config_dir: the file's paths are aurora_config's (it said '/vehicles/pioneer3dx.yaml' cannot be read)
        return self.run_node("aurora_control", "formation_controller", ns)

    def test_formation_subscribers_out_of_range(self):
        rc, out = self.formation_case("/bad_audience", lambda p: rospy.set_param(p + "formation_subscribers", -1))
        self.assert_refused(rc, out, "/bad_audience/formation_controller/formation_subscribers", "[0, 100]")

    def test_formation_subscribers_under_its_old_name(self):
        """It held in lockstep only, as ~lockstep_subscribers/formation; a
        launch file of the old name is refused, not ignored."""
        rc, out = self.formation_case("/old_audience",
                                      lambda p: rospy.set_param(p + "lockstep_subscribers/formation", 1))
        self.assert_refused(rc, out, "'/old_audience/formation_controller/lockstep_subscribers/formation' is now "
                            "'/old_audience/formation_controller/formation_subscribers'", "rename it")

if __name__ == "__main__":
    rospy.init_node("check_bad_params")
    rostest.rosrun("aurora_tests", "bad_params", BadParamsTest)
