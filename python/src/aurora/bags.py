"""Bags as pandas DataFrames: the report's reading and analysis
(aurora.report) handed to Python users.

    import aurora
    flights = aurora.read_bag("out/mission.bag")          # {namespace: BagFlight}
    f = flights["/ardrone1"]
    f.states[["t", "x", "y", "z"]], f.controls[["t", "u1", "delay_in_force"]], f.metrics["iae"]

A formation bag (formation.launch record:=true) also gives
read_formation_bag(path): one row per tick with Q, Qd and each drone's
position. A missing, unindexed or damaged bag raises ValueError saying what
to do (the report's messages)."""
import os

from aurora import formation_report, report


class BagFlight:
    """One drone of a bag: states (one row per state step: step, t [s from
    the first state], the 12-state in the report's names), controls (one
    row per answered step: step, t, the reference xd, yd, zd, the command
    u1..u4 as applied, delay_samples, delay_in_force, mode, law_ran and the
    controller's running iae, itae, iasc), metrics (the report's
    metrics.json entry for this drone)."""

    def __init__(self, states, controls, metrics):
        self.states, self.controls, self.metrics = states, controls, metrics

    def __repr__(self):
        return "BagFlight(%d states, %d controls, IAE %.4f)" % (len(self.states), len(self.controls),
                                                                self.metrics["iae"])


def _open(path):
    if not isinstance(path, (str, os.PathLike)):
        raise ValueError("path: expected a bag file's path, got %r" % (path,))
    try:
        return report.open_bag(path)
    except report.ReportError as e:
        raise ValueError(str(e)) from None


def _states_frame(states, t0):
    import pandas as pd
    rows = {"step": [], "t": []}
    rows.update({k: [] for k in report.STATE_NAMES})
    for s in states:
        rows["step"].append(s.step)
        rows["t"].append(s.header.stamp.to_sec() - t0)
        for k, v in zip(report.STATE_NAMES, report.state_values(s)):
            rows[k].append(v)
    return pd.DataFrame(rows)


def _controls_frame(controls, t0):
    import pandas as pd
    keys = ("step", "t", "xd", "yd", "zd", "u1", "u2", "u3", "u4", "delay_samples", "delay_in_force", "mode",
            "law_ran", "iae", "itae", "iasc")
    rows = {k: [] for k in keys}
    for step in sorted(controls):
        c = controls[step]
        values = (step, c.header.stamp.to_sec() - t0, c.desired_position.x, c.desired_position.y,
                  c.desired_position.z) + tuple(c.command) + (c.delay_samples, c.delay_in_force, c.mode, c.law_ran,
                                                              c.iae, c.itae, c.iasc)
        for k, v in zip(keys, values):
            rows[k].append(v)
    return pd.DataFrame(rows)


def read_bag(path, namespaces=None):
    """{namespace: BagFlight} of the drones in the bag at `path` (all with
    a state and a control topic, or those named)."""
    bag = _open(path)
    try:
        if formation_report.has_formation(report.topics_of(bag)):
            raise ValueError("bag '%s' is a formation's (it holds %s and no robot's control topic): read it with "
                             "aurora.read_formation_bag(path)" % (path, formation_report.FORMATION_TOPIC))
        data = report.read_bag(bag, namespaces)
        flights = {}
        for ns, d in data.items():
            metrics, _, _ = report.analyse(ns, d)
            states = {}
            for s in d["states"]:
                states.setdefault(s.step, s)  # the first of a re-sent step
            t0 = states[min(states)].header.stamp.to_sec()
            flights[ns] = BagFlight(_states_frame([states[k] for k in sorted(states)], t0),
                                    _controls_frame(d["controls"], t0), metrics)
        return flights
    except report.ReportError as e:
        raise ValueError(str(e)) from None
    finally:
        bag.close()


def read_formation_bag(path):
    """One row per formation tick with every robot's state: step, t, Q_*,
    Qd_* (the shape's formation variables, the layer's held desired) and
    each robot's position d{i}_x, d{i}_y, d{i}_z; and the report's
    formation metrics (ticks_missing: the ticks the recorder dropped, which
    have no row)."""
    import pandas as pd
    bag = _open(path)
    try:
        if not formation_report.has_formation(report.topics_of(bag)):
            raise ValueError("bag '%s' holds no %s: record formation.launch with record:=true"
                             % (path, formation_report.FORMATION_TOPIC))
        drones, ticks, states = formation_report.read_formation(bag, report.ReportError)
        ts, names = ticks[min(ticks)].sample_time, formation_report.variable_names(ticks[min(ticks)])
        s = formation_report.series_of(drones, ticks, states, ts)
    except report.ReportError as e:
        raise ValueError(str(e)) from None
    finally:
        bag.close()
    rows = {"step": s["k"], "t": s["t"]}
    for j, name in enumerate(names):
        rows["Q_" + name] = [q[j] for q in s["Q"]]
        rows["Qd_" + name] = [q[j] for q in s["Qd"]]
    for i, d in enumerate(drones):
        for j, axis in enumerate("xyz"):
            rows["d%d_%s" % (i + 1, axis)] = [p[j] for p in s[d]["pos"]]
    return pd.DataFrame(rows), formation_report.metrics_of(drones, s, ts, names)
