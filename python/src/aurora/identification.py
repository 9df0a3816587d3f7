"""Identify a recorded loop from its bag (docs/identify.md):

    rosrun aurora identify BAG --out DIR [--ns NAME] [--max-delay N] [--window N] [--study NAME|FILE]

Measures the loop's timing from the bag's stamps and steps (the feedback
delay of each cycle, the state and command streams' rates, jitter and
losses) and fits the vehicle's model with the actuation delay that fits
best (each vehicle its own way, docs/identify.md: by least squares where
its model is linear in its parameters, else by output error through its
simulator), flies the recorded commands open loop
through the identified and the nominal model, then writes DIR/identify.json,
DIR/link.yaml (a link file flight --link, the nodes and sweeps take),
DIR/vehicle.yaml (where the model was identified), figures and report.md.
The same from Python: aurora.identify(bag) returns the identify.json
object. The arithmetic is aurora.identify_core's (ROS-free)."""
import argparse
import json
import os
import shutil
import sys
import tempfile

import numpy as np

from aurora import formation_report, identify_core as core
from aurora import report
from aurora.identify_model import key_parent, key_value, open_loop_flyer
from aurora.identify_vehicles import MODELS

# Fewer state steps than this identify nothing (10 s at 30 Hz).
MIN_STEPS = 300
# Control.mode in the supervisor's take-off phase (its first word).
TAKEOFF_MODE = "takeoff"


class IdentifyError(Exception):
    """A problem the user can act on; printed without a traceback."""


def parse_args(argv):
    p = argparse.ArgumentParser(prog="identify", description=__doc__.split("\n\n")[0])
    p.add_argument("bag", help="the .bag file (sim.launch or real.launch record:=true)")
    p.add_argument("--out", required=True, help="output folder (created; its identify files are replaced)")
    p.add_argument("--ns", default=None, help="the robot's namespace (default: the bag's only one)")
    p.add_argument("--max-delay", type=int, default=15,
                   help="largest actuation delay tried [samples] (default 15: 0.5 s at 30 Hz)")
    p.add_argument("--window", type=int, default=1,
                   help="steps summed per equation against position noise [samples; 1: each step] "
                        "(docs/identify.md, eq. I4; 15 for a motion capture's millimetres)")
    p.add_argument("--study", default=None,
                   help="a single-robot sweep (a shipped NAME or a FILE) of the bag's vehicle, run as shipped and "
                        "with DIR's vehicle.yaml and link.yaml; both side by side in DIR/study_compare")
    args = p.parse_args(argv)
    if not 0 <= args.max_delay <= 300:
        p.error("--max-delay %d is refused: accepted 0 .. 300 samples" % args.max_delay)
    if not 1 <= args.window <= 300:
        p.error("--window %d is refused: accepted 1 .. 300 samples" % args.window)
    return args


def read_loop(path, ns=None):
    """The robot's states and controls of the bag at `path`, as arrays."""
    try:
        bag = report.open_bag(path)
    except report.ReportError as e:
        raise IdentifyError(str(e))
    try:
        topics = report.topics_of(bag)
        if formation_report.has_formation(topics) and ns is None:
            raise IdentifyError("bag '%s' is a formation's: identify one robot at a time with --ns NAME (its "
                                "namespaces: %s)" % (path, ", ".join(report.find_namespaces(topics)) or "none"))
        try:
            data = report.read_bag(bag, None if ns is None else [ns])
        except report.ReportError as e:
            raise IdentifyError(str(e).replace("the report needs", "identify needs").replace(
                "has no drone to report", "has no robot to identify"))
    finally:
        bag.close()
    if len(data) > 1:
        raise IdentifyError("bag '%s' holds %d robots (%s): choose one with --ns NAME" % (path, len(data), ", ".join(data)))
    name, d = next(iter(data.items()))
    return name, loop_arrays(d)


