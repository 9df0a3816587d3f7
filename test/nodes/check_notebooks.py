#!/usr/bin/python3
"""Every notebook of notebooks/ runs top to bottom with plain `jupyter
nbconvert --execute` without an error or a traceback in its output, and shows each of
its figures (an image output for every plt.show()). Its time is printed, not
asserted (a busy machine is slow; bench/ measures speed)."""
import glob
import os
import subprocess
import sys
import tempfile
import time
import unittest

import nbformat
import rostest

NOTEBOOKS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "notebooks")


def execute(path, out_dir):
    """Runs nbconvert on `path`; returns (seconds, the executed notebook, its log)."""
    start = time.time()
    # Plain nbconvert, as a user runs it: no configuration file (issue 31: notebook 4's sliders needed one).
    p = subprocess.run(["jupyter", "nbconvert", "--to", "notebook", "--execute", "--output-dir", out_dir, path],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    seconds = time.time() - start
    if p.returncode != 0:
        return seconds, None, p.stdout
    return seconds, nbformat.read(os.path.join(out_dir, os.path.basename(path)), as_version=4), p.stdout


class NotebooksTest(unittest.TestCase):
    def test_every_notebook_runs_and_shows_its_figures(self):
        paths = sorted(glob.glob(os.path.join(NOTEBOOKS, "*.ipynb")))
        self.assertEqual(len(paths), 4, paths)
        with tempfile.TemporaryDirectory() as tmp:
            for path in paths:
                name = os.path.basename(path)
                seconds, nb, log = execute(path, tmp)
                self.assertIsNotNone(nb, "%s failed:\n%s" % (name, log[-3000:]))
                sys.stdout.write("%s: %.1f s\n" % (name, seconds))
                code = [c for c in nb.cells if c.cell_type == "code"]
                errors = [o for c in code for o in c.get("outputs", []) if o.get("output_type") == "error"]
                self.assertEqual(errors, [], name)
                # A traceback printed by a cell (a progress bar's widget failing in a thread) is an error too.
                printed = [o.get("text", "") for c in code for o in c.get("outputs", []) if o.get("output_type") == "stream"]
                self.assertEqual([t for t in printed if "Traceback" in t], [], name)
                shown = sum(c.source.count("plt.show()") for c in code)
                images = sum(1 for c in code for o in c.get("outputs", []) if "image/png" in o.get("data", {}))
                self.assertGreater(shown, 0, name)
                self.assertGreaterEqual(images, shown, "%s: %d figures shown, %d images" % (name, shown, images))


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "notebooks", NotebooksTest)
