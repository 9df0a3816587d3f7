"""Waiting for a subscriber's link to one publisher node, instead of sleeping:
a message published before the link is up is lost, whatever the margin.
And a free port for a test's own master."""
import socket
import time

import rosgraph
import rospy


def wait_linked(subscriber, node, timeout=20.0):
    """True once `subscriber` (rospy.Subscriber) is connected to `node`'s publisher."""
    master = rosgraph.Master(rospy.get_name())
    end = time.time() + timeout
    while time.time() < end and not rospy.is_shutdown():
        try:
            uri = master.lookupNode(node)
        except Exception:  # not registered yet
            uri = None
        # getBusInfo format: (id, publisher URI, direction, transport, topic, connected, info)
        if uri and any(c[1] == uri for c in subscriber.impl.get_stats_info()):
            return True
        time.sleep(0.05)
    return False


def free_port():
    """A TCP port nobody listens on now (for a launch with its own master)."""
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]