def loop_arrays(d):
    """States (steps, stamps, X) and controls (steps, used steps, pending,
    arrived, law ran, taking off, commands as applied and their ages,
    stamps) of one robot's bag data."""
    states = sorted({s.step: s for s in d["states"]}.values(), key=lambda s: s.step)
    controls = [d["controls"][k] for k in sorted(d["controls"])]
    first = controls[0]
    return {
        "vehicle": first.vehicle, "Ts": first.sample_time,
        "state_steps": np.array([s.step for s in states], dtype=np.int64),
        "state_stamps": np.array([s.header.stamp.to_sec() for s in states]),
        "X": np.array([report.state_values(s) for s in states], dtype=float),
        "control_steps": np.array([c.step for c in controls], dtype=np.int64),
        "used_steps": np.array([c.state_used.step for c in controls], dtype=np.int64),
        "pending": np.array([c.delay_pending for c in controls], dtype=np.int64),
        "arrived": np.array([c.state_arrived for c in controls], dtype=bool),
        "law_ran": np.array([c.law_ran for c in controls], dtype=bool),
        # The supervisor's take-off phase (flight_supervisor.h): the law holds the start while a real drone's
        # driver climbs by itself, so the commands sent are not what it flies.
        "taking_off": np.array([c.mode.startswith(TAKEOFF_MODE) for c in controls], dtype=bool),
        # As the robot applies them: after the controller's own link (docs/links.md), the command's age.
        "applied": np.array([list(c.command)[:len(first.command_names)] for c in controls], dtype=float),
        "command_age": np.array([c.command_age for c in controls], dtype=np.int64),
        "control_stamps": np.array([c.header.stamp.to_sec() for c in controls]),
    }


def timing(loop):
    """Eqs. I1, I2: the feedback delays of the cycles the law flew once the
    delay was in force (delay_pending 0) and a state had come over the link
    (until one does, the law flies the current one, of age 0: links.md; the
    leading cycles of age 0 where later ones are older), the streams'
    timing, the uplink (eq. I2b)."""
    ages = core.feedback_delays(loop["control_steps"], loop["used_steps"])
    older = np.flatnonzero(ages > 0)
    start = older[0] if older.size else 0
    steady = (loop["pending"] == 0) & loop["law_ran"] & (np.arange(len(ages)) >= start)
    delays = ages[steady]
    t = {"feedback_delay_samples": core.percentiles(delays), "feedback_delays": delays,
         "state_stream": core.stream_timing(loop["state_steps"], loop["state_stamps"], loop["Ts"]),
         "command_stream": core.stream_timing(loop["control_steps"], loop["control_stamps"], loop["Ts"]),
         "state_intervals": np.diff(loop["state_stamps"])}
    up = link_direction(delays[loop["arrived"][steady]], loop["used_steps"][steady])
    t.update({"uplink_delay": up["delay"], "uplink_jitter": up["jitter"], "uplink_loss": up["loss"],
              "uplink_loss_stderr": up["loss_stderr"], "states_seen": up["seen"]})
    t.update(downlink(loop))
    return t


def link_direction(on_arrival, used):
    """Eq. I2b, either direction: its base delay and uniform jitter from the
    ages of packets on the cycle they took effect (D + J each: a held one's
    age is not its packet's), its loss from the share of the steps sent
    that ever took effect (`used`; inverting seen_share, with its standard
    error by the delta method)."""
    if on_arrival.size == 0:
        return {"delay": 0, "jitter": 0, "loss": 0.0, "loss_stderr": None, "seen": None}
    base = int(on_arrival.min())
    jitter = int(on_arrival.max()) - base
    seen_steps = np.unique(used)
    n = int(seen_steps.max() - seen_steps.min()) + 1
    seen = seen_steps.size / n
    loss = core.link_loss(seen, jitter)
    lo, hi = max(loss - 1e-4, 0.0), min(loss + 1e-4, 1.0)
    slope = (core.seen_share(hi, jitter) - core.seen_share(lo, jitter)) / (hi - lo)
    stderr = float(np.sqrt(seen * (1.0 - seen) / n) / abs(slope)) if slope else None
    return {"delay": base, "jitter": jitter, "loss": loss, "loss_stderr": stderr, "seen": seen}


