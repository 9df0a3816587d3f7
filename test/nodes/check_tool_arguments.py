#!/usr/bin/python3
"""replay refuses what the node refuses, with the same limits (limits.h):
gains outside [0, 10], two delays, two clamp choices, a delay beyond 2047."""
import subprocess
import unittest

import rostest


def replay(*args):
    p = subprocess.run(["rosrun", "aurora_control", "replay", "/nonexistent.bag"] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    return p.returncode, p.stdout.decode(errors="replace")


class ToolArgumentsTest(unittest.TestCase):
    def assert_refused(self, args, text):
        rc, out = replay(*args)
        self.assertEqual(rc, 2, out)
        self.assertIn(text, out)
        self.assertNotIn("cannot", out.split(text)[0][-40:])  # refused before the bag is opened

    def test_negative_gain(self):
        self.assert_refused(["--kp", "-1"], "--kp -1 is outside the accepted range [0, 10]")

    def test_gain_above_range(self):
        self.assert_refused(["--kd", "12"], "--kd 12 is outside the accepted range [0, 10]")

    def test_two_delays(self):
        self.assert_refused(["--delay", "5", "--delay-seconds", "0.2"], "--delay and --delay-seconds exclude each other")

    def test_two_clamp_choices(self):
        self.assert_refused(["--clamp", "--no-clamp"], "--clamp and --no-clamp exclude each other")

    def test_delay_beyond_the_node_limit(self):
        self.assert_refused(["--delay", "2048"], "--delay must be integer samples in [0, 2047]")


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "tool_arguments", ToolArgumentsTest)
