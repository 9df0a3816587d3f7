"""Report of a recorded flight (simulated or real) from its bag.

    rosrun aurora report BAG [--out DIR] [--ns NAME ...] [--no-video]

Writes, per drone namespace: metrics (IAE, ITAE, IASC with the study's
conventions, maximum and final position error, settling time and overshoot per
waypoint segment, delay in force, state and command rates), figures (PNG and
PDF: 3D route with waypoints, position against desired, attitude, velocities,
commands), an MP4 of the flight, metrics.json and a one-page report.md. A
bag of formation.launch record:=true gets the formation's part instead
(aurora/formation_report.py).
"""
import argparse
import json
import math
import os
import sys
import time

from aurora import _core, formation_report

# Metric integrals of the study (docs/delay-and-study.md): dt = 0.03 s, t the
# loop clock (docs/architecture.md, "Step index and metric time").
METRIC_DT = 0.03
# Settling band: within 5 % of the segment's step size (at least 5 cm). A
# segment has settled once its error stays inside the band for SETTLE_HOLD
# seconds and until the segment ends; a response still swinging in and out of
# the band at the end is "not settled", however it happens to end.
SETTLE_FRACTION = 0.05
SETTLE_MIN = 0.05
SETTLE_HOLD = 1.0


class ReportError(Exception):
    """A problem the user can act on; printed without a traceback."""


def parse_args(argv):
    p = argparse.ArgumentParser(prog="report", description=__doc__.split("\n\n")[0] + " Writes figures, "
                                "an MP4, metrics.json and report.md.")
    p.add_argument("bag", help="the .bag file")
    p.add_argument("--out", help="output folder (default: BAG without .bag + '_report')")
    p.add_argument("--ns", action="append", default=None,
                   help="drone namespace to report (repeatable; default: every namespace with state and control)")
    p.add_argument("--no-video", action="store_true", help="skip the MP4")
    p.add_argument("--fps", type=float, default=10.0, help="video frames per second of flight time (default 10)")
    p.add_argument("--no-pdf", action="store_true", help="PNG figures only")
    args = p.parse_args(argv)
    if not (0 < args.fps <= 60):
        p.error("--fps %g is invalid: accepted (0, 60]" % args.fps)
    return args


def open_bag(path):
    import rosbag
    if not os.path.exists(path):
        raise ReportError("bag '%s' does not exist" % path)
    if path.endswith(".active"):
        raise ReportError("'%s' is still being recorded or was interrupted: stop the recorder, or run "
                          "'rosbag reindex %s' and report the result" % (path, path))
    try:
        return rosbag.Bag(path, "r")
    except rosbag.ROSBagUnindexedException:
        raise ReportError("bag '%s' is not indexed (the recording was interrupted): run 'rosbag reindex %s' "
                          "first" % (path, path))
    except (rosbag.ROSBagException, rosbag.ROSBagFormatException, OSError, ValueError) as e:
        raise ReportError("bag '%s' cannot be read (truncated or not a bag?): %s" % (path, e))


def find_namespaces(topics):
    """Namespaces with a DroneState `state` or a Control `control` topic."""
    names = set()
    for t, info in topics.items():
        for suffix, msg_type in (("/state", "aurora_msgs/DroneState"), ("/control", "aurora_msgs/Control")):
            if t.endswith(suffix) and info.msg_type == msg_type:
                names.add(t[: -len(suffix)])
    return sorted(names)


def topics_of(bag):
    try:
        return bag.get_type_and_topic_info().topics
    except Exception as e:  # a damaged index surfaces here
        raise ReportError("bag '%s' cannot be read: %s" % (bag.filename, e))


def writable(out_dir):
    try:
        os.makedirs(out_dir, exist_ok=True)
        probe = os.path.join(out_dir, ".write_test")
        open(probe, "w").close()
        os.remove(probe)
    except OSError as e:
        raise ReportError("output folder '%s' is not writable: %s (choose another with --out)" % (out_dir, e))


def read_bag(bag, namespaces):
    """Per namespace: states, controls (first per step) and cmd_vel receive times."""
    info = topics_of(bag)
    present = sorted(info)
    if namespaces is None:
        namespaces = find_namespaces(info)
        if not namespaces:
            raise ReportError("bag '%s' has no drone to report: need <ns>/state (aurora_msgs/DroneState) and "
                              "<ns>/control (aurora_msgs/Control); present: %s" % (bag.filename, ", ".join(present) or "none"))
    namespaces = ["/" + n.strip("/") for n in namespaces]
    missing = []
    for ns in namespaces:
        for t in ("state", "control"):
            if ns + "/" + t not in info:
                missing.append(ns + "/" + t)
    if missing:
        raise ReportError("bag '%s' lacks the topics the report needs: missing %s; present: %s"
                          % (bag.filename, ", ".join(missing), ", ".join(present) or "none"))
    data = {ns: {"states": [], "controls": {}, "control_stamps": [], "control_seqs": [], "cmd_times": []}
            for ns in namespaces}
    wanted = {}
    for ns in namespaces:
        wanted[ns + "/state"] = (ns, "state")
        wanted[ns + "/control"] = (ns, "control")
        wanted[ns + "/cmd_vel"] = (ns, "cmd")
    try:
        for topic, msg, t in bag.read_messages(topics=list(wanted)):
            ns, kind = wanted[topic]
            d = data[ns]
            if kind == "state":
                d["states"].append(msg)
            elif kind == "control":
                d["control_stamps"].append(msg.header.stamp.to_sec())
                d["control_seqs"].append((msg.header.seq, msg.step))
                d["controls"].setdefault(msg.step, msg)  # a re-sent state is answered twice: keep the first
            else:
                d["cmd_times"].append(t.to_sec())
    except Exception as e:
        raise ReportError("bag '%s' is damaged while reading (%s): %s" % (bag.filename, type(e).__name__, e))
    for ns in namespaces:
        if not data[ns]["states"] or not data[ns]["controls"]:
            raise ReportError("bag '%s': %s/state or %s/control holds no message" % (bag.filename, ns, ns))
    return data


