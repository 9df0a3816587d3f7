#!/usr/bin/python3
"""Each bad parameter makes the node exit non-zero, naming the key and what is accepted."""
import os
import subprocess
import unittest

import rosparam
import rospy
import rostest


def load_yaml(path, ns):
    for params, sub_ns in rosparam.load_file(path, default_namespace=ns):
        rosparam.upload_params(sub_ns, params)


class BadParamsTest(unittest.TestCase):
    def setUp(self):
        self.config = rospy.get_param("~config_dir")

    def run_node(self, pkg, node, ns, timeout=15.0):
        proc = subprocess.run(["rosrun", pkg, node, "__ns:=" + ns, "__name:=" + node],
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
        rc, out = self.controller_case("/bad_delay_s", lambda p: rospy.set_param(p + "delay/seconds", -0.5))
        self.assert_refused(rc, out, "/bad_delay_s/controller/delay/seconds", "accepted range [0,")

    def test_unknown_controller(self):
        rc, out = self.controller_case("/bad_name", lambda p: rospy.set_param(p + "controller/name", "lqr"))
        self.assert_refused(rc, out, "/bad_name/controller/controller/name", "accepted controllers: 'pd_saturated'")
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

    def test_sim_missing_vehicle_constant(self):
        ns = "/no_mass"
        load_yaml(os.path.join(self.config, "vehicles/ardrone2.yaml"), ns + "/vehicle")
        rospy.delete_param(ns + "/vehicle/mass")
        rc, out = self.run_node("aurora_sim", "ardrone_sim", ns)
        self.assert_refused(rc, out, "/no_mass/vehicle/mass", "config/vehicles/ardrone2.yaml")

    def test_sim_out_of_range_vehicle_constant(self):
        ns = "/neg_mass"
        load_yaml(os.path.join(self.config, "vehicles/ardrone2.yaml"), ns + "/vehicle")
        rospy.set_param(ns + "/vehicle/mass", -0.4)
        rc, out = self.run_node("aurora_sim", "ardrone_sim", ns)
        self.assert_refused(rc, out, "/neg_mass/vehicle/mass", "accepted range")


if __name__ == "__main__":
    rospy.init_node("check_bad_params")
    rostest.rosrun("aurora_tests", "bad_params", BadParamsTest)
