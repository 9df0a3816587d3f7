#!/usr/bin/python3
"""Every docs/ page and section the code and the README cite exists: a
citation of a page, with a quoted section name after it or a #anchor, must
name a page under docs/ and one of its headings (or a heading's leading
words before " (" or ":"). A renamed heading or a page never written fails."""
import os
import re
import subprocess
import sys
import unittest

SOURCES = (".h", ".cpp", ".cu", ".py", ".cfg", ".launch", ".sh", ".md", ".txt")
SCRIPTS = ("report", "plot_sweep", "aurora_launch", "drone_marker")
# docs/PAGE.md, or a bare (PAGE.md in a comment; then a #anchor or a quoted section.
CITATION = re.compile(r'(?:docs/|(?<=\())([\w-]+\.md)(?:#([\w-]+)|,?\s*\(?"([^"]+)")?')


def repo_root():
    if len(sys.argv) > 1 and os.path.isdir(os.path.join(sys.argv[1], "docs")):
        return sys.argv[1]
    pkg = subprocess.run(["rospack", "find", "aurora_control"], stdout=subprocess.PIPE,
                         universal_newlines=True, check=True).stdout.strip()
    return os.path.dirname(os.path.realpath(pkg))


def headings(path):
    with open(path) as f:
        return [l.lstrip("#").strip() for l in f if l.startswith("#")]


def cites(section, heading):
    """A citation names a heading, or its leading words before " (" or ":"."""
    return heading == section or heading.startswith(section + " (") or heading.startswith(section + ":")


def anchor(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to '-'."""
    return re.sub(r"\s", "-", re.sub(r"[^\w\s-]", "", heading.lower()))


def flattened(path):
    """The text with comment markers at line starts dropped, so that a
    section name wrapped over two comment lines reads as one."""
    with open(path, errors="replace") as f:
        lines = [re.sub(r"^\s*(//|#|\*)\s?", "", l.rstrip("\n")) for l in f]
    return " ".join(lines)


def sources(root):
    for d, dirs, files in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith(".") and x not in ("build", "out")]
        for name in files:
            if (name.endswith(SOURCES) or name in SCRIPTS) and name != os.path.basename(__file__):
                yield os.path.join(d, name)


class DocsCitationsTest(unittest.TestCase):
    def test_the_lap_2_table_is_what_flight_prints(self):
        """Issue 31: all 12 cells differed from flight's output (the table of docs/simulation.md)."""
        root = repo_root()
        text = open(os.path.join(root, "docs", "simulation.md")).read()
        rows = re.findall(r"^\| (pd_saturated|underactuated) \| (circle|lemniscate) \| (.+) \|$", text, re.M)
        self.assertEqual(len(rows), 4, "docs/simulation.md's lap-2 table has 4 rows")
        for law, task, cells in rows:
            for delay, cell in zip((0, 5, 10), cells.split(" | ")):
                out = subprocess.run(["rosrun", "aurora_control", "flight", "--controller",
                                      os.path.join(root, "config", "controllers", law + ".yaml"), "--task",
                                      os.path.join(root, "config", "tasks", task + ".yaml"), "--delay", str(delay)],
                                     stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
                rms, worst = re.search(r"lap 2: RMS tracking error ([\d.]+) m, max ([\d.]+) m", out).groups()
                self.assertEqual(cell, "%.3f / %.3f m" % (float(rms), float(worst)), (law, task, delay))

    def test_every_cited_page_and_section_exists(self):
        root = repo_root()
        if not os.path.isdir(os.path.join(root, "docs")):
            self.skipTest("no source tree beside %s (an install space): the sources are checked from the "
                          "devel space" % root)
        problems, cited = [], 0
        for path in sources(root):
            text = flattened(path)
            for m in CITATION.finditer(text):
                cited += 1
                page, link, section = m.groups()
                where = os.path.relpath(path, root)
                doc = os.path.join(root, "docs", page)
                if not os.path.exists(doc):
                    problems.append("%s cites docs/%s, which does not exist" % (where, page))
                    continue
                names = headings(doc)
                if link and link not in [anchor(h) for h in names]:
                    problems.append("%s links docs/%s#%s: no such heading" % (where, page, link))
                if section and not any(cites(re.sub(r"\s+", " ", section), h) for h in names):
                    problems.append('%s cites docs/%s "%s": no such heading' % (where, page, section))
        self.assertGreater(cited, 20, "the scan found almost no citations: is the root right?")
        self.assertEqual(problems, [], "\n".join(problems))


if __name__ == "__main__":
    if "--root" in sys.argv:
        sys.argv = [sys.argv[0], sys.argv[sys.argv.index("--root") + 1]]
        unittest.main(argv=[sys.argv[0]])
    import rostest
    rostest.rosrun("aurora_tests", "docs_citations", DocsCitationsTest)
