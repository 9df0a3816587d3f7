"""The figures of bench/python.sh (run it, not this file)."""
import os
import resource
import statistics
import subprocess
import tempfile
import time
import timeit

import yaml

import aurora


def simulate_ms():
    aurora.simulate("pd_saturated", "mission4")  # the config lookup, once
    times = timeit.repeat(lambda: aurora.simulate("pd_saturated", "mission4"), number=20, repeat=10)
    return 1000 * min(times) / 20, 1000 * statistics.median(times) / 20


def cli_seconds(config, out):
    t = time.perf_counter()
    subprocess.run([aurora.sweep_program(), "--config", config, "--out", out, "--backend", "cpu", "--output", "hdf5",
                    "--no-plots", "--quiet", "--overwrite"], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - t, aurora.read_summary(out)["timing"]["compute_s"]


def python_seconds(config):
    t = time.perf_counter()
    _, summary = aurora.sweep(config, backend="cpu", progress=False)
    return time.perf_counter() - t, summary["timing"]["compute_s"]


def sweep_vs_cli(rounds=5):
    config = os.path.join(aurora.simulation.config_dir(), "sweeps", "positioning_delay.yaml")
    cli, py = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(rounds):  # interleaved: the machine's load hits both alike
            cli.append(cli_seconds(config, os.path.join(tmp, "cli")))
            py.append(python_seconds(config))
    med = lambda xs, i: statistics.median(x[i] for x in xs)  # noqa: E731
    return med(cli, 0), med(cli, 1), med(py, 0), med(py, 1)


def peak_memory_1m():
    with open(os.path.join(aurora.simulation.config_dir(), "sweeps", "positioning_delay.yaml")) as f:
        d = yaml.safe_load(f)
    p = d["sweep"]["parameters"]
    p["kp"]["count"], p["kd"]["count"] = 64, 64
    p["delay"] = {"from": 0, "to": 255, "count": 256}
    d["sweep"]["precision"] = "float"
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    t = time.perf_counter()
    results, summary = aurora.sweep(d, backend="cpu", progress=False)
    seconds = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    child = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    data = results.memory_usage(index=False, deep=True).sum() / 2 ** 20
    return len(results), seconds, summary["timing"]["compute_s"], before, after, data, child


def main():
    best, median = simulate_ms()
    print("aurora.simulate, 60 s flight (mission4, 1,801 steps): %.2f ms best, %.2f ms median" % (best, median))
    cli_wall, cli_compute, py_wall, py_compute = sweep_vs_cli()
    print("thesis grid, cpu backend, medians of 5 interleaved rounds:")
    print("  sweep program: %.2f s wall (compute %.2f s)" % (cli_wall, cli_compute))
    print("  aurora.sweep : %.2f s wall (compute %.2f s), returning the DataFrame" % (py_wall, py_compute))
    print("  compute time ratio aurora.sweep / program: %.3f; wall ratio %.3f" % (py_compute / cli_compute,
                                                                               py_wall / cli_wall))
    n, seconds, compute, before, after, data, child = peak_memory_1m()
    print("1M grid (64 x 64 x 256, float): %d results in %.1f s (compute %.1f s)" % (n, seconds, compute))
    print("  Python peak RSS %.0f MiB before, %.0f MiB after; the DataFrame holds %.0f MiB; "
          "the sweep program's peak RSS %.0f MiB" % (before, after, data, child))


if __name__ == "__main__":
    main()
