#!/usr/bin/python3
"""lockstep_stall.test: the controller stopped for 2 s in lockstep (a loaded
machine's scheduler, on purpose) makes the sim re-send its state; the
controller then answers that step more than once. The sim steps once per
step (the answers name it, cmd_vel_stamped), so the states are flight's,
bit for bit: the same command file, task and delay offline."""
import csv
import os
import subprocess
import sys
import tempfile
import threading
import unittest

import rospy
import rostest
from aurora_msgs.msg import DroneState

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from flight_checks import hold_up, node_pid, wait_for  # noqa: E402
from tools import rosrun  # noqa: E402

STATE = ("x", "y", "z", "phi", "theta", "psi", "dx", "dy", "dz", "dphi", "dtheta", "dpsi")


def state_of(m):
    return (m.position.x, m.position.y, m.position.z, m.attitude.x, m.attitude.y, m.attitude.z,
            m.velocity.x, m.velocity.y, m.velocity.z, m.attitude_rate.x, m.attitude_rate.y, m.attitude_rate.z)


class LockstepStallTest(unittest.TestCase):
    def setUp(self):
        self.lock = threading.Lock()
        self.states = {}   # step -> the 12-state as first published
        self.resent = 0    # states published again with a step already seen
        self.sub = rospy.Subscriber("state", DroneState, self.on_state, queue_size=1000, tcp_nodelay=True)

    def on_state(self, m):
        with self.lock:
            if m.step in self.states:
                self.resent += 1
                self.assertEqual(self.states[m.step], state_of(m), "a re-sent state differs")
            else:
                self.states[m.step] = state_of(m)

    def flown(self):
        with self.lock:
            return len(self.states)

    def test_a_stalled_controller_leaves_the_flight_as_flights(self):
        steps, stall_at = rospy.get_param("~steps"), rospy.get_param("~stall_at")
        self.assertTrue(wait_for(self.lock, lambda: len(self.states) > stall_at, 60.0), "the flight never started")
        pid = node_pid(rospy.get_namespace() + "controller")
        hold_up(pid, 2.0)
        self.assertTrue(wait_for(self.lock, lambda: len(self.states) > steps, 120.0),
                        "the flight stopped after the stall at step %d" % self.flown())
        with self.lock:
            resent = self.resent
            flown = {k: self.states[k] for k in range(steps + 1)}
        # The sim re-sent its state while the controller stood still: the situation the test is about.
        self.assertGreater(resent, 0, "no state was re-sent during the 2 s stall")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "flight.csv")
            p = subprocess.run(rosrun("aurora_control", "flight") + ["--controller", rospy.get_param("~controller"),
                                "--task", rospy.get_param("~task"), "--delay", str(rospy.get_param("~delay")),
                                "--csv", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
            self.assertEqual(p.returncode, 0, p.stdout)
            rows = {int(r["step"]): r for r in csv.DictReader(open(out))}
        for k in range(steps + 1):
            # flight's CSV: the state after k model steps, each number read back to its double.
            self.assertEqual(flown[k], tuple(float(rows[k][n]) for n in STATE),
                             "step %d differs from flight's (%d states re-sent)" % (k, resent))


if __name__ == "__main__":
    rospy.init_node("check_lockstep_stall")
    rostest.rosrun("aurora_tests", "lockstep_stall", LockstepStallTest)
