"""aurora.sweep: a sweep from Python, run by the sweep program (the C++
backends, chunks and resume of `rosrun aurora_sweep sweep`), its results
returned as a pandas DataFrame (or a numpy structured array) with the
columns of results.csv, and its summary.json as a dict.

    import aurora
    results, summary = aurora.sweep("positioning_delay", backend="cpu", precision="float")
    results[results.feasible == 1].groupby("delay").size()

`config` is a shipped sweep's name (config/sweeps/NAME.yaml), a path, or a
dict with the sweep file's schema. A progress bar follows the run (tqdm: a
widget in notebooks). Ctrl-C (or a notebook's interrupt) stops the program;
the chunks finished so far stay in `out` and the same call with that `out`
computes only the missing ones (SweepInterrupted says where). A refused
sweep file or option raises ValueError with the program's message."""
import json
import os
import re
import signal
import subprocess
import tempfile
import threading

from aurora.arguments import plain, whole
from aurora.simulation import config_dir
from aurora.widgets_compat import old_ipywidgets

_PROGRESS = re.compile(r"^sweep: (\d+)/(\d+) \(")


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C during aurora.sweep: the finished chunks are in `out`."""

    def __init__(self, message, out):
        KeyboardInterrupt.__init__(self, message)
        self.out = out


def sweep_program():
    """The sweep program of this workspace (catkin's libexec folder of
    aurora_sweep, as rosrun finds it)."""
    from catkin.find_in_workspaces import find_in_workspaces
    found = find_in_workspaces(search_dirs=["libexec"], project="aurora_sweep", path="sweep", first_match_only=True)
    if not found:
        raise ValueError("the sweep program of aurora_sweep is not built in any sourced workspace: build it and "
                         "source the workspace's setup.bash")
    return found[0]


def _config_file(config, tmp):
    if isinstance(config, dict):
        import yaml
        path = os.path.join(tmp, "sweep.yaml")
        with open(path, "w") as f:
            yaml.safe_dump(plain(config, "config"), f)
        return path
    if not isinstance(config, str):
        raise ValueError("config: expected a shipped sweep's name, a path or a dict, got %s" % type(config).__name__)
    if os.path.sep in config or config.endswith(".yaml"):
        if not os.path.exists(config):
            raise ValueError("sweep file '%s' does not exist" % config)
        return config
    path = os.path.join(config_dir(), "sweeps", config + ".yaml")
    if not os.path.exists(path):
        shipped = sorted(n[:-5] for n in os.listdir(os.path.dirname(path)) if n.endswith(".yaml"))
        raise ValueError("sweep '%s' is not a shipped one: accepted %s, a path, or a dict" % (config, ", ".join(shipped)))
    return path


def _whole(name, value):
    return str(whole(value, name, 1, 2 ** 31 - 1, "a whole number", "whole numbers"))


def _command(file, out, backend, precision, threads, chunk_size, output, rows, plots):
    for name, value in (("backend", backend), ("output", output), ("rows", rows)):
        if not isinstance(value, str):
            raise ValueError("%s: expected a word, got %r" % (name, value))
    cmd = [sweep_program(), "--config", file, "--out", out, "--backend", backend, "--output", output, "--rows", rows]
    if precision is not None:
        cmd += ["--precision", str(precision)]
    if threads is not None:
        cmd += ["--threads", _whole("threads", threads)]
    if chunk_size is not None:
        cmd += ["--chunk-size", _whole("chunk_size", chunk_size)]
    if not plots:
        cmd.append("--no-plots")
    return cmd


def _progress_bar(total):
    """tqdm's bar: a widget in notebooks where ipywidgets can draw it (7 and
    later), else text. Debian 12's ipywidgets 6 lacks what tqdm's widget
    sets ('FloatProgress' object has no attribute 'style'), so it gets the
    text bar rather than a traceback and no bar."""
    from tqdm import tqdm as text_tqdm
    kwargs = dict(total=total, unit="sim", unit_scale=True, desc="sweep")
    if old_ipywidgets():
        return text_tqdm(**kwargs)
    try:
        from tqdm.auto import tqdm  # a widget in notebooks
    except ImportError:  # tqdm before 4.31 (Ubuntu 20.04's 4.30)
        return text_tqdm(**kwargs)
    try:
        return tqdm(**kwargs)
    except Exception:  # the widget cannot be built here: the text bar
        return text_tqdm(**kwargs)


def _follow(proc, progress):
    """Reads the program's stderr: progress lines move the bar, the others are kept."""
    bar, lines = None, []
    for line in proc.stderr:
        m = _PROGRESS.match(line)
        if m and progress:
            done, total = int(m.group(1)), int(m.group(2))
            if bar is None:
                bar = _progress_bar(total)
            bar.update(done - bar.n)
        elif not m:
            lines.append(line.rstrip("\n"))
    if bar is not None:
        bar.close()
    return lines