def downlink(loop):
    """Eq. I2c: the controller's own downlink (its link file's, docs/links.md)
    from the commands' ages (Control.command_age: steps since the command the
    robot applies was sent; -1 before the first): the command of step k -
    age took effect on the cycles it replaced an older one. A real radio's
    own losses beyond it are not in a bag."""
    ok = loop["command_age"] >= 0
    age = loop["command_age"][ok]
    applied = (loop["control_steps"] - loop["command_age"])[ok]
    took_effect = np.concatenate([[True], np.diff(applied) > 0]) if applied.size else np.zeros(0, dtype=bool)
    d = link_direction(age[took_effect], applied)
    return {"downlink_delay": d["delay"], "downlink_jitter": d["jitter"], "downlink_loss": d["loss"],
            "downlink_loss_stderr": d["loss_stderr"]}


def commands_by_step(loop):
    """The commands as the robot applies them (after the controller's own
    link: I2c), one row per state step (a step the controller did not
    answer holds the command before it, as the vehicle does)."""
    X_steps = loop["state_steps"]
    U = np.zeros((len(X_steps), loop["applied"].shape[1]))
    at = {int(s): i for i, s in enumerate(loop["control_steps"])}
    last = np.zeros(U.shape[1])
    for i, s in enumerate(X_steps):
        if int(s) in at:
            last = loop["applied"][at[int(s)]]
        U[i] = last
    return U


def contiguous(loop):
    """The longest run of consecutive state steps (the differences need them)
    while the law flew the robot past its take-off (until then, a real
    drone's driver takes off by itself and the commands sent are not what it
    flies)."""
    s = loop["state_steps"]
    flown = np.isin(s, loop["control_steps"][loop["law_ran"] & ~loop["taking_off"]])
    breaks = np.flatnonzero((np.diff(s) != 1) | ~flown[1:] | ~flown[:-1])
    starts = np.concatenate([[0], breaks + 1])
    ends = np.concatenate([breaks + 1, [len(s)]])
    i = int(np.argmax(ends - starts))
    return slice(int(starts[i]), int(ends[i]))


def known_vehicle(loop):
    """The bag's vehicle, refused when this tool fits no model of it."""
    vehicle = loop["vehicle"]
    if vehicle not in MODELS:
        raise IdentifyError("vehicle '%s' (the bag's Control.vehicle) is unknown to identify: accepted %s"
                            % (vehicle, ", ".join(sorted(MODELS))))
    return vehicle


def series_of(loop, run, phases):
    """The run's states and commands on uniform grids (eq. I4b), one per
    grid phase: [(phase, X, U)]; a run whose stamps are already on one
    (lockstep) as it is, its phase None."""
    stamps = loop["state_stamps"][run]
    if core.on_uniform_grid(loop["state_steps"][run], stamps, loop["Ts"]):
        return [(None, loop["X"][run], commands_by_step(loop)[run])]
    back = np.flatnonzero(np.diff(stamps) <= 0)
    if back.size:
        k = int(loop["state_steps"][run][back[0] + 1])
        raise IdentifyError("the state of step %d is stamped %.6f s, not after the step before it (%.6f s): identify "
                            "reads a realtime loop's states by their stamps (docs/identify.md, eq. I4b), so they must "
                            "increase with the steps; record the estimator's states as they are published"
                            % (k, stamps[back[0] + 1], stamps[back[0]]))
    series = []
    for phase in phases:
        grid = core.time_grid(stamps, loop["Ts"], phase)
        series.append((phase, core.states_on_grid(stamps, loop["X"][run], grid),
                       core.commands_on_grid(grid, loop["Ts"], loop["control_stamps"], loop["applied"])))
    return series


def fitted_model(loop, max_delay, window, nominal_path, nominal):
    """The vehicle's model (eqs. I3-I7) at the best actuation delay (and,
    on a realtime loop, grid phase: eq. I4b), around its nominal file (its
    path and content)."""
    vehicle = known_vehicle(loop)
    run = contiguous(loop)
    steps = run.stop - run.start
    if steps < MIN_STEPS:
        raise IdentifyError("the bag's longest run of consecutive states is %d steps (%.1f s): identify needs %d "
                            "(%.0f s); record a longer flight" % (steps, steps * loop["Ts"], MIN_STEPS,
                                                                   MIN_STEPS * loop["Ts"]))
    fit = MODELS[vehicle].fit(nominal_path, nominal)
    best = None
    for phase, X, U in series_of(loop, run, MODELS[vehicle].phases):
        delay, tried = core.best_delay(lambda d: fit(X, U, loop["Ts"], d, window, max_delay), max_delay)
        if best is None or tried[delay]["rss"] < best[1][delay]["rss"]:
            best = (delay, tried, phase, X, U)
    delay, tried, phase, X, U = best
    result = tried[delay]
    result["actuation_delay_samples"] = delay
    result["residual_by_delay"] = {d: tried[d]["rss"] for d in tried}
    result["grid_phase"] = phase
    result["series"] = (X, U)
    result["Ts"] = loop["Ts"]
    return result