def rate(times):
    if len(times) < 2:
        return 0.0
    span = times[-1] - times[0]
    return (len(times) - 1) / span if span > 0 else 0.0


def norm(v):
    return math.sqrt(sum(x * x for x in v))


def loop_clock(steps, ts):
    """The metric time of each step, ascending: t_0 = 0, t_(k+1) = t_k + Ts by
    repeated addition, as the controller's LoopClock (closed_loop.h)."""
    t, at = 0.0, 0
    for step in steps:
        while at < step:
            t, at = t + ts, at + 1
        yield step, t


def control_gap(seqs):
    """Control messages the recorder dropped (a loaded machine): header.seq,
    which roscpp numbers per publisher, skips them. `seqs`: (seq, step) in
    the bag's order. How many are missing, and the step of the first message
    after the first gap (None without one)."""
    missing, first = 0, None
    for (before, _), (seq, step) in zip(seqs, seqs[1:]):
        if seq > before + 1:
            missing += seq - before - 1
            first = step if first is None else first
    return missing, first


def controller_metrics_match(controls, ts, gap_step, whole):
    """Whether the metrics recomputed from the control messages equal the
    controller's own (each message carries its running IAE, ITAE, IASC): over
    the whole flight (`whole`: study_metrics of all of them), or, where the
    recorder dropped control messages, up to the last message before the
    first gap (the dropped ones' terms are not in the bag). Returns (match,
    the last step compared)."""
    steps = sorted(s for s in controls if gap_step is None or s < gap_step)
    if not steps:
        return False, None
    iae, itae, iasc = whole if gap_step is None else study_metrics({s: controls[s] for s in steps}, ts)
    last = controls[steps[-1]]
    return (iae == last.iae and itae == last.itae and iasc == last.iasc), steps[-1]


def study_metrics(controls, ts):
    """IAE, ITAE and IASC recomputed from the recorded errors and commands in
    the controller's own order of operations (closed_loop.h, feasibility.h)."""
    iae = itae = iasc = 0.0
    for step, t in loop_clock(sorted(controls), ts):
        c = controls[step]
        e = math.sqrt(c.position_error.x * c.position_error.x + c.position_error.y * c.position_error.y
                      + c.position_error.z * c.position_error.z)
        # The command the controller sent (over an imperfect link the drone's
        # differs); bags recorded before command_sent existed have command only.
        u = math.sqrt(sum(x * x for x in getattr(c, "command_sent", c.command)))
        iae = iae + e * METRIC_DT
        itae = itae + e * t * METRIC_DT
        iasc = iasc + u * METRIC_DT
    return iae, itae, iasc


# A DroneState's 12-state in the report's names (the model's order).
STATE_NAMES = ("x", "y", "z", "roll", "pitch", "yaw", "vx", "vy", "vz", "p", "q", "r")


def commands_before_command_names():
    """The commands of a bag recorded before Control.command_names and
    Control.vehicle: the default vehicle's, the only one flown then."""
    return _core.vehicle_command_names(_core.DEFAULT_VEHICLE)


def state_values(s):
    """The 12-state of DroneState `s`, STATE_NAMES' order."""
    return (s.position.x, s.position.y, s.position.z, s.attitude.x, s.attitude.y, s.attitude.z,
            s.velocity.x, s.velocity.y, s.velocity.z, s.attitude_rate.x, s.attitude_rate.y, s.attitude_rate.z)


def gains_label(control):
    """The gains a figure's title names: each by name where the law has at
    most four (the PD law's kp and kd, a kinematic ground law's four),
    else how many (metrics.json lists them); a bag from before Control named
    its gains flew the PD law (its kp and kd fields)."""
    names, values = list(getattr(control, "gain_names", ())), list(getattr(control, "gains", ()))
    if not names:
        return "kp %g, kd %g" % (control.kp, control.kd)
    if len(names) > 4:
        return "%d gains in metrics.json" % len(names)
    return ", ".join("%s %g" % (name, value) for name, value in zip(names, values))


