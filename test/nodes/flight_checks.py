"""Shared by the real-drone checks: polling a condition under a lock, the
joystick message the xbox mapping reads (LB deadman, right stick up = x), and
holding a node's process up as a loaded machine would."""
import os
import signal
import time
import xmlrpc.client

import rosgraph
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


def node_pid(name):
    """The process id of a running node (its XML-RPC API's getPid)."""
    uri = rosgraph.Master(rospy.get_name()).lookupNode(name)
    code, msg, pid = xmlrpc.client.ServerProxy(uri).getPid(rospy.get_name())
    if code != 1:
        raise RuntimeError("getPid of %s: %s" % (name, msg))
    return pid


def hold_up(pid, seconds):
    """Stops a process for `seconds` (SIGSTOP, then SIGCONT), as a loaded
    machine's scheduler may: its threads and timers all stand still."""
    os.kill(pid, signal.SIGSTOP)
    try:
        time.sleep(seconds)
    finally:
        os.kill(pid, signal.SIGCONT)