def nominal_vehicle(vehicle):
    import yaml
    from aurora.simulation import config_dir
    path = os.path.join(config_dir(), "vehicles", vehicle + ".yaml")
    with open(path) as f:
        return path, yaml.safe_load(f)


def parameter_table(model, nominal, vehicle):
    """Each parameter of the fit `model` of `vehicle` (its Model, MODELS) by
    key: value, stderr, nominal, identified (excited axis, positive unless
    signed, within eq. I7's bounds where bounded, standard error below a
    tenth of the value) and why not."""
    table = {}
    for key in model["parameters"]:  # the regression's order
        value, stderr = model["parameters"][key]
        axis = vehicle.excited_by(key)
        excited = model["spread"][axis] >= core.MIN_EXCITATION
        inside = key not in vehicle.bounded or 0.1 < value / key_value(nominal, key) < 10.0  # eq. I7's bounds
        ok = excited and inside and (value > 0 or key in vehicle.signed) and stderr < 0.1 * abs(value)
        why = ("" if ok else "its axis was not excited (command spread %.3g < %g)" % (model["spread"][axis],
               core.MIN_EXCITATION) if not excited else "the fit is not determined (%.4g +- %.2g)" % (value, stderr))
        table[key] = {"value": value if ok else key_value(nominal, key), "stderr": stderr if ok else None,
                      "nominal": key_value(nominal, key), "identified": bool(ok)}
        if why:
            table[key]["why_not"] = why
    return table


def link_of(t, actuation_delay):
    """The link file's content (docs/links.md): the uplink's base delay,
    uniform jitter and loss of eq. I2b; the downlink's delay the actuation
    delay (I5; the controller's own downlink's where it was not measured),
    its jitter and loss the controller's own downlink's (I2c; a real
    radio's own losses are not in a bag)."""
    def direction(delay, jitter, loss):
        d = {"delay": int(delay)}
        if jitter > 0:
            d["jitter"] = {"kind": "uniform", "max": int(jitter)}
        if loss > 0:
            d["loss"] = round(loss, 6)
        return d
    up = direction(t["uplink_delay"], t["uplink_jitter"], t["uplink_loss"])
    down = direction(t["downlink_delay"] if actuation_delay is None else actuation_delay, t["downlink_jitter"],
                     t["downlink_loss"])
    return {"link": {"uplink": up, "downlink": down, "seed": 1}}


def identify(bag, ns=None, max_delay=15, window=1, out=None):
    """What `rosrun aurora identify` writes as identify.json, as a dict;
    with `out`, the files too. Raises ValueError on bad input."""
    name, loop = bag_loop(bag, ns)
    return identify_loop(bag, name, loop, max_delay, window, out)


def bag_loop(bag, ns=None):
    """The robot's name and loop as identify reads them from the bag
    (read_loop), refused (ValueError) when too short to identify."""
    try:
        name, loop = read_loop(bag, ns)
    except IdentifyError as e:
        raise ValueError(str(e)) from None
    if len(loop["state_steps"]) < MIN_STEPS:
        raise ValueError("bag '%s' holds %d states of %s (%.1f s): identify needs %d (%.0f s)"
                         % (bag, len(loop["state_steps"]), name, len(loop["state_steps"]) * loop["Ts"],
                            MIN_STEPS, MIN_STEPS * loop["Ts"]))
    return name, loop


def identify_loop(bag, name, loop, max_delay, window, out):
    """identify() of a loop bag_loop read."""
    try:
        result = summary(bag, name, loop, max_delay, window)
    except IdentifyError as e:
        raise ValueError(str(e)) from None
    if out is not None:
        write_all(out, result)
    return result["json"]


