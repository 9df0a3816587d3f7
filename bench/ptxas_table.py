#!/usr/bin/env python3
"""The table of bench/cuda_registers.sh: reads `nvcc -Xptxas -v` output on
stdin and prints, per sweep kernel instantiation, its template arguments
(law, shape, precision, history capacity, link, predictor), registers per
thread, stack frame and spills. Names are demangled with c++filt, so a
renamed law, vehicle or shape still shows; exits 1 when no entry function
of the sweep kernels (sweepKernel, formationKernel) is found."""
import re
import subprocess
import sys

KERNELS = ("sweepKernel", "formationKernel")


def demangle(names):
    if not names:
        return []
    out = subprocess.run(["c++filt"], input="\n".join(names), stdout=subprocess.PIPE, universal_newlines=True,
                         check=True).stdout
    return out.splitlines()


def template_args(text, kernel):
    """The top-level template arguments of `kernel<...>` in a demangled name."""
    start = text.find(kernel + "<")
    if start < 0:
        return None
    i, depth, args, cur = start + len(kernel) + 1, 1, [], ""
    while i < len(text) and depth > 0:
        c = text[i]
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
            if depth == 0:
                break
        if c == "," and depth == 1:
            args.append(cur.strip())
            cur = ""
        else:
            cur += c
        i += 1
    args.append(cur.strip())
    return args


# The AR.Drone's laws by their LawType (aurora_control/law/ardrone2/control_law.h's order).
LAW_TYPES = {"(LawType)0": "pd_saturated", "(LawType)1": "underactuated"}


def short(name):
    """aurora_control::ArdroneLaw<(aurora_control::LawType)1> -> ArdroneLaw<underactuated>."""
    name = re.sub(r"\b[a-z_0-9]+::", "", name).replace("(anonymous namespace)::", "")
    for k, v in LAW_TYPES.items():
        name = name.replace(k, v)
    return name


def describe(kernel, args):
    if kernel == "sweepKernel":  # <Law, T, Capacity, Linked, Predicted>
        law, t, cap, linked = args[:4]
        predicted = args[4] if len(args) > 4 else "false"
        return [short(law), "-", t, cap, "model" if linked == "true" else "ideal",
                "yes" if predicted == "true" else "no"]
    law, shape, t, cap, linked = args[:5]  # formationKernel<Law, Shape, T, Capacity, Linked>
    return [short(law), short(shape), t, cap, "model" if linked == "true" else "ideal", "no"]


def entries(lines):
    """(mangled name, stack, spill stores, spill loads, registers) per entry function."""
    found, name, frame = [], None, None
    for line in lines:
        m = re.search(r"Compiling entry function '(\w+)'", line)
        if m:
            name, frame = m.group(1), None
            continue
        m = re.search(r"(\d+) bytes stack frame, (\d+) bytes spill stores, (\d+) bytes spill loads", line)
        if m and name:
            frame = m.groups()
            continue
        m = re.search(r"Used (\d+) registers", line)
        if m and name:
            found.append((name,) + (frame or ("0", "0", "0")) + (m.group(1),))
            name = None
    return found


def main():
    found = entries(sys.stdin.read().splitlines())
    names = demangle([f[0] for f in found])
    rows = []
    for f, text in zip(found, names):
        kernel = next((k for k in KERNELS if k + "<" in text), None)
        args = template_args(text, kernel) if kernel else None
        if args:
            rows.append(describe(kernel, args) + [f[4], f[1], f[2] + "/" + f[3]])
    if not rows:
        sys.exit("cuda_registers: no sweep kernel (%s) among the %d entry functions ptxas reported: "
                 "the kernels were renamed, or the log is not `nvcc -Xptxas -v` output" % (", ".join(KERNELS), len(found)))
    head = ["law", "shape", "type", "capacity", "link", "predictor", "registers", "stack [B]", "spills st/ld"]
    widths = [max(len(str(r[i])) for r in rows + [head]) for i in range(len(head))]
    for r in [head] + sorted(rows):
        print("  ".join(str(v).ljust(w) for v, w in zip(r, widths)))
    print("%d kernel instantiations" % len(rows))


if __name__ == "__main__":
    main()
