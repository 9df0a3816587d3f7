#!/usr/bin/python3
"""The formation node's lockstep answers to re-sent states (formation_resend.test).

A sim re-sends its newest state when no command came for 0.2 s. On a busy
machine one drone's sim can re-send its state of step k while the other
drone's state of step k has not reached the node: the node must not answer
it (with its previous command the sim would step and the two drones would
run a step apart, each step then waiting for re-sends: a lockstep run once
crawled at 2.5 steps/s that way). A state re-sent after its step was
answered (the command was lost) gets that command again. Each answer also
comes on cmd_vel_stamped, stamped with the state it answers (a lockstep
sim steps on it once per step, issue 51)."""
import threading
import unittest

import rospy
import rostest
from aurora_msgs.msg import DroneState
from geometry_msgs.msg import Twist, TwistStamped

STARTS = {1: (-1.0, 0.0, 0.75), 2: (1.0, 0.0, 1.0)}  # line_lemniscate_ik.yaml's


class FormationResendTest(unittest.TestCase):
    def setUp(self):
        self.lock = threading.Lock()
        self.cmds = {1: [], 2: []}
        self.stamped = {1: [], 2: []}
        self.pubs, self.subs = {}, []
        for d in (1, 2):
            self.pubs[d] = rospy.Publisher("/ardrone%d/state" % d, DroneState, queue_size=10)
            self.subs.append(rospy.Subscriber("/ardrone%d/cmd_vel" % d, Twist, self.on_cmd, d))
            self.subs.append(rospy.Subscriber("/ardrone%d/cmd_vel_stamped" % d, TwistStamped, self.on_stamped, d))
        deadline = rospy.Time.now() + rospy.Duration(20.0)
        while rospy.Time.now() < deadline and not all(p.get_num_connections() for p in self.pubs.values()):
            rospy.sleep(0.05)
        self.assertTrue(all(p.get_num_connections() for p in self.pubs.values()), "the node never subscribed")
        rospy.sleep(0.5)  # its cmd_vel publishers reach our subscribers

    def on_cmd(self, msg, d):
        with self.lock:
            self.cmds[d].append((msg.linear.x, msg.linear.y, msg.linear.z, msg.angular.z))

    def on_stamped(self, msg, d):
        with self.lock:
            t = msg.twist
            self.stamped[d].append((msg.header.stamp, (t.linear.x, t.linear.y, t.linear.z, t.angular.z)))

    @staticmethod
    def stamp_of(step):
        """A lockstep sim's stamp of its state of `step` (step Ts, Ts = 1/30 s)."""
        return rospy.Time(0, int(round(step * 1e9 / 30.0)))

    def count(self, d):
        with self.lock:
            return len(self.cmds[d])

    def send(self, d, step):
        m = DroneState()
        m.header.stamp = self.stamp_of(step)
        m.step = step
        m.position.x, m.position.y, m.position.z = STARTS[d]
        self.pubs[d].publish(m)

    def wait_for(self, d, n, timeout=5.0):
        deadline = rospy.Time.now() + rospy.Duration(timeout)
        while rospy.Time.now() < deadline and self.count(d) < n:
            rospy.sleep(0.02)
        return self.count(d)

    def test_a_resent_state_is_answered_only_once_its_step_was(self):
        # Drone 1's state of step 0, then re-sent twice: drone 2's has not come.
        for _ in range(3):
            self.send(1, 0)
            rospy.sleep(0.3)
        self.assertEqual(self.count(1), 0, "a re-sent state of a step not answered yet got a command: %s"
                         % self.cmds[1])
        # Drone 2's state of step 0: step 0 is answered, one command each.
        self.send(2, 0)
        self.assertEqual(self.wait_for(1, 1), 1)
        self.assertEqual(self.wait_for(2, 1), 1)
        rospy.sleep(0.3)
        self.assertEqual((self.count(1), self.count(2)), (1, 1), "more than one answer to step 0")
        # Drone 1 re-sends step 0 (its command was lost): the same command again.
        self.send(1, 0)
        self.assertEqual(self.wait_for(1, 2), 2, "a re-sent answered state got no command")
        with self.lock:
            self.assertEqual(self.cmds[1][1], self.cmds[1][0])
        # Drone 1 steps (step 1) and re-sends it before drone 2's step 1: nothing.
        self.send(1, 1)
        rospy.sleep(0.3)
        self.send(1, 1)
        rospy.sleep(0.3)
        self.assertEqual(self.count(1), 2, "drone 1's unanswered step 1 got a command")
        self.send(2, 1)
        self.assertEqual(self.wait_for(1, 3), 3)
        self.assertEqual(self.wait_for(2, 2), 2)
        # The stamped answers: the same commands, each stamped with the step it answers.
        rospy.sleep(0.3)
        with self.lock:
            self.assertEqual([c for _, c in self.stamped[1]], self.cmds[1])
            self.assertEqual([c for _, c in self.stamped[2]], self.cmds[2])
            self.assertEqual([s for s, _ in self.stamped[1]], [self.stamp_of(k) for k in (0, 0, 1)])
            self.assertEqual([s for s, _ in self.stamped[2]], [self.stamp_of(k) for k in (0, 1)])


if __name__ == "__main__":
    rospy.init_node("check_formation_resend")
    rostest.rosrun("aurora_tests", "formation_resend", FormationResendTest)
