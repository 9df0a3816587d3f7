#!/usr/bin/python3
"""Every docs/ page and section the code and the README cite exists: a
citation of a page, with a quoted section name after it or a #anchor, must
name a page under docs/ and one of its headings (or a heading's leading
words before " (" or ":"). A renamed heading or a page never written fails."""
import os
import re
import shlex
import subprocess
import sys
import unittest

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from tools import rosrun  # noqa: E402

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


# A passage of docs/ or the README whose figures a shipped command prints:
#   <!-- printed: flight --formation triangle_ardrones --delay 6 6 6 ; flight ... -->
#   ... figures ...
#   <!-- /printed -->
# Each command (paths relative to the repository) is run; every number
# written with 3 or more decimals between the markers must be one the
# commands print, rounded to the digits written (a table's 0.290 is a
# printed 0.2904). A change that moves a number fails until the docs follow.
PRINTED = re.compile(r"<!-- printed: (.+?) -->(.*?)<!-- /printed -->", re.S)
FIGURE = re.compile(r"(?<![\w.])-?\d+\.(\d{3,})(?![\w.])")
TOOLS = {"flight": ("aurora_control", "flight"), "replay": ("aurora_control", "replay")}


def printed_numbers(root, commands):
    """Every decimal number the commands (`TOOL args ; TOOL args`) print, from the repository's root."""
    numbers = []
    for command in commands.split(" ; "):
        words = shlex.split(command)
        pkg, tool = TOOLS[words[0]]
        p = subprocess.run(rosrun(pkg, tool) + words[1:], cwd=root, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, universal_newlines=True)
        if p.returncode != 0:
            raise AssertionError("'%s' failed: %s" % (command, p.stdout))
        numbers += re.findall(r"-?\d+\.\d+", p.stdout)
    return numbers


def unprinted_figures(root, path):
    """(passage's commands, figure) for each figure of `path` that its commands do not print."""
    missing, passages = [], 0
    for m in PRINTED.finditer(open(path).read()):
        passages += 1
        printed = printed_numbers(root, m.group(1))
        figures = [(f.group(0), len(f.group(1))) for f in FIGURE.finditer(m.group(2))]
        if not figures:
            missing.append((m.group(1), "no figure between its markers"))
        for text, digits in figures:
            if not any("%.*f" % (digits, float(n)) == text for n in printed if len(n.split(".")[1]) >= digits):
                missing.append((m.group(1), text))
    return missing, passages


def sources(root):
    for d, dirs, files in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith(".") and x not in ("build", "out")]
        for name in files:
            if (name.endswith(SOURCES) or name in SCRIPTS) and name != os.path.basename(__file__):
                yield os.path.join(d, name)


class DocsCitationsTest(unittest.TestCase):
    def test_every_printed_figure_is_what_its_command_prints(self):
        """Issue 51 (11): figures of docs/formation.md and docs/predictor.md had drifted from what the shipped
        commands print. Every passage between printed markers is checked against its commands' output."""
        root = repo_root()
        if not os.path.isdir(os.path.join(root, "docs")):
            self.skipTest("no source tree beside %s (an install space)" % root)
        problems, passages = [], 0
        pages = [os.path.join(root, "docs", f) for f in sorted(os.listdir(os.path.join(root, "docs"))) if f.endswith(".md")]
        for path in pages + [os.path.join(root, "README.md")]:
            missing, n = unprinted_figures(root, path)
            passages += n
            problems += ["%s: %s not printed by '%s'" % (os.path.relpath(path, root), f, c) for c, f in missing]
        self.assertGreaterEqual(passages, 7, "the printed markers of docs/formation.md and docs/predictor.md")
        self.assertEqual(problems, [], "\n".join(problems))

    def test_the_lap_2_table_is_what_flight_prints(self):
        """Issue 31: all 12 cells differed from flight's output (the table of docs/simulation.md)."""
        root = repo_root()
        text = open(os.path.join(root, "docs", "simulation.md")).read()
        rows = re.findall(r"^\| (pd_saturated|underactuated) \| (circle|lemniscate) \| (.+) \|$", text, re.M)
        self.assertEqual(len(rows), 4, "docs/simulation.md's lap-2 table has 4 rows")
        for law, task, cells in rows:
            for delay, cell in zip((0, 5, 10), cells.split(" | ")):
                out = subprocess.run(rosrun("aurora_control", "flight") + ["--controller",
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