def flight_series(ns, states, controls, ts, t0):
    """Per step with both a state and a control: time, state, reference,
    tracking error, waypoint (or lap), whether in the task."""
    series = {k: [] for k in ("t", "x", "y", "z", "xd", "yd", "zd", "roll", "pitch", "yaw", "vx", "vy", "vz",
                              "p", "q", "r", "err", "wp", "in_task", "yaw_d")}
    for step in sorted(states):
        s = states[step]
        c = controls.get(step)
        if c is None:
            continue
        series["t"].append(s.header.stamp.to_sec() - t0)
        for key, val in zip(STATE_NAMES + ("xd", "yd", "zd"), state_values(s) + (
                c.desired_position.x, c.desired_position.y, c.desired_position.z)):
            series[key].append(val)
        # The tracking error of docs/controllers.md ("Steps of a task and its
        # tracking error"): state k against the reference of step k.
        series["err"].append(norm((c.desired_position.x - s.position.x, c.desired_position.y - s.position.y,
                                   c.desired_position.z - s.position.z)))
        series["yaw_d"].append(c.desired_yaw)
        series["wp"].append(c.waypoint_index)
        series["in_task"].append(c.task_time <= c.task_duration + 0.5 * ts)
    if not series["t"]:
        raise ReportError("%s: no state step has a matching control message" % ns)
    return series


def analyse(ns, d):
    states = {}
    for s in d["states"]:
        states.setdefault(s.step, s)
    controls = d["controls"]
    first, last = controls[min(controls)], controls[max(controls)]
    ts = first.sample_time
    iae, itae, iasc = study_metrics(controls, ts)
    missing_controls, gap_step = control_gap(d["control_seqs"])
    metrics_match, compared_to = controller_metrics_match(controls, ts, gap_step, (iae, itae, iasc))
    t0 = states[min(states)].header.stamp.to_sec()
    series = flight_series(ns, states, controls, ts, t0)
    # The vehicle's own commands (a bag from before Control named them: the default vehicle's).
    names = list(getattr(last, "command_names", ())) or commands_before_command_names()
    cmd = {"t": [], "u": [[] for _ in names], "names": names}
    for step in sorted(controls):
        if step in states:
            cmd["t"].append(states[step].header.stamp.to_sec() - t0)
            for i in range(len(names)):
                cmd["u"][i].append(controls[step].command[i])
    series["extra_names"] = list(getattr(last, "extra_state_names", ()))
    series["extra"] = [tuple(getattr(states[k], "extra", ())) for k in sorted(states) if k in controls]
    # A moving reference (circle, lemniscate) has a desired velocity; the
    # segments are then laps (the node writes the lap into waypoint_index).
    trajectory = any(c.desired_velocity.x or c.desired_velocity.y or c.desired_velocity.z
                     for c in controls.values())
    series["trajectory"] = trajectory
    # Every figure title says which flight it shows: law, gains, delay.
    law = last.controller or "pd_saturated"
    gains = gains_label(last)
    predictor = getattr(last, "predictor", "off") or "off"
    series["label"] = "%s (%s%s, %s; delay %d samples = %.3f s)" % (
        ns, law, "" if predictor == "off" else " with the %s predictor" % predictor, gains, last.delay_samples,
        last.delay_seconds)
    vehicle = getattr(last, "vehicle", "") or _core.DEFAULT_VEHICLE
    series["flies"] = _core.vehicle_flies(vehicle)
    segments = segment_metrics(series)
    metrics = {
        "namespace": ns,
        "steps": len(series["t"]),
        "duration_s": series["t"][-1],
        "iae": iae, "itae": itae, "iasc": iasc,
        "controller_iae": last.iae, "controller_itae": last.itae, "controller_iasc": last.iasc,
        "metrics_match_controller": metrics_match,
        "control_messages_missing": missing_controls,  # the recorder dropped them (header.seq skips)
        "metrics_compared_up_to_step": compared_to,     # the last step before the first missing one
        "max_position_error_m": max(series["err"]),
        "final_position_error_m": series["err"][-1],
        "delay_samples": last.delay_samples,
        "delay_seconds": last.delay_seconds,
        "sample_time_s": ts,
        "kp": last.kp, "kd": last.kd, "commands_clamped": last.clamped,
        "controller": last.controller or "pd_saturated",
        "vehicle": vehicle,
        # A drone hovers on zero commands; a ground robot stands still, and its laws saturate
        # their own commands (the vehicle's sim profile, aurora._core.vehicle_flies).
        "flies": series["flies"],
        "command_names": names,
        "gains": dict(zip(last.gain_names, last.gains)),
        "task_kind": "trajectory" if trajectory else "waypoints",
        "rms_tracking_error_m": math.sqrt(sum(e * e for e in series["err"]) / len(series["err"])),
        "state_rate_hz": rate([s.header.stamp.to_sec() for s in d["states"]]),
        "control_rate_hz": rate(d["control_stamps"]),
        "cmd_vel_rate_hz": rate(d["cmd_times"]),
        "cmd_vel_messages": len(d["cmd_times"]),
        "segments": segments,
        "modes": sorted({c.mode for c in controls.values()}),
    }
    # The task's part the report covers: its steps with both a state and a
    # control (flight_series). A recorder closing on a loaded machine can
    # write a step's control without its state: that step is not covered.
    covered = [controls[k] for k in sorted(controls) if k in states]
    metrics.update(task_coverage(covered[0], covered[-1], ts))
    prediction = prediction_metrics(states, controls, t0)
    if prediction is not None:
        series["prediction_t"], series["prediction_err"] = prediction.pop("t"), prediction.pop("err")
        metrics["predictor"] = prediction
    link = link_metrics(controls)
    if link is not None:
        series["state_age"] = link.pop("state_age_samples")
        series["command_age"] = link.pop("command_age_samples")
        metrics["link"] = link
    return metrics, series, cmd


