#!/usr/bin/python3
"""formation.launch with real robots of a UAV-UGV line (formation_real_pioneer.test):
against a fake RosAria (pioneer1) and a fake AR.Drone driver (ardrone2), the
drone takes off and the Pioneer drives to its start point, the formation
flies its ticks once both are still at their starts and holds its shape,
the Pioneer's commands reach RosAria within its safety file's limits, and at
the end the drone lands and the Pioneer stops. The Pioneer is never told to
take off or land: nothing publishes those topics in its namespace."""
import math
import os
import sys
import unittest

import rosgraph
import rospy
import rostest
import yaml

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from real_formation import flown_ticks, watch_until_landed  # noqa: E402

# Measured here (both cores busy too): shape error at most 0.066 m, position error 0.022 m after 10 s
# (the sim's: 0.06 m, 0.02 m).
SHAPE_ERROR, POSITION_ERROR = 0.3, 0.3
MAX_SPEED, MAX_TURN_RATE = 0.5, 1.0  # config/safety/real_ground.yaml


class FormationRealPioneerTest(unittest.TestCase):
    def test_a_pioneer_and_a_drone_fly_the_line_formation(self):
        cmd = []
        sub = rospy.Subscriber("/pioneer1/RosAria/cmd_vel", rospy.AnyMsg, lambda m: cmd.append(m), queue_size=1000)
        ended, ticks, truth, received = watch_until_landed(["pioneer1", "ardrone2"], 130.0)
        sub.unregister()
        self.assertTrue(ended, "the flight did not end with 'landed': last mode %r" % (ticks[-1].mode if ticks else None))
        flown = flown_ticks(self, ticks)
        # The formation's first tick found the Pioneer at its start point (within the supervisor's 0.05 m),
        # not where its driver put it (0.25 m behind): the formation held until it got there.
        with open(rospy.get_param("~formation_file")) as f:
            start = yaml.safe_load(f)["formation"]["robots"][0]["start"]
        at = flown[0].Q_newest
        self.assertLess(math.hypot(at[0] - start[0], at[1] - start[1]), 0.1, (at[:3], start))
        self.assertEqual(list(flown[0].drones), ["pioneer1", "ardrone2"])
        self.assertEqual(list(flown[0].vehicles), ["pioneer3dx", "ardrone2"])
        # The shape holds once settled (the formation checks' errors, from 10 s on).
        settled = [m for m in flown if m.step * m.sample_time >= 10.0]
        print("formation.launch, a Pioneer with a drone: %d ticks flown; after 10 s shape error max %.3f m, position "
              "error max %.3f m; Pioneer |u| max %.3f m/s, |omega| max %.3f rad/s"
              % (len(flown), max(m.shape_error for m in settled), max(m.position_error for m in settled),
                 max(abs(m.command[0]) for m in flown), max(abs(m.command[1]) for m in flown)))
        self.assertLess(max(m.shape_error for m in settled), SHAPE_ERROR)
        self.assertLess(max(m.position_error for m in settled), POSITION_ERROR)
        # The Pioneer drove (it leads the figure-eight) within its limits, through RosAria. (They do not bind
        # here: 0.388 m/s and 0.709 rad/s measured; FormationCrew.TheUavUgvLinesTickIsTheRunners checks the clamp.)
        u = [m.command[0] for m in flown]
        w = [m.command[1] for m in flown]
        self.assertGreater(max(abs(v) for v in u), 0.02)
        self.assertLessEqual(max(abs(v) for v in u), MAX_SPEED)
        self.assertLessEqual(max(abs(v) for v in w), MAX_TURN_RATE)
        self.assertGreater(len(cmd), len(flown))
        p = truth["pioneer1"]
        self.assertGreater(math.hypot(p[-1][0] - p[0][0], p[-1][1] - p[0][1]), 0.5)
        self.assertEqual(max(z for _, _, z in p), 0.0)
        # The drone took off and landed; nothing asks the Pioneer to.
        self.assertNotIn("takeoff=0", received["ardrone2"])
        self.assertNotIn("land=0", received["ardrone2"])
        publishers = dict(rosgraph.Master("/check").getSystemState()[0])
        for topic in ("/pioneer1/takeoff", "/pioneer1/land", "/pioneer1/RosAria/takeoff"):
            self.assertFalse(publishers.get(topic), topic)
        self.assertTrue(publishers.get("/ardrone2/ardrone/takeoff"), "the drone's take-off topic has no publisher")
        # At the end the Pioneer stands: zero commands once the formation ended.
        after = [m for m in ticks if m.mode in ("land (task complete)", "landed")]
        self.assertTrue(after and all(m.command[0] == 0.0 and m.command[1] == 0.0 for m in after[1:]))


if __name__ == "__main__":
    rospy.init_node("check_formation_real_pioneer")
    rostest.rosrun("aurora_tests", "formation_real_pioneer", FormationRealPioneerTest)
