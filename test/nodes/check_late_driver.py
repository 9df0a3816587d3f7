#!/usr/bin/python3
"""Take-off and land reach a driver that subscribes late and drops the first of each."""
import os
import sys
import threading
import unittest

import rospy
import rostest
from aurora_msgs.msg import Control
from std_msgs.msg import String

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from flight_checks import wait_for  # noqa: E402


def counts(text):
    return {k: int(v) for k, v in (item.split("=") for item in text.split())}


class LateDriverTest(unittest.TestCase):
    def setUp(self):
        self.lock = threading.Lock()
        self.controls = []
        self.received = {"takeoff": 0, "land": 0, "reset": 0}
        self.status = []
        rospy.Subscriber("control", Control, self.on_control, queue_size=100)
        rospy.Subscriber("/fake_ardrone/received", String, self.on_received, queue_size=10)
        rospy.Subscriber("/fake_ardrone/status", String, self.on_status, queue_size=10)

    def on_control(self, m):
        with self.lock:
            self.controls.append((m.mode, m.takeoff_attempts, m.land_attempts))

    def on_received(self, m):
        with self.lock:
            self.received = counts(m.data)

    def on_status(self, m):
        with self.lock:
            self.status.append(m.data)

    def wait_for(self, predicate, timeout):
        return wait_for(self.lock, predicate, timeout)

    def test_takeoff_and_land_are_delivered(self):
        # The state arrives long before the driver listens to take-off; the
        # supervisor's take-off timeout is 15 s, so 'fly' within 40 s means
        # the take-off got through.
        flew = self.wait_for(lambda: any(c[0] == "fly" for c in self.controls), 40.0)
        with self.lock:
            modes = sorted({c[0] for c in self.controls})
        self.assertTrue(flew, "never reached 'fly' (modes seen: %s)" % modes)
        with self.lock:
            at_fly = next(c for c in self.controls if c[0] == "fly")
            received = dict(self.received)
        rospy.loginfo("take-off: %d sent, %d received by the driver", at_fly[1], received["takeoff"])
        # One dropped by the not-yet-ready driver, then one that worked.
        self.assertGreaterEqual(at_fly[1], 2)
        # Held until the driver subscribed: nothing was published into the void.
        self.assertEqual(received["takeoff"], at_fly[1])

        landed = self.wait_for(lambda: self.controls and self.controls[-1][0] == "landed", 40.0)
        self.assertTrue(landed, "the flight did not end with 'landed'")
        self.assertTrue(self.wait_for(lambda: self.status and self.status[-1] == "landed", 5.0),
                        "the driver never landed: %s" % self.status)
        with self.lock:
            last = self.controls[-1]
            received = dict(self.received)
        rospy.loginfo("land: %d sent, %d received by the driver", last[2], received["land"])
        self.assertGreaterEqual(last[2], 2)
        self.assertEqual(received["land"], last[2])
        self.assertEqual(received["reset"], 0)


if __name__ == "__main__":
    rospy.init_node("check_late_driver")
    rostest.rosrun("aurora_tests", "real_late_driver", LateDriverTest)
