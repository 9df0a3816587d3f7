#!/usr/bin/python3
"""replay and flight refuse what the node refuses, with the same limits
(limits.h): gains outside [0, 10], two delays, two clamp choices, a delay
beyond 2047 or not shorter than the task."""
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
        self.assert_refused(["--delay", "2048"], "--delay 2048 is refused: accepted integer samples in [0, 2047]")


    def test_missing_bag_is_named_as_missing(self):
        rc, out = replay()
        self.assertEqual(rc, 2, out)
        self.assertIn("bag '/nonexistent.bag' does not exist", out)
        self.assertNotIn("still recording", out)

    def test_flight_refuses_a_delay_not_shorter_than_the_task(self):
        # It flew such a delay as no delay at all; node, replay, sweep refuse it.
        for task, delay, longest in (("mission4", 2000, 1800), ("circle", 1201, 1200)):
            p = subprocess.run(["rosrun", "aurora_control", "flight", "--delay", str(delay), "--task",
                                subprocess.run(["rospack", "find", "aurora_config"], stdout=subprocess.PIPE)
                                .stdout.decode().strip() + "/tasks/%s.yaml" % task],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
            out = p.stdout.decode(errors="replace")
            self.assertEqual(p.returncode, 2, out)
            self.assertIn("--delay %d samples is not shorter than the run's %d steps" % (delay, longest + 1), out)
            self.assertIn("accepted delays up to %d samples" % longest, out)

    def test_flight_refuses_a_negative_delay_by_its_limits(self):
        # A value starting with '-' is the option's value, not an unknown option.
        cfg = subprocess.run(["rospack", "find", "aurora_config"], stdout=subprocess.PIPE).stdout.decode().strip()
        for args, said in ((["--delay", "-4"], "--delay -4 is refused: accepted integer samples in [0, 2047]"),
                           (["--formation", cfg + "/formations/line_lemniscate.yaml", "--delay", "3", "-4"],
                            "--delay -4 (drone 2) is refused: accepted integer samples in [0, 2047]")):
            p = subprocess.run(["rosrun", "aurora_control", "flight"] + args, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, timeout=60)
            out = p.stdout.decode(errors="replace")
            self.assertEqual(p.returncode, 2, out)
            self.assertIn(said, out)
            self.assertNotIn("unrecognised option", out)


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "tool_arguments", ToolArgumentsTest)