def prediction_metrics(states, controls, t0):
    """The state predictor's error (docs/predictor.md): each predicted
    position against the state that later arrived for the step it
    predicted, [m]. None when the node ran without one (or the bag predates
    the predictor's fields)."""
    cs = [controls[k] for k in sorted(controls)]
    if not cs or getattr(cs[-1], "predictor", "off") in ("", "off"):
        return None
    t, err, horizons = [], [], []
    for c in cs:
        if not c.law_ran or not c.predicted_state or c.prediction_step not in states:
            continue
        s = states[c.prediction_step]
        p = c.predicted_state
        t.append(s.header.stamp.to_sec() - t0)
        err.append(norm((p[0] - s.position.x, p[1] - s.position.y, p[2] - s.position.z)))
        horizons.append(int(c.prediction_horizon))
    if not err:
        raise ReportError("the controller predicted (%s) but no predicted step has its state in the bag" %
                          cs[-1].predictor)
    return {"form": cs[-1].predictor, "t": t, "err": err, "predictions_checked": len(err),
            "rms_prediction_error_m": math.sqrt(sum(e * e for e in err) / len(err)),
            "max_prediction_error_m": max(err), "max_prediction_horizon_samples": max(horizons)}


def prediction_figure(plt, series, save):
    """The predicted position's error against the state that arrived for
    the step it predicted."""
    fig, ax = plt.subplots(figsize=(10, 4))
    ax.plot(series["prediction_t"], series["prediction_err"], color="tab:purple", lw=1)
    ax.set_xlabel("time of the predicted step [s]")
    ax.set_ylabel("|predicted - arrived| position [m]")
    ax.grid(True, alpha=0.3)
    ax.set_title("%s\nstate predictor: prediction error" % series["label"])
    fig.tight_layout()
    save(fig, "prediction")


def longest_run(flags):
    """The longest run of consecutive True values."""
    best = run = 0
    for f in flags:
        run = run + 1 if f else 0
        best = max(best, run)
    return best


def link_metrics(controls):
    """What the link did (docs/links.md), from the controls of each step: the
    age of the state the law used and of the command the drone applied,
    the losses, and the longest outages (steps without a newer state; steps
    the drone hovered for want of a fresh command). None for bags recorded
    before the link's fields existed."""
    cs = [controls[k] for k in sorted(controls)]
    if not cs or not hasattr(cs[0], "drone_hovers"):
        return None
    state_age = [int(c.delay_in_force) for c in cs if c.law_ran]
    command_age = [int(c.command_age) for c in cs if c.law_ran]
    no_state = [not c.state_arrived for c in cs if c.law_ran]
    hover = [c.drone_hovers for c in cs if c.law_ran]
    last = cs[-1]
    return {"state_age_samples": state_age, "command_age_samples": command_age,
            "uplink_losses": int(last.uplink_losses), "downlink_losses": int(last.downlink_losses),
            "longest_without_new_state_steps": longest_run(no_state),
            "longest_drone_hover_steps": longest_run(hover),
            "max_state_age_samples": max(state_age) if state_age else 0,
            "max_command_age_samples": max(command_age) if command_age else 0}


def task_coverage(first, last, ts):
    """How much of the task the bag holds, from the controller's task clock
    (Control.task_time, task_duration) of the first and last steps covered:
    a bag cut short says so."""
    start, end, length = first.task_time, last.task_time, last.task_duration
    return {"task_duration_s": length, "task_time_recorded_s": [start, end],
            "task_complete": end + 0.5 * ts >= length and start <= 0.5 * ts}


def coverage_text(m):
    start, end = m["task_time_recorded_s"]
    return ("TRUNCATED: only %.1f s of the %.1f s task were recorded (task time %.1f to %.1f s); "
            "the metrics cover that part only" % (end - start, m["task_duration_s"], start, end))


def settling(t, err, band):
    """(settling time or None, swing of the error over the segment's last
    SETTLE_HOLD seconds). Settled: inside `band` from some time on, for at
    least SETTLE_HOLD seconds and until the segment ends."""
    inside_from = None
    for k in range(len(err)):
        if err[k] > band:
            inside_from = None
        elif inside_from is None:
            inside_from = k
    tail = [e for tk, e in zip(t, err) if tk >= t[-1] - SETTLE_HOLD]
    swing = max(tail) - min(tail)
    if inside_from is None or t[-1] - t[inside_from] < SETTLE_HOLD:
        return None, swing
    return t[inside_from] - t[0], swing


