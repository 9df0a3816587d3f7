#!/usr/bin/python3
"""Checks that no header of a package includes a header of a higher concept
layer of the same package (docs/architecture.md, "Layers"): within
include/<package>/, each folder is a layer, listed lowest first in LAYERS
("" the package's top folder); a header may include its own layer's and
lower ones' headers only. A folder not listed is reported too (list it).

    scripts/check_include_layers.py [REPO]    # exit 1 and the includes that run up

Sources (src/, test/) may include any layer: they sit above them all."""
import os
import re
import sys

LAYERS = {
    "aurora_common": ["", "testing", "ros"],
    "aurora_sim": ["", "vehicle", "ros"],
    "aurora_control": ["params", "task", "law", "link", "predictor", "loop", "robot", "formation", "ros"],
    "aurora_sweep": [""],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/([^"]+)"', re.M)


def layer_of(relative):
    folder = os.path.dirname(relative)
    return folder.split("/")[0] if folder else ""


def violations(repo, layers=LAYERS):
    """Each include that runs up a layer, or sits in an unlisted folder."""
    found = []
    for package, order in sorted(layers.items()):
        root = os.path.join(repo, package, "include", package)
        for dirpath, _, files in os.walk(root):
            for name in sorted(files):
                if not name.endswith((".h", ".cuh")):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                here = layer_of(rel)
                if here not in order:
                    found.append("%s/%s: its folder '%s' is not a layer of %s (list it in LAYERS)" % (
                        package, rel, here, package))
                    continue
                with open(path) as f:
                    text = f.read()
                for pkg, target in INCLUDE.findall(text):
                    there = layer_of(target)
                    if pkg != package or there not in order:
                        continue
                    if order.index(there) > order.index(here):
                        found.append("%s/%s includes %s/%s: layer '%s' is above '%s'" % (
                            package, rel, pkg, target, there, here))
    return found


def main(argv):
    repo = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.realpath(__file__)), "..")
    found = violations(repo)
    for v in found:
        print(v)
    if not found:
        print("check_include_layers: no include runs up a layer (%s)" % ", ".join(sorted(LAYERS)))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
