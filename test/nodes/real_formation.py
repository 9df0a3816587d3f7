"""Shared by the real-robot formation rostests (fake drivers in each robot's
namespace): watch the formation topic and each fake driver until the flight
ends "landed", and the flight sequence every such flight goes through."""
import threading

import rospy
from aurora_msgs.msg import DroneState, Formation
from std_msgs.msg import String


def watch_until_landed(robots, timeout):
    """Whether the mode reached "landed" within `timeout` [s], the
    Formation messages, each robot's true positions (its fake driver's) and
    what its driver received."""
    ticks, truth, received = [], {r: [] for r in robots}, {}
    landed = threading.Event()

    def on_formation(m):
        ticks.append(m)
        if m.mode == "landed":
            landed.set()
    subs = [rospy.Subscriber("/formation/formation", Formation, on_formation, queue_size=1000)]
    for ns in robots:
        subs.append(rospy.Subscriber("/%s/fake_driver/true_state" % ns, DroneState,
                                     lambda m, ns=ns: truth[ns].append((m.position.x, m.position.y, m.position.z)),
                                     queue_size=1000))
        subs.append(rospy.Subscriber("/%s/fake_driver/received" % ns, String,
                                     lambda m, ns=ns: received.__setitem__(ns, m.data)))
    ended = landed.wait(timeout)
    if ended:
        # Each subscription has its own callback thread: the drivers' last true states (sent before the
        # formation said "landed") may still be queued. A landed drone's z was read 0.1005 m once, its
        # descent's sample before touch-down.
        rospy.sleep(1.0)
    for s in subs:
        s.unregister()
    return ended, ticks, truth, received


def flown_ticks(test, ticks):
    """The flight sequence (take-off, hold until every robot is still at
    its start, the formation's ticks 0 .. n - 1, land at the task's end):
    the ticks flown."""
    modes = [m.mode for m in ticks]
    # The formation node takes no state before this checker listens
    # (formation.launch's extra_formation_subscribers): it sees the take-off.
    test.assertEqual(next((m for m in modes if m != "wait for state"), None), "takeoff", sorted(set(modes)))
    test.assertTrue(any(m.startswith("hold (waiting for") for m in modes), sorted(set(modes)))
    test.assertIn("land (task complete)", modes)
    flown = [m for m in ticks if m.mode == "fly"]
    test.assertEqual(flown[0].step, 0)
    test.assertEqual(flown[-1].step, flown[-1].ticks - 1, "the formation did not fly its ticks 0 .. n - 1")
    return flown
