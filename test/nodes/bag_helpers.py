"""Shared by the bag rostests: wait for a lockstep run to reach a step, stop
the recorder the way roslaunch would (it closes the bag), find the bag."""
import glob
import os
import subprocess
import threading
import time

import rospy
from aurora_msgs.msg import DroneState
from tools import rosrun  # noqa: E402


def record_until(steps, bag_dir, prefix, timeout=120.0, state="state", recorder=None):
    started = time.time()
    reached = threading.Event()
    sub = rospy.Subscriber(state, DroneState, lambda m: reached.set() if m.step >= steps else None)
    if not reached.wait(timeout):
        raise AssertionError("the loop did not reach step %d in %.0f s" % (steps, timeout))
    sub.unregister()
    subprocess.run(["rosnode", "kill", recorder or rospy.get_namespace() + "recorder"], check=True,
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    deadline = time.time() + 30
    while time.time() < deadline:
        fresh = [p for p in glob.glob(os.path.join(bag_dir, prefix + "_*.bag"))
                 if os.path.getmtime(p) >= started - 1]
        if fresh:
            return max(fresh, key=os.path.getmtime)
        time.sleep(0.2)
    raise AssertionError("no closed bag %s_*.bag in %s" % (prefix, bag_dir))


def run_tool(cmd, timeout=240):
    """A tool's exit status and its output (stdout and stderr together)."""
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
    return p.returncode, p.stdout.decode(errors="replace")


def report_on(bag):
    """`rosrun aurora report BAG` into BAG's folder (no PDF): the report's
    folder, its output and exit status."""
    out = bag[:-4] + "_report"
    p = subprocess.run(rosrun("aurora", "report") + [bag, "--out", out, "--no-pdf"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    return out, p.returncode, p.stdout


def frames_moved(video, frames):
    """The pixels [count] that differ (by more than a quarter of the grey
    scale) between the video's first and last of `frames` frames: what
    moves in it (the drones, their trails, the clock in the title). A
    video whose moving parts were not drawn has none."""
    grey = subprocess.run(["ffmpeg", "-v", "error", "-i", video, "-vf",
                           "select=eq(n\\,0)+eq(n\\,%d)" % (frames - 1), "-vsync", "0",
                           "-f", "rawvideo", "-pix_fmt", "gray", "-"], stdout=subprocess.PIPE, check=True).stdout
    half = len(grey) // 2
    return sum(1 for a, b in zip(grey[:half], grey[half:]) if abs(a - b) > 64)
