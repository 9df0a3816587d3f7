#!/usr/bin/python3
"""formation.launch with real robots of AuRoRA's triangle (formation_real_triangle.test):
against three fake AR.Drone drivers (ardrone1..3), each with its mocap
stream, the three take off together, the formation flies its ticks once all
three hover and holds its shape, and at the end all three land."""
import os
import sys
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from real_formation import flown_ticks, watch_until_landed  # noqa: E402

DRONES = ["ardrone1", "ardrone2", "ardrone3"]
# Measured here: after 10 s shape error at most 0.239 m, position error 0.355 m (0.235, 0.358 m with both
# cores busy; the sim's, the sweep's record of triangle_ardrones without delay: 0.222, 0.378 m: the
# drones lag the carrousel).
SHAPE_ERROR, POSITION_ERROR = 0.5, 0.6


class FormationRealTriangleTest(unittest.TestCase):
    def test_three_drones_fly_the_triangle(self):
        ended, ticks, truth, received = watch_until_landed(DRONES, 140.0)
        self.assertTrue(ended, "the flight did not end with 'landed': last mode %r" % (ticks[-1].mode if ticks else None))
        flown = flown_ticks(self, ticks)
        self.assertEqual(flown[0].shape, "triangle")
        self.assertEqual(list(flown[0].drones), DRONES)
        self.assertEqual(list(flown[0].vehicles), ["ardrone2"] * 3)
        self.assertEqual(list(flown[0].variables), ["xF", "yF", "zF", "p", "q", "beta", "phi", "theta", "psi"])
        settled = [m for m in flown if m.step * m.sample_time >= 10.0]
        shape, position = max(m.shape_error for m in settled), max(m.position_error for m in settled)
        print("formation.launch, the triangle of three AR.Drones: %d ticks flown; after 10 s shape error max %.3f m, "
              "position error max %.3f m" % (len(flown), shape, position))
        self.assertLess(shape, SHAPE_ERROR)
        self.assertLess(position, POSITION_ERROR)
        for ns in DRONES:  # each took off and landed through its own driver
            self.assertNotIn("takeoff=0", received[ns], ns)
            self.assertNotIn("land=0", received[ns], ns)
            self.assertGreater(max(z for _, _, z in truth[ns]), 0.5, ns)
            self.assertLess(truth[ns][-1][2], 0.1, ns)


if __name__ == "__main__":
    rospy.init_node("check_formation_real_triangle")
    rostest.rosrun("aurora_tests", "formation_real_triangle", FormationRealTriangleTest)
