#!/usr/bin/python3
"""include_layers.test: scripts/check_include_layers.py finds no include
that runs up a concept layer in the repository, and finds one that does
(and a folder that is no layer) in a tree made to have them."""
import importlib.util
import os
import tempfile
import unittest

import rostest

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))


def checker():
    spec = importlib.util.spec_from_file_location("check_include_layers",
                                                  os.path.join(ROOT, "scripts", "check_include_layers.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class IncludeLayersTest(unittest.TestCase):
    def test_no_include_runs_up_a_layer(self):
        if not os.path.isdir(os.path.join(ROOT, "aurora_control", "include")):  # run from an install space
            self.skipTest("no source tree next to this script (%s)" % ROOT)
        self.assertEqual(checker().violations(ROOT), [])

    def test_an_upward_include_and_an_unlisted_folder_are_found(self):
        with tempfile.TemporaryDirectory() as repo:
            root = os.path.join(repo, "aurora_control", "include", "aurora_control")
            for folder, name, text in (("law", "a.h", '#include "aurora_control/loop/b.h"\n'),
                                       ("loop", "b.h", '#include "aurora_control/law/a.h"\n'),
                                       ("misc", "c.h", "")):
                os.makedirs(os.path.join(root, folder), exist_ok=True)
                with open(os.path.join(root, folder, name), "w") as f:
                    f.write(text)
            found = checker().violations(repo, {"aurora_control": ["law", "loop"]})
        self.assertEqual(len(found), 2, found)
        self.assertIn("aurora_control/law/a.h includes aurora_control/loop/b.h: layer 'loop' is above 'law'", found)
        self.assertTrue(any(v.startswith("aurora_control/misc/c.h: its folder 'misc' is not a layer of aurora_control")
                            for v in found), found)


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "include_layers", IncludeLayersTest)
