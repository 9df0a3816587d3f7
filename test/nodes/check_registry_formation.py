#!/usr/bin/python3
"""Issue 53 (6): the registry test's shape (registry/three_abreast/), known
only to a test build of the formation node, flies three test_quads in
lockstep, each robot its own delay, recorded as any formation is. From the
bag: the shape, its robots and variables by name; each robot's delay in
force, read from its commands (the law is test_quad_pd: U = (v_ref +
k_position (p_ref - p_used)) / speed, so each command gives the position
its law used, which must be the robot's state `delay` steps back); the
formation held at the end. The shipped formation node refuses the shape by
its name."""
import os
import sys
import unittest

import rosbag
import rospy
import rostest
import yaml

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402

ROBOTS = ["quad1", "quad2", "quad3"]
MAX_DELAY = 20  # [samples] the delays looked for


class RegistryFormationTest(unittest.TestCase):
    def test_the_test_shape_flies_and_is_recorded(self):
        bag = record_until(rospy.get_param("~steps"), rospy.get_param("~bag_dir"), rospy.get_param("~prefix"),
                           state="/quad1/state", recorder="/recorder")
        with rosbag.Bag(bag) as b:
            # By tick: a bag orders messages by their arrival on its clock, and
            # two that arrive on one /clock value may swap.
            formation = sorted((m for _, m, _ in b.read_messages(topics=["/formation/formation"])),
                               key=lambda m: m.step)
            states = {r: {m.step: m for _, m, _ in b.read_messages(topics=["/%s/state" % r])} for r in ROBOTS}
        # The recorder stops while the loop runs: the last ticks may lack a
        # robot's state. Judge the ticks whose states every robot's are there.
        end = min(max(states[r]) for r in ROBOTS)
        formation = [m for m in formation if m.step <= end]
        self.check_names(formation)
        self.check_delays(formation, states)
        self.check_held(formation, states)
        self.check_shipped_refuses()
        os.remove(bag)

    def check_names(self, formation):
        self.assertGreater(len(formation), 300)
        steps = [m.step for m in formation]
        self.assertEqual(steps, list(range(len(steps))), "a tick missing or twice")
        for m in formation:
            self.assertEqual(m.shape, "three_abreast")
            self.assertEqual(list(m.drones), ROBOTS)
            self.assertEqual(list(m.vehicles), ["test_quad"] * 3)
            self.assertEqual(list(m.variables), ["x1", "y1", "z1", "dx2", "dy2", "dz2", "dx3", "dy3", "dz3"])
            self.assertEqual(len(m.command), 12)
        # Its layer runs every 0.2 s, 6 robot steps (its file's period).
        self.assertEqual(sum(m.layer_ran for m in formation), (len(formation) + 5) // 6)

    def law_constants(self):
        with open(rospy.get_param("~vehicle_file")) as f:
            speed = yaml.safe_load(f)["speed"]
        with open(rospy.get_param("~controller_file")) as f:
            k = yaml.safe_load(f)["controller"]["k_position"]
        return speed, k

    def used_position(self, m, r, speed, k):
        """The position robot r's law used at tick m, from its command."""
        return [m.reference_position[3 * r + i] - (m.command[4 * r + i] * speed - m.reference_velocity[3 * r + i]) / k
                for i in range(3)]

    def matches(self, used, state):
        p = state.position
        return max(abs(used[0] - p.x), abs(used[1] - p.y), abs(used[2] - p.z)) < 1e-9

    def check_delays(self, formation, states):
        speed, k = self.law_constants()
        for r, (robot, delay) in enumerate(zip(ROBOTS, rospy.get_param("~delays"))):
            # The delays whose states every command's used position equals
            # (a robot at rest matches several; a moving one only its own).
            fits = set(range(MAX_DELAY + 1))
            checked = 0
            for m in formation:
                if m.step < MAX_DELAY + 1 or max(abs(u) for u in m.command[4 * r:4 * r + 3]) >= 1.0:
                    continue  # not every candidate state yet; or clamped, which the inversion cannot see through
                used = self.used_position(m, r, speed, k)
                fits = {d for d in fits if self.matches(used, states[robot][m.step - d])}
                checked += 1
            rospy.loginfo("%s: %d commands fit the delays %s", robot, checked, sorted(fits))
            self.assertEqual(fits, {delay}, "%s: its law used the states of delays %s, configured %d"
                             % (robot, sorted(fits), delay))
            self.assertGreater(checked, len(formation) // 2, robot)

    def check_held(self, formation, states):
        last = formation[-1]
        tol = rospy.get_param("~tolerance")
        rospy.loginfo("at tick %d: position error %.4f m, shape error %.4f m", last.step, last.position_error,
                      last.shape_error)
        self.assertLess(last.position_error, tol)
        self.assertLess(last.shape_error, tol)
        with open(rospy.get_param("~formation_file")) as f:
            held = yaml.safe_load(f)["formation"]
        p1 = held["position"]  # robot 1's place; the others' its plus their offsets
        desired = [p1] + [[p1[i] + o[i] for i in range(3)] for o in held["offsets"]]
        for r, robot in enumerate(ROBOTS):
            p = states[robot][last.step].position
            for i, x in enumerate((p.x, p.y, p.z)):
                self.assertAlmostEqual(last.desired_position[3 * r + i], desired[r][i], places=9)
                self.assertLess(abs(x - desired[r][i]), tol, "%s at %s" % (robot, (p.x, p.y, p.z)))

    def check_shipped_refuses(self):
        rc, log = run(rosrun("aurora_control", "formation_controller") + ["__name:=shipped_formation",
                       "_formation_file:=" + rospy.get_param("~formation_file"),
                       "_config_dir:=" + rospy.get_param("~config_dir")], timeout=60)
        rospy.loginfo(log)
        self.assertNotEqual(rc, 0, log)
        self.assertIn("three_abreast", log)
        self.assertIn("line, uav_ugv_line, triangle", log)


if __name__ == "__main__":
    rospy.init_node("check_registry_formation")
    rostest.rosrun("aurora_tests", "registry_formation_lockstep", RegistryFormationTest)