def segment_metrics(series):
    """Per waypoint segment or lap of the task: its steps 0..N only (after
    the task the reference holds its end; docs/controllers.md)."""
    out = []
    inside = [k for k, flag in enumerate(series["in_task"]) if flag]
    idx = series["wp"][: inside[-1] + 1] if inside else []
    bounds = []
    start = 0
    for i in range(1, len(idx) + 1):
        if i == len(idx) or idx[i] != idx[start]:
            bounds.append((start, i))
            start = i
    for a, b in bounds:
        target = (series["xd"][a], series["yd"][a], series["zd"][a])
        origin = (series["x"][a], series["y"][a], series["z"][a])
        step_vec = [target[i] - origin[i] for i in range(3)]
        size = norm(step_vec)
        band = max(SETTLE_FRACTION * size, SETTLE_MIN)
        settle, last_swing = settling(series["t"][a:b], series["err"][a:b], band)
        overshoot = 0.0
        if size > 1e-9:
            unit = [c / size for c in step_vec]
            past = max(sum((series[ax][k] - target[i]) * unit[i] for i, ax in enumerate(("x", "y", "z")))
                       for k in range(a, b))
            overshoot = max(0.0, past) / size * 100.0
        errs = series["err"][a:b]
        tracking = {"rms_tracking_error_m": math.sqrt(sum(e * e for e in errs) / len(errs)),
                    "max_tracking_error_m": max(errs)}
        if series.get("trajectory"):
            out.append(dict(lap=idx[a] + 1, t_start_s=series["t"][a], t_end_s=series["t"][b - 1], **tracking))
            continue
        out.append({"waypoint_index": idx[a], "waypoint": list(target), "t_start_s": series["t"][a],
                    "t_end_s": series["t"][b - 1], "step_size_m": size, "settling_band_m": band,
                    "settling_time_s": settle, "settling_hold_s": SETTLE_HOLD,
                    "final_error_m": series["err"][b - 1],
                    "final_swing_m": last_swing, "still_oscillating": settle is None and last_swing > band,
                    "overshoot_percent": overshoot,
                    "closest_approach_m": min(series["err"][a:b]), **tracking})
    return out


def waypoints_in_order(series):
    """The desired points in the order the flight met them."""
    wps = []
    for i in range(len(series["wp"])):
        p = (series["xd"][i], series["yd"][i], series["zd"][i])
        if not wps or wps[-1] != p:
            wps.append(p)
    return wps


def tracking_figure(plt, ns, series, save):
    """Desired against flown seen from above, and the tracking error over
    time with the segment (waypoint or lap) boundaries."""
    t = series["t"]
    fig, (top, err) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [1, 1.4]})
    if series.get("trajectory"):
        top.plot(series["xd"], series["yd"], "--", color="tab:red", label="desired path")
    else:
        # The reference jumps from waypoint to waypoint (a step): points, not lines.
        wps = waypoints_in_order(series)
        top.scatter([w[0] for w in wps], [w[1] for w in wps], color="tab:red", s=40, zorder=3, label="waypoints")
        for i, w in enumerate(wps):
            top.annotate(str(i + 1), (w[0], w[1]), textcoords="offset points", xytext=(5, 5), color="tab:red")
    top.plot(series["x"], series["y"], color="tab:blue", label="flown")
    top.set_xlabel("x [m]"); top.set_ylabel("y [m]")
    top.set_aspect("equal", adjustable="datalim")
    top.grid(True, alpha=0.3)
    top.legend(loc="best")
    top.set_title("seen from above")
    err.plot(t, series["err"], color="tab:purple")
    name = "lap" if series.get("trajectory") else "waypoint"
    for i in range(len(t)):
        if i == 0 or series["wp"][i] != series["wp"][i - 1]:  # the first segment is labelled too
            if i > 0:
                err.axvline(t[i], color="0.6", lw=0.8)
            err.text(t[i], max(series["err"]) * 0.95, " %s %d" % (name, series["wp"][i] + 1), fontsize=8)
    err.set_xlabel("t [s]"); err.set_ylabel("|desired - flown| [m]")
    err.grid(True, alpha=0.3)
    err.set_title("tracking error")
    fig.suptitle("%s\ntracking" % series["label"])
    fig.tight_layout()
    save(fig, "tracking")


def route_figure(plt, series, save):
    """The 3D route: the flown path, the waypoints (numbered) or the desired path."""
    wps = waypoints_in_order(series)
    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(111, projection="3d")
    ax.plot(series["x"], series["y"], series["z"], color="tab:blue", label="flown path")
    if series.get("trajectory"):
        ax.plot(series["xd"], series["yd"], series["zd"], "--", color="tab:red", label="desired path")
    else:
        ax.scatter([w[0] for w in wps], [w[1] for w in wps], [w[2] for w in wps], color="tab:red", s=40,
                   label="waypoints", depthshade=False)
        for i, w in enumerate(wps):
            ax.text(w[0], w[1], w[2] + 0.08, str(i + 1), color="tab:red")
    ax.scatter([series["x"][0]], [series["y"][0]], [series["z"][0]], color="k", marker="^", s=40, label="start")
    ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]"); ax.set_zlabel("z [m]")
    ax.set_title("%s\n3D route" % series["label"])
    ax.legend(loc="upper left")
    save(fig, "route3d")