def _run(cmd, progress, out):
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)  # our SIGINT goes to Python; we pass it on
    result = {}
    reader = threading.Thread(target=lambda: result.setdefault("lines", _follow(proc, progress)))
    reader.start()
    try:
        stdout = proc.stdout.read()
        proc.wait()
    except KeyboardInterrupt:
        proc.send_signal(signal.SIGINT)
        proc.wait()
        reader.join()
        done = _chunks_done(out)
        raise SweepInterrupted("sweep interrupted: %d finished chunk%s stay in %s; aurora.sweep(..., out=%r) computes "
                               "only the missing ones" % (done, "" if done == 1 else "s", out, out), out) from None
    reader.join()
    return proc.returncode, stdout, result.get("lines", [])


def _chunks_done(out):
    folder = os.path.join(out, "progress")
    return len([n for n in os.listdir(folder) if n.startswith("chunk_") and n.endswith(".bin")]) \
        if os.path.isdir(folder) else 0  # whole chunks (a chunk is written to .tmp, then renamed)


def read_results(out, as_frame=True):
    """The results of a sweep folder (results.h5, else results.csv), with
    results.csv's columns: a DataFrame, or a numpy structured array."""
    import numpy as np
    h5, csv = os.path.join(out, "results.h5"), os.path.join(out, "results.csv")
    summary = read_summary(out)
    # results.csv's order: the index, the parameters, the result columns.
    names = ["index"] + list(summary["parameters"]) + [c["name"] for c in summary["result_columns"]]
    if os.path.exists(h5):
        import h5py
        with h5py.File(h5, "r") as f:
            missing = [n for n in names if n not in f]
            if missing:
                raise ValueError("'%s' lacks the columns %s of its summary.json" % (h5, ", ".join(missing)))
            columns = {n: f[n][()] for n in names}  # one read per column into its array
    elif os.path.exists(csv):
        if as_frame:  # round-trip parsing: each value the double the program wrote
            import pandas as pd
            return pd.read_csv(csv, float_precision="round_trip")
        table = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding="ascii")
        columns = {n: table[n] for n in table.dtype.names}
    else:
        raise ValueError("'%s' holds no results.h5 or results.csv (a sweep run with --output none?)" % out)
    if as_frame:
        import pandas as pd
        return pd.DataFrame(columns, copy=False)
    arr = np.empty(len(next(iter(columns.values()))), dtype=[(n, c.dtype) for n, c in columns.items()])
    for n, c in columns.items():
        arr[n] = c
    return arr


def read_summary(out):
    """A sweep folder's summary.json as a dict."""
    path = os.path.join(out, "summary.json")
    if not os.path.exists(path):
        raise ValueError("'%s' holds no summary.json: not a sweep's output folder, or its sweep did not finish "
                         "(the same sweep with this folder resumes it)" % out)
    with open(path) as f:
        return json.load(f)


def sweep(config, backend="auto", precision="double", out=None, threads=None, progress=True, as_frame=True,
          output="hdf5", rows="all", plots=False, chunk_size=None):
    """Runs the sweep `config` (a shipped sweep's name, a path, or a dict
    of a sweep file's schema: without `controller` it flies pd_saturated,
    without `task` the thesis's positioning task, as a sweep file does);
    returns (results, summary). backend: auto,
    scalar, cpu or cuda; `precision` double or float (None: the sweep
    file's `precision`); `out` None computes in a temporary folder removed afterwards
    (give `out` to keep the results, plots and chunks, and to resume);
    threads, output (hdf5, csv, both), rows (all, feasible), plots,
    chunk_size: the program's options of those names."""
    keep = out is not None
    with tempfile.TemporaryDirectory() as tmp:
        file = _config_file(config, tmp)
        folder = out if keep else tempfile.mkdtemp(prefix="aurora_sweep_")
        try:
            cmd = _command(file, folder, backend, precision, threads, chunk_size, output, rows, plots)
            rc, _, lines = _run(cmd, progress, folder)
        except SweepInterrupted:
            raise  # the chunks stay, also in a temporary folder: the message names it
        except BaseException:
            if not keep:
                _remove(folder)
            raise
    try:
        if rc != 0:
            message = "\n".join(l for l in lines if l.startswith("sweep:") or l.startswith("usage")) or "\n".join(lines)
            # 2: a refused file or option; 3: the backend cannot run here (no CUDA device): both the
            # caller's choice to correct. A crash (a signal) stays a RuntimeError.
            raise (ValueError if rc in (2, 3) else RuntimeError)(message)
        return read_results(folder, as_frame), read_summary(folder)
    finally:
        if not keep:
            _remove(folder)


def _remove(folder):
    import shutil
    shutil.rmtree(folder, ignore_errors=True)