def summary(bag, name, loop, max_delay, window):
    t = timing(loop)
    nominal_path, nominal = nominal_vehicle(known_vehicle(loop))
    model = fitted_model(loop, max_delay, window, nominal_path, nominal)
    j = {"vehicle": loop["vehicle"], "bag": os.path.abspath(bag), "namespace": name, "sample_time_s": loop["Ts"],
         "feedback_delay_samples": int(round(t["feedback_delay_samples"]["median"])),
         "feedback_delay_distribution": t["feedback_delay_samples"], "actuation_delay_samples": None,
         "state_stream": t["state_stream"], "command_stream": t["command_stream"], "uplink_loss": t["uplink_loss"],
         "uplink_loss_stderr": t["uplink_loss_stderr"], "states_seen": t["states_seen"],
         "downlink_loss": t["downlink_loss"], "downlink_loss_stderr": t["downlink_loss_stderr"],
         "command_path_samples": {"link": t["downlink_delay"], "beyond_link": None},  # the fit's: below
         "parameters": {}, "fit": {}, "model": "identified"}
    vehicle_file = None
    j["parameters"] = parameter_table(model, nominal, MODELS[loop["vehicle"]])
    j["fit"] = {axis: f["nrmse"] for axis, f in model["fit"].items()}
    j["nominal_vehicle_file"] = nominal_path
    if any(p["identified"] for p in j["parameters"].values()):
        vehicle_file = vehicle_yaml(nominal, j["parameters"])
        model["open_loop"] = open_loop_comparison(loop["vehicle"], nominal_path, vehicle_file, model)
        j["open_loop_rms"] = {which: r["rms"] for which, r in model["open_loop"]["models"].items()}
        # I5: the controller's own downlink's base delay (I2c) and what the fit finds beyond it.
        beyond = model["actuation_delay_samples"]
        j["actuation_delay_samples"] = t["downlink_delay"] + beyond
        j["command_path_samples"] = {"link": t["downlink_delay"], "beyond_link": beyond}
        j["residual_by_actuation_delay"] = {str(t["downlink_delay"] + d): r for d, r in model["residual_by_delay"].items()}
        j["grid_phase"] = model["grid_phase"]  # eq. I4b: null where the states were on a uniform grid
    else:
        j["model"] = "nothing identifiable: " + "; ".join(
            "%s: %s" % (k, p["why_not"]) for k, p in j["parameters"].items())
    j["link"] = link_of(t, j["actuation_delay_samples"])["link"]
    j["vehicle_file_written"] = vehicle_file is not None
    return {"json": j, "timing": t, "model": model if vehicle_file is not None else None, "vehicle_file": vehicle_file}


def vehicle_yaml(nominal, parameters):
    """The bag's vehicle file: the nominal one with the identified values."""
    import copy
    v = copy.deepcopy(nominal)
    for key, p in parameters.items():
        parent, name = key_parent(v, key)
        parent[name] = p["value"]
    return v


def open_loop_comparison(vehicle, nominal_path, identified, model):
    """The recorded commands flown open loop (eq. I7's segments, at the
    identified actuation delay) through the identified and the nominal
    model: each one's poses and their RMS error [m, rad] against the
    recorded ones."""
    import yaml
    X, U = model["series"]
    Ua = core.applied(U, model["actuation_delay_samples"])
    starts = core.segment_starts(len(X))
    X_model = MODELS[vehicle].state(X, model["Ts"])
    measured = core.segment_poses(X, starts)
    with tempfile.NamedTemporaryFile("w", suffix=".yaml") as f:
        yaml.safe_dump(identified, f)
        f.flush()
        files = {"identified": f.name, "nominal": nominal_path}
        from aurora import _core
        ones = [1.0] * len(_core.vehicle_factor_names(vehicle))
        flown = {which: open_loop_flyer(vehicle, path)(ones, X_model, Ua, starts, core.SEGMENT, core.FORCED)
                 for which, path in files.items()}
    models = {}
    for which, poses in flown.items():
        e = core.pose_error(poses, measured).reshape(-1, 6)
        models[which] = {"poses": poses[..., :6], "rms": {name: float(np.sqrt(np.mean(e[:, i] ** 2)))
                                                          for i, name in enumerate(core.POSE)}}
    return {"starts": starts, "models": models}