def link_figure(plt, series, save):
    """Histograms of the age of the state the law used and of the command the
    drone applied (-1: none had arrived, the drone hovered)."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, name in zip(axes, ("state_age", "command_age"), ("state the law used", "command the drone applied")):
        ages = series[key]
        lo, hi = min(ages + [0]), max(ages + [0])
        ax.hist(ages, bins=[b - 0.5 for b in range(lo, hi + 2)], color="tab:blue")
        ax.set_xlabel("age of the %s [samples of Ts]" % name)
        ax.set_ylabel("control cycles")
        ax.grid(True, alpha=0.3)
    axes[0].set_title("%s\nlink: ages" % series["label"])
    fig.tight_layout()
    save(fig, "link")


def figures(ns, series, cmd, out_dir, pdf):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d import Axes3D  # noqa: F401  (projection="3d" on matplotlib < 3.2)
    tag = ns.strip("/").replace("/", "_")
    files = []

    def save(fig, name):
        for ext in ("png", "pdf") if pdf else ("png",):
            path = os.path.join(out_dir, "%s_%s.%s" % (tag, name, ext))
            fig.savefig(path, dpi=110)
            files.append(path)
        plt.close(fig)

    def finish(fig, axes, title, name):
        """A time-series figure's common end: time axis, title under the flight's label, saved."""
        axes[-1].set_xlabel("t [s]")
        axes[0].set_title("%s\n%s" % (series["label"], title))
        save(fig, name)

    route_figure(plt, series, save)

    t = series["t"]
    tracking_figure(plt, ns, series, save)
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    for ax, k, kd in zip(axes, ("x", "y", "z"), ("xd", "yd", "zd")):
        ax.plot(t, series[k], label=k)
        ax.plot(t, series[kd], "--", color="tab:red", label=k + " desired")
        ax.set_ylabel("%s [m]" % k)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best")
    finish(fig, axes, "position against desired", "position")

    # A ground robot's roll and pitch are 0 by its model: its heading alone.
    angles = (("roll", "pitch", "yaw"), ("roll φ", "pitch θ", "yaw ψ")) if series.get("flies", True) else (("yaw",), ("heading ψ",))
    fig, axes = plt.subplots(len(angles[0]), 1, figsize=(8, 7 if len(angles[0]) == 3 else 3.5), sharex=True, squeeze=False)
    axes = axes[:, 0]
    for ax, k, name in zip(axes, *angles):
        ax.plot(t, [math.degrees(v) for v in series[k]], label=name)
        if k == "yaw":  # the task's desired yaw (along the path, or fixed)
            ax.plot(t, [math.degrees(v) for v in series["yaw_d"]], "--", color="tab:red", label=name.split()[0] + " desired")
            ax.legend(loc="best")
        ax.set_ylabel(name + " [deg]")
        ax.grid(True, alpha=0.3)
    finish(fig, axes, "attitude", "attitude")

    extra = series.get("extra_names", [])  # a series built without them (a caller's own): none
    fig, axes = plt.subplots(3 if extra else 2, 1, figsize=(8, 8 if extra else 6), sharex=True)
    if extra:  # the vehicle's own states beyond the 12 (a ground robot's u [m/s], omega [rad/s])
        values = series["extra"]
        for i, name in enumerate(extra):
            axes[2].plot(t, [v[i] if i < len(v) else float("nan") for v in values], label=name)
        axes[2].set_ylabel("the vehicle's\nown states")
    for k in ("vx", "vy", "vz"):
        axes[0].plot(t, series[k], label=k)
    axes[0].set_ylabel("velocity [m/s]")
    # mathtext dots: a Unicode combining dot (θ̇) is dropped by the fonts matplotlib ships.
    for k, name in (("p", r"$\dot\phi$"), ("q", r"$\dot\theta$"), ("r", r"$\dot\psi$")):
        axes[1].plot(t, [math.degrees(v) for v in series[k]], label=name)
    axes[1].set_ylabel("attitude rate [deg/s]")  # degrees, as the attitude figure
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best")
    finish(fig, axes, "linear and angular velocities", "velocities")

    names = cmd.get("names") or commands_before_command_names()  # a caller's own cmd: the default vehicle's
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 2 * len(names)), sharex=True, squeeze=False)
    axes = axes[:, 0]
    for ax, i, name in zip(axes, range(len(names)), names):
        ax.plot(cmd["t"], cmd["u"][i])
        # the name, what it does and its unit on lines of their own
        what, _, unit = name.partition(" [")
        ax.set_ylabel(what.replace(" (", "\n(").replace(", ", ",\n") + ("\n[" + unit if unit else ""), fontsize=8)
        ax.grid(True, alpha=0.3)
    fig.subplots_adjust(left=0.17)
    finish(fig, axes, "commands as sent to the driver (the vehicle's order)", "commands")
    if "state_age" in series:
        link_figure(plt, series, save)
    if "prediction_err" in series:
        prediction_figure(plt, series, save)
    return files


def video(ns, series, out_dir, fps):
    """3D view of the drone moving along its path; returns (path, frames)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d import Axes3D  # noqa: F401  (projection="3d" on matplotlib < 3.2)
    from aurora.video import write_mp4
    t = series["t"]
    frame_times = [k / fps for k in range(int(math.floor(t[-1] * fps + 1e-9)) + 1)]
    path = os.path.join(out_dir, "%s_flight.mp4" % ns.strip("/").replace("/", "_"))
    fig = plt.figure(figsize=(6.4, 4.8), dpi=100)
    ax = fig.add_subplot(111, projection="3d")
    wps = sorted({(series["xd"][i], series["yd"][i], series["zd"][i]) for i in range(len(t))})
    if series.get("trajectory"):
        ax.plot(series["xd"], series["yd"], series["zd"], "--", color="tab:red", label="desired path")
    else:
        ax.scatter([w[0] for w in wps], [w[1] for w in wps], [w[2] for w in wps], color="tab:red", s=30,
                   depthshade=False, label="waypoints")
    pad = 0.3
    ax.set_xlim(min(series["x"] + [w[0] for w in wps]) - pad, max(series["x"] + [w[0] for w in wps]) + pad)
    ax.set_ylim(min(series["y"] + [w[1] for w in wps]) - pad, max(series["y"] + [w[1] for w in wps]) + pad)
    ax.set_zlim(0, max(series["z"] + [w[2] for w in wps]) + pad)
    ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]"); ax.set_zlabel("z [m]")
    trail, = ax.plot([], [], [], color="tab:blue", lw=1.5)
    drone, = ax.plot([], [], [], "o", color="k", ms=7)
    label = ax.set_title("")

    def frames():
        i = 0
        for ft in frame_times:
            while i + 1 < len(t) and t[i + 1] <= ft + 1e-9:
                i += 1
            trail.set_data_3d(series["x"][: i + 1], series["y"][: i + 1], series["z"][: i + 1])
            drone.set_data_3d([series["x"][i]], [series["y"][i]], [series["z"][i]])
            label.set_text("%s   t = %5.1f s" % (ns, ft))
            yield
    written = write_mp4(fig, path, fps, [trail, drone, label], frames())
    plt.close(fig)
    return path, written


