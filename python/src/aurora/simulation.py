"""aurora.simulate: one offline flight on the C++ core (aurora._core), the
`flight` tool's flight to the last bit, from Python without a roscore.

    import aurora
    f = aurora.simulate("underactuated", "circle", delay=5)
    f.t, f.states, f.commands, f.reference, f.metrics["iae"]
    g = aurora.simulate_formation("line_lemniscate", delays=(3, 9))
    g.states[:, 1, 2], g.Q, g.Qd, g.metrics["feasible"]

A controller, task, vehicle or link is a name of the shipped files
(controllers/NAME.yaml of aurora_config, ...), a path to such a file, or a
dict with the file's schema (e.g. {"controller": {"name": "pd_saturated",
"kp": 0.5, "kd": 0.85}}). A bad one raises ValueError with the flight
tool's message, naming the key."""
import functools
import os
import tempfile

import yaml

from aurora import _core
from aurora.arguments import boolean, per_drone, plain, positive, whole

_FOLDERS = {"controller": "controllers", "task": "tasks", "vehicle": "vehicles", "link": "links",
            "formation": "formations"}


class Flight:
    """One flight: rows k = 0..n-1 (task time k Ts).

    t [s] (n), states (n x S: the state after k model steps, its columns
    named by state_names: x, y, z [m], phi, theta, psi [rad] and their rates
    for every vehicle, then the vehicle's own states, such as a ground
    robot's speeds), commands (n x N: the command the vehicle applied at
    step k, in its model's order: fractions of full scale for the drones,
    speed references for a ground robot; docs/<vehicle>.md),
    reference (n x 3 [m]), error (n: tracking error [m]),
    delay_in_force (n: samples between state k and the state the law
    received at step k: by the delay rule 0 while k < delay, then delay;
    over a link its varying age), metrics (dict: steps, iae, itae, iasc,
    rms_tracking_error, max_tracking_error, delay), law, vehicle."""

    def __init__(self, d):
        for k in ("t", "states", "commands", "reference", "error", "delay_in_force", "metrics", "sample_time", "law",
                  "vehicle", "state_names"):
            setattr(self, k, d[k])

    def __repr__(self):
        m = self.metrics
        return "Flight(%s, %d steps, delay %d, IAE %.4f, RMS tracking error %.4f m)" % (
            self.law, m["steps"], m["delay"], m["iae"], m["rms_tracking_error"])


@functools.lru_cache(maxsize=1)
def config_dir():
    """The aurora_config package's folder (the shipped YAML files), looked up
    once (rospkg crawls ROS_PACKAGE_PATH)."""
    import rospkg
    try:
        return rospkg.RosPack().get_path("aurora_config")
    except rospkg.ResourceNotFound:
        raise ValueError("the aurora_config package is not on ROS_PACKAGE_PATH: source the workspace's setup.bash")


def _as_file(value, kind, tmp):
    """A path to a YAML file for `value` (a dict, a path or a shipped name)."""
    if isinstance(value, dict):
        path = os.path.join(tmp, kind + ".yaml")
        with open(path, "w") as f:
            yaml.safe_dump(plain(value, kind), f)
        return path
    if not isinstance(value, str):
        raise ValueError("%s: expected a name, a path or a dict, got %s" % (kind, type(value).__name__))
    if not _core.is_shipped_name(value):  # flight's rule (aurora_control/params/shipped_files.h)
        if not os.path.exists(value):
            raise ValueError("%s file '%s' does not exist" % (kind, value))
        return value
    path = _core.shipped_or_path(value, config_dir(), _FOLDERS[kind])
    if not os.path.exists(path):
        shipped = sorted(n[:-5] for n in os.listdir(os.path.dirname(path)) if n.endswith(".yaml"))
        raise ValueError("%s '%s' is not a shipped one: accepted %s, a path, or a dict" % (kind, value, ", ".join(shipped)))
    return path


def simulate(controller, task, vehicle=None, delay=None, link=None, clamp=True, rate=None):
    """One flight of `controller` on `task` with a feedback delay of `delay`
    samples. Over `link`, a given delay replaces the link's uplink delay and
    None keeps it (docs/links.md, "A delay beside a link"); without a link
    None is 0. The controller's law chooses the vehicle (None: the shipped
    file of the vehicle the law flies, vehicles/<vehicle>.yaml); `rate` [Hz]
    is a law's own control rate instead of its file's, for a law that has
    one (docs/bebop2.md); clamp=False is refused for a law that saturates
    its own commands (its vehicle's page in docs/)."""
    delay = _core.DELAY_NOT_GIVEN if delay is None else whole(delay, "delay")
    clamp = boolean(clamp, "clamp")
    rate = 0.0 if rate is None else positive(rate, "rate")
    with tempfile.TemporaryDirectory() as tmp:
        controller_file = _as_file(controller, "controller", tmp)
        if vehicle is None:
            vehicle = _core.controller_vehicle(controller_file)
        task_file, vehicle_file = _as_file(task, "task", tmp), _as_file(vehicle, "vehicle", tmp)
        link_file = _as_file(link, "link", tmp) if link is not None else ""
        return Flight(_core.simulate_files(controller_file, task_file, vehicle_file, delay, link_file, clamp, rate))


