"""Shared by the real-drone checks: polling a condition under a lock, and the
joystick message the xbox mapping reads (LB deadman, right stick up = x)."""
import time

import rospy
from sensor_msgs.msg import Joy


def wait_for(lock, predicate, timeout):
    """True once predicate() holds (evaluated under `lock`), False after `timeout` s."""
    end = time.time() + timeout
    while time.time() < end and not rospy.is_shutdown():
        with lock:
            if predicate():
                return True
        time.sleep(0.01)
    return False


def joy_msg(deadman, stick):
    m = Joy()
    m.header.stamp = rospy.Time.now()
    m.axes = [0.0] * 8
    m.buttons = [0] * 11
    m.axes[4] = stick
    m.buttons[4] = 1 if deadman else 0
    return m