def matched_text(m):
    """Whether the recomputed metrics equal the controller's, and how far
    they could be compared."""
    said = "yes" if m["metrics_match_controller"] else "NO"
    if m["control_messages_missing"]:
        said += " (up to step %s: %d control messages missing from the bag, the recorder dropped them)" % (
            m["metrics_compared_up_to_step"], m["control_messages_missing"])
    return said


def commands_text(m):
    """How the controller's commands were limited: a drone's clamped to [-1, 1] (or not); a ground robot's laws
    saturate their own (its vehicle's page in docs/), which the clamp flag does not describe."""
    if not m.get("flies", True):
        return "commands saturated by the law"
    return "clamped" if m["commands_clamped"] else "unclamped"


def write_markdown(bag_path, out_dir, sections, formation_lines=()):
    lines = ["# Flight report", "", "Bag: `%s`" % bag_path, ""] + list(formation_lines)
    for m, files in sections:
        tag = m["namespace"]
        lines += ["## %s" % tag, "",
                  "| metric | value |", "|---|---|",
                  "| IAE / ITAE / IASC | %.6g / %.6g / %.6g |" % (m["iae"], m["itae"], m["iasc"]),
                  "| equal to the controller's own | %s |" % matched_text(m),
                  "| max / final position error | %.4f m / %.4f m |" % (m["max_position_error_m"], m["final_position_error_m"]),
                  "| delay in force | %d samples (%.4f s) |" % (m["delay_samples"], m["delay_seconds"]),
                  "| controller | %s: %s (%s) |" % (m["controller"], ", ".join("%s = %g" % kv for kv in m["gains"].items()),
                                                   commands_text(m)),
                  "| task recorded | %s |" % ("all %.1f s" % m["task_duration_s"] if m["task_complete"]
                                              else "**" + coverage_text(m) + "**"),
                  "| RMS tracking error | %.4f m |" % m["rms_tracking_error_m"],
                  "| state / control / cmd_vel rate | %.2f / %.2f / %.2f Hz |" % (m["state_rate_hz"], m["control_rate_hz"], m["cmd_vel_rate_hz"])]
        if m.get("link"):
            k = m["link"]
            lines += ["| link: losses up / down | %d / %d packets |" % (k["uplink_losses"], k["downlink_losses"]),
                      "| link: longest without a new state / %s | %d / %d steps |" % (
                          "drone hovering" if m.get("flies", True) else "robot standing still",
                          k["longest_without_new_state_steps"], k["longest_drone_hover_steps"]),
                      "| link: max state / command age | %d / %d samples |" % (
                          k["max_state_age_samples"], k["max_command_age_samples"])]
        lines.append("")
        if m["task_kind"] == "trajectory":
            lines += ["| lap | RMS tracking error | max tracking error |", "|---|---|---|"]
            lines += ["| %d | %.4f m | %.4f m |" % (s["lap"], s["rms_tracking_error_m"], s["max_tracking_error_m"])
                      for s in m["segments"]]
        else:
            lines += ["Settled: the error stays within the band (5 %% of the step, at least 5 cm) for %g s "
                      "and until the segment ends." % SETTLE_HOLD, "",
                      "| segment | waypoint | settling time | overshoot | closest | RMS / max tracking error |",
                      "|---|---|---|---|---|---|"]
        for s in m["segments"] if m["task_kind"] != "trajectory" else []:
            st = "%.2f s" % s["settling_time_s"] if s["settling_time_s"] is not None else (
                "not settled (still swinging %.3f m)" % s["final_swing_m"] if s["still_oscillating"] else "not settled")
            lines.append("| %d | (%.2f, %.2f, %.2f) | %s | %.1f %% | %.4f m | %.4f / %.4f m |" % (
                s["waypoint_index"] + 1, s["waypoint"][0], s["waypoint"][1], s["waypoint"][2], st,
                s["overshoot_percent"], s["closest_approach_m"], s["rms_tracking_error_m"], s["max_tracking_error_m"]))
        lines.append("")
        for f in files:
            if f.endswith(".png"):
                lines.append("![%s](%s)" % (os.path.basename(f), os.path.basename(f)))
        if m.get("video"):
            lines += ["", "Video: [%s](%s) (%d frames)" % (os.path.basename(m["video"]), os.path.basename(m["video"]),
                                                          m["video_frames"])]
        lines.append("")
    with open(os.path.join(out_dir, "report.md"), "w") as f:
        f.write("\n".join(lines))