class FormationFlight:
    """One formation flight (docs/formation.md): rows k = 0..n-1, the drones
    on axis 1 in the file's order.

    t [s] (n), states (n x 2 x 12: each drone's state after k steps),
    commands (n x 2 x 4), reference (n x 2 x 3: each drone's held reference
    position [m]), Q, Qd (n x 6: xF, yF, zF [m], rho [m], alpha, beta [rad]
    of the drones' positions, and the layer's held desired), metrics (dict:
    ticks, delays, rms_rho, rms_alpha, rms_beta, rms_position_xy,
    rms_height (after 10 s), max_position_error, max_shape_error,
    iae_position, iae_shape, min_distance, checks (4 bools), feasible), law
    (the formation's), drone_law, drones (namespaces)."""

    def __init__(self, d):
        for k in ("t", "states", "commands", "reference", "Q", "Qd", "metrics", "sample_time", "law", "drone_law",
                  "drones"):
            setattr(self, k, d[k])

    def __repr__(self):
        m = self.metrics
        return "FormationFlight(%s, %s law, %d ticks, delays %s, RMS rho %.4f m, %s)" % (
            self.law, self.drone_law, m["ticks"], m["delays"], m["rms_rho"],
            "feasible" if m["feasible"] else "not feasible")


class ShapedFormationFlight:
    """A flight of AuRoRA's UAV-UGV line or triangle (docs/formation.md):
    `table` (n x m: flight --formation's CSV rows, its values to the bit),
    `columns` (its header: step, t, each robot's r{i}_ / d{i}_ states and
    commands, Q_ and Qd_ by the spec's variables), `errors` (dict: the RMS
    after 20 s, the closest approach, the delays), `shape`, `summary` (the
    lines flight prints). `column(name)` gives one column."""

    def __init__(self, d):
        for k in ("shape", "columns", "errors", "summary"):
            setattr(self, k, d[k])
        self.table = d["rows"]

    def column(self, name):
        if name not in self.columns:
            raise KeyError("%r is not a column: %s" % (name, ", ".join(self.columns)))
        return self.table[:, self.columns.index(name)]

    def __repr__(self):
        return "ShapedFormationFlight(%s, %d rows, %s)" % (self.shape, len(self.table), self.summary.splitlines()[0])


def simulate_formation(formation, vehicle=None, delays=None, law=None):
    """One formation flight of `formation` (a shipped name, a path or a dict
    of config/formations/NAME.yaml's schema), each robot over its own delay
    (`delays`: one per robot in samples, in the file's order; None keeps
    the file's). The two-drone line gives a FormationFlight; AuRoRA's
    UAV-UGV line and triangle (their files' `shape`) a ShapedFormationFlight
    with flight --formation's CSV as an array; `law` is the shape's own,
    for a shape with laws (_core.SHAPE_LAWS: the triangle's N, PSO, SPO,
    OSP, S-PO; None: the file's)."""
    with tempfile.TemporaryDirectory() as tmp:
        formation_file = _as_file(formation, "formation", tmp)
        shape = _core.formation_shape(formation_file)
        info = _core.formation_shape_info().get(shape)  # None: an unknown shape, which the reader refuses
        if info is None or info["names_its_vehicles"]:
            if vehicle is not None:
                raise ValueError("vehicle= is refused for a formation of shape %r: its robots' vehicle files are "
                                 "in the formation file" % shape)
            robots = 2 if info is None else info["robots"]
            given = [] if delays is None else per_drone(delays, "delays", robots, "robot")
            if law is not None and (not isinstance(law, str) or not law):
                raise ValueError("law: expected a shape law's name (" + _core.SHAPE_LAWS + "), got %r; "
                                 "law=None flies the file's" % (law,))
            return ShapedFormationFlight(_core.simulate_shaped_formation_files(
                formation_file, given, "" if law is None else law, config_dir()))
        if law is not None:
            raise ValueError("law= is refused for the line: its law is its file's formation.law")
        delays = [] if delays is None else per_drone(delays, "delays")
        vehicle_file = _as_file(info["vehicle"] if vehicle is None else vehicle, "vehicle", tmp)
        return FormationFlight(_core.simulate_formation_files(formation_file, vehicle_file, delays, config_dir()))