def write_all(out, result):
    """Every file into a fresh folder beside `out`, then moved in: an
    interrupted run leaves nothing half-written."""
    os.makedirs(out, exist_ok=True)
    stage = tempfile.mkdtemp(prefix=".identify_", dir=out)
    try:
        write_files(stage, result)
        for f in os.listdir(stage):
            os.replace(os.path.join(stage, f), os.path.join(out, f))
        if result["vehicle_file"] is None and os.path.exists(os.path.join(out, "vehicle.yaml")):
            os.remove(os.path.join(out, "vehicle.yaml"))  # an earlier run's: not this bag's
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def write_files(d, result):
    import yaml
    j = result["json"]
    with open(os.path.join(d, "identify.json"), "w") as f:
        json.dump(j, f, indent=2)
    with open(os.path.join(d, "link.yaml"), "w") as f:
        f.write("# The link identified from bag %s (rosrun aurora identify; docs/identify.md)\n" % j["bag"])
        yaml.safe_dump({"link": j["link"]}, f, sort_keys=False)
    if result["vehicle_file"] is not None:
        with open(os.path.join(d, "vehicle.yaml"), "w") as f:
            f.write("# %s identified from bag %s (rosrun aurora identify; docs/identify.md): the nominal file's\n"
                    "# values where a parameter was not identified (the report says why) or is not fitted\n"
                    % (j["vehicle"], j["bag"]))
            yaml.safe_dump(result["vehicle_file"], f, sort_keys=False)
    figures(d, result)
    with open(os.path.join(d, "report.md"), "w") as f:
        f.write(markdown(j))


def figures(d, result):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = result["timing"]
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.5))
    delays = t["feedback_delays"]
    if delays.size:
        ax[0].hist(delays, bins=np.arange(delays.min() - 0.5, delays.max() + 1.5, 1.0))
    ax[0].set_xlabel("feedback delay [samples]"), ax[0].set_ylabel("cycles")
    ax[1].plot(t["state_intervals"], lw=0.8)
    ax[1].set_xlabel("state message"), ax[1].set_ylabel("interval [s]")
    fig.tight_layout(), fig.savefig(os.path.join(d, "timing.png")), plt.close(fig)
    if result["model"]:
        fit_figure(plt, d, result)


def fit_figure(plt, d, result):
    """The recorded poses and the recorded commands flown open loop through
    the identified and the nominal model (eq. I7's segments, each started
    at the recorded state), for each pose the flight moved."""
    X, _ = result["model"]["series"]
    comparison = result["model"]["open_loop"]
    Ts, seg = result["json"]["sample_time_s"], core.SEGMENT
    moved = [i for i, _ in enumerate(core.POSE) if np.ptp(X[:, i]) > 1e-6]
    fig, ax = plt.subplots(len(moved), 1, figsize=(10, 2.2 * len(moved)), sharex=True, squeeze=False)
    for a, i in zip(ax[:, 0], moved):
        a.plot(np.arange(len(X)) * Ts, X[:, i], "k", lw=0.8, label="recorded")
        for which, style in (("identified", "C0"), ("nominal", "C3--")):
            poses = comparison["models"][which]["poses"]
            for j, s in enumerate(comparison["starts"]):
                a.plot((s + 1 + np.arange(seg)) * Ts, poses[j, :, i], style, lw=0.9,
                       label=("%s model, open loop" % which) if j == 0 else None)
        a.set_ylabel(core.POSE[i] + (" [m]" if i < 3 else " [rad]"))
    ax[0, 0].legend(loc="upper right", fontsize=8)
    ax[-1, 0].set_xlabel("t [s]  (open-loop segments of %.0f s, each from the recorded state)" % (seg * Ts))
    fig.tight_layout(), fig.savefig(os.path.join(d, "fit.png")), plt.close(fig)


def downlink_row(j):
    """report.md's row of the controller's own downlink (eq. I2c)."""
    loss = " +- %.4f" % j["downlink_loss_stderr"] if j["downlink_loss_stderr"] else ""
    return "| the controller's own downlink (eq. I2c) | delay %d, jitter up to %d samples, loss %.4f%s |" % (
        j["command_path_samples"]["link"], j["link"]["downlink"].get("jitter", {"max": 0})["max"], j["downlink_loss"],
        loss)


