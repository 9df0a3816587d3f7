#!/usr/bin/python3
"""A bag recorded over a congested link replays identically over the same
link file (the link is configured with the recorded delay and sample time
before the first state, as the node does); without --link replay says the
bag was flown over an imperfect link instead of "(recorded configuration)"."""
import os
import sys
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from bag_helpers import record_until, run_tool as run  # noqa: E402
from tools import rosrun  # noqa: E402


class ReplayLinkTest(unittest.TestCase):
    def test_replay_over_the_recorded_link(self):
        bag = record_until(rospy.get_param("~steps"), rospy.get_param("~bag_dir"), rospy.get_param("~prefix"))
        link = rospy.get_param("~link_file")
        rc, log = run(rosrun("aurora_control", "replay") + [bag, "--link", link, "--expect-identical"])
        rospy.loginfo(log)
        self.assertEqual(rc, 0, log)
        self.assertIn(" 0 differ, max |dU| = 0 ", log)
        self.assertIn("(recorded configuration over the link given)", log)
        # Without the link: not the recorded configuration, and it says so.
        rc, log = run(rosrun("aurora_control", "replay") + [bag])
        self.assertNotIn("(recorded configuration)", log)
        self.assertIn("flown over an imperfect link; give it with --link FILE", log)
        self.assertNotIn(" 0 differ", log)
        os.remove(bag)


if __name__ == "__main__":
    rospy.init_node("check_replay_link")
    rostest.rosrun("aurora_tests", "replay_link", ReplayLinkTest)
