#!/usr/bin/python3
"""Replay of a real-drone flight: take-off (with the hold), joystick cycles,
a hover while the poses stop, the landing; every command reproduced."""
import glob
import os
import subprocess
import sys
import threading
import time
import unittest

import rosbag
import rospy
import rostest
from aurora_msgs.msg import Control
from sensor_msgs.msg import Joy
from std_msgs.msg import Float64

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from flight_checks import joy_msg, wait_for  # noqa: E402
from tools import rosrun  # noqa: E402


class RealReplayTest(unittest.TestCase):
    def setUp(self):
        self.lock = threading.Lock()
        self.modes = []
        rospy.Subscriber("control", Control, self.on_control, queue_size=100)

    def on_control(self, m):
        with self.lock:
            self.modes.append(m.mode)

    def wait_mode(self, mode, timeout):
        return wait_for(self.lock, lambda: self.modes and self.modes[-1] == mode, timeout)

    def test_real_flight_replays_identically(self):
        started = time.time()
        joy = rospy.Publisher("joy", Joy, queue_size=10)
        pause = rospy.Publisher("/fake_ardrone/pause_mocap", Float64, queue_size=1, latch=True)
        self.assertTrue(self.wait_mode("fly", 40.0), "never reached 'fly'")
        for _ in range(15):  # 0.5 s of stick at 30 Hz, deadman held
            joy.publish(joy_msg(True, 0.3))
            time.sleep(1.0 / 30.0)
        joy.publish(joy_msg(False, 0.0))
        time.sleep(1.5)
        pause.publish(Float64(0.5))
        self.assertTrue(self.wait_mode("landed", 40.0), "the flight did not end with 'landed'")
        subprocess.run(["rosnode", "kill", rospy.get_namespace() + "recorder"], check=True,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        bag = None
        end = time.time() + 30
        while bag is None and time.time() < end:
            fresh = [p for p in glob.glob(os.path.join(rospy.get_param("~bag_dir"), rospy.get_param("~prefix") + "_*.bag"))
                     if os.path.getmtime(p) >= started - 1]
            bag = max(fresh, key=os.path.getmtime) if fresh else None
            time.sleep(0.2)
        self.assertIsNotNone(bag, "no closed bag")
        # The bag holds every kind of cycle the replay must decide like the node.
        with rosbag.Bag(bag) as b:
            controls = [m for _, m, _ in b.read_messages(topics=[rospy.get_namespace() + "control"])]
        kinds = {
            "take-off hold (law on the hold point)": any(c.mode == "takeoff" and c.law_ran for c in controls),
            "waiting or landing (no law)": any(not c.law_ran for c in controls),
            "joystick override": any(c.overridden and "joystick" in c.mode for c in controls),
            "hand-back slew": any(c.overridden and "resuming" in c.mode for c in controls),
            "hover without poses": any(c.mode.startswith("hover") for c in controls),
        }
        rospy.loginfo("cycles in the bag: %d; %s", len(controls), kinds)
        for kind, present in kinds.items():
            self.assertTrue(present, "the bag has no %s cycle" % kind)
        p = subprocess.run(rosrun("aurora_control", "replay") + [bag, "--expect-identical"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
        log = p.stdout.decode(errors="replace")
        rospy.loginfo(log)
        self.assertEqual(p.returncode, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        os.remove(bag)


if __name__ == "__main__":
    rospy.init_node("check_real_replay")
    rostest.rosrun("aurora_tests", "real_replay", RealReplayTest)