def markdown(j):
    lines = ["# Identified loop: %s (%s)" % (j["namespace"], j["vehicle"]), "", "Bag: `%s`" % j["bag"], "",
             "## Timing", "", "| quantity | value |", "|---|---|",
             "| feedback delay (median) | %d samples |" % j["feedback_delay_samples"],
             "| actuation delay (best fit) | %s |" % ("%d samples" % j["actuation_delay_samples"]
                                                     if j["actuation_delay_samples"] is not None else "not measured"),
             "| states' grid (I4b) | %s |" % ("as recorded (stamps on a uniform grid)" if j.get("grid_phase") is None
                                               else "resampled from the stamps, phase %.1f of Ts" % j["grid_phase"]),
             "| state stream | %.2f Hz, %d lost of %d steps (longest burst %d) |" % (
                 j["state_stream"]["rate_hz"] or 0.0, j["state_stream"]["lost"], j["state_stream"]["steps_spanned"],
                 j["state_stream"]["longest_burst"]),
             "| uplink loss (states never used, eq. I2b) | %.4f%s |" % (
                 j["uplink_loss"], " +- %.4f" % j["uplink_loss_stderr"] if j["uplink_loss_stderr"] else ""),
             downlink_row(j), "",
             "`link.yaml`: `%s`" % json.dumps(j["link"]), "", "## Model", "", j["model"], ""]
    if j["parameters"]:
        lines += ["| parameter | identified | stderr | nominal |", "|---|---|---|---|"]
        for k, p in j["parameters"].items():
            lines.append("| %s | %s | %s | %.6g |" % (k, "%.6g" % p["value"] if p["identified"] else "— (%s)" % p["why_not"],
                                                      "%.2g" % p["stderr"] if p["stderr"] is not None else "—", p["nominal"]))
        lines += ["", "Fit (NRMSE per axis): " + ", ".join("%s %.3g" % kv for kv in j["fit"].items()), ""]
    if j.get("open_loop_rms"):
        lines += ["## Open loop (fit.png)", "", "The recorded commands flown through each model over segments of "
                  "%.0f s, each from the recorded state; RMS error against the recording:" % (
                      core.SEGMENT * j["sample_time_s"]), "", "| model | " + " | ".join(core.POSE) + " |",
                  "|---|" + "---|" * len(core.POSE)]
        for which, rms in j["open_loop_rms"].items():
            lines.append("| %s | %s |" % (which, " | ".join("%.3g" % rms[k] for k in core.POSE)))
        lines.append("")
    return "\n".join(lines) + "\n"


def study(j, checked, out):
    """identify --study: the study (its path and sweep as study_sweep
    checked them) with the identified files beside the nominal one,
    recorded in identify.json (docs/identify.md)."""
    from aurora import identified_study
    if not j["vehicle_file_written"]:
        raise ValueError("--study needs an identified vehicle file, and this bag gave none (%s); the timing and "
                         "link.yaml are in %s" % (j["model"], out))
    j["study"] = identified_study.run_study(*checked, out)
    with open(os.path.join(out, "identify.json"), "w") as f:
        json.dump(j, f, indent=2)
    print("identify: study %s: %d of %d feasible as shipped, %d with the identified vehicle and link; figures in %s"
          % (os.path.basename(j["study"]["study"]), j["study"]["nominal"]["feasible"],
             j["study"]["nominal"]["combinations"], j["study"]["identified"]["feasible"], j["study"]["figures"]))


def main(argv):
    args = parse_args(argv)
    try:
        name, loop = bag_loop(args.bag, args.ns)
        checked = None
        if args.study:  # a study that cannot run is refused before the fit (seconds), not after it
            from aurora import identified_study
            checked = identified_study.study_sweep(args.study, loop["vehicle"])
        j = identify_loop(args.bag, name, loop, args.max_delay, args.window, args.out)
        print("identify: %s (%s): feedback delay %d samples, actuation delay %s; %s; wrote %s" % (
            j["namespace"], j["vehicle"], j["feedback_delay_samples"],
            "%d samples" % j["actuation_delay_samples"] if j["actuation_delay_samples"] is not None else "not measured",
            j["model"], args.out))
        if checked:
            study(j, checked, args.out)
    except ValueError as e:
        print("identify: %s" % e, file=sys.stderr)
        return 2
    return 0