def main(argv):
    args = parse_args(argv)
    started = time.time()
    bag_path = os.path.abspath(args.bag)
    out_dir = args.out or (bag_path[:-4] if bag_path.endswith(".bag") else bag_path) + "_report"
    with open_bag(bag_path) as bag:
        formation = formation_report.has_formation(topics_of(bag))
        # A formation's drones have no control topic: their part is the formation's.
        data = read_bag(bag, args.ns) if args.ns or not formation else {}
        writable(out_dir)
        formation_part = formation_report.report(bag, out_dir, not args.no_pdf, not args.no_video, args.fps,
                                                 ReportError) if formation else None
    sections = []
    all_metrics = {"bag": bag_path, "drones": []}
    if formation_part:
        all_metrics["formation"] = formation_part[0]
        f = formation_part[0]
        position = f["rms_after_settle"]["position_xy_m"]
        print("report: formation (%s): %d ticks, RMS after %.0f s %s%s; smallest distance %.4f m"
              % (f["shape"], f["ticks"], formation_report.SETTLE_TIME, formation_report.shape_rms_text(f),
                 "" if position is None else ", position %.4f m" % position, f["smallest_distance_m"]), file=sys.stderr)
        if f["ticks_missing"]:
            print("report: formation: warning: %s" % formation_report.missing_text(f), file=sys.stderr)
    for ns, d in data.items():
        m, series, cmd = analyse(ns, d)
        print("report: %s: %d steps, IAE %.6g, ITAE %.6g, IASC %.6g, max error %.3f m" %
              (ns, m["steps"], m["iae"], m["itae"], m["iasc"], m["max_position_error_m"]), file=sys.stderr)
        if not m["task_complete"]:
            print("report: %s: warning: %s" % (ns, coverage_text(m)), file=sys.stderr)
        files = figures(ns, series, cmd, out_dir, not args.no_pdf)
        if not args.no_video:
            print("report: %s: rendering the video ..." % ns, file=sys.stderr)
            m["video"], m["video_frames"] = video(ns, series, out_dir, args.fps)
            files.append(m["video"])
        m["files"] = [os.path.basename(f) for f in files]
        sections.append((m, files))
        all_metrics["drones"].append(m)
    all_metrics["report_wall_time_s"] = time.time() - started
    with open(os.path.join(out_dir, "metrics.json"), "w") as f:
        json.dump(all_metrics, f, indent=2)
    write_markdown(bag_path, out_dir, sections, formation_part[2] if formation_part else [])
    files = sum(len(s[1]) for s in sections) + (len(formation_part[1]) if formation_part else 0)
    print("report: wrote %s (metrics.json, report.md, %d files) in %.1f s" %
          (out_dir, files, all_metrics["report_wall_time_s"]), file=sys.stderr)
    return 0


def run(argv):
    """The command line's entry (the `report` script): main, with a refusal
    printed as one line and exit status 2."""
    try:
        return main(argv)
    except ReportError as e:
        print("report: error: %s" % e, file=sys.stderr)
        return 2
