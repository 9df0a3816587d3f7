"""What identify fits of a vehicle (docs/identify.md): Model, the one
description each vehicle's module of aurora.identify_vehicles gives (its
module named as its vehicle file's `type`), and what those modules share:
a vehicle file's values by key, the vehicle's own simulator flown open
loop (eq. I7)."""
import numpy as np

from aurora import identify_core as core


class Model:
    """How identify fits one vehicle's model (eqs. I3-I7):

    - fit(nominal_path, nominal) gives fit(X, U, Ts, delay, window, first),
      each parameter by its vehicle file's key with its standard error, the
      fit of each axis, the residual and each command's spread;
    - state(X, Ts): its model state from the recorded 12-state (the
      speeds of a ground robot too), for the open-loop flights;
    - phases: the grid phases it tries (eq. I4b);
    - excited_by(key): the command axis (a key of the fit's spread) that
      excites parameter `key`;
    - signed: the parameters that may be negative (the others are physical
      gains, time constants or damping);
    - bounded: the parameters fitted as factors within eq. I7's bounds
      (0.1 .. 10 times the nominal value)."""

    def __init__(self, fit, excited_by, state=None, phases=None, signed=(), bounded=()):
        self.fit = fit
        self.excited_by = excited_by
        self.state = state or (lambda X, Ts: X)
        self.phases = np.arange(core.GRID_PHASES) / core.GRID_PHASES if phases is None else phases
        self.signed = frozenset(signed)
        self.bounded = frozenset(bounded)


def key_parent(tree, key):
    """The mapping of a vehicle file's tree that holds a parameter's key
    ("mass", "input_gain.x"), and the key's last name."""
    *groups, name = key.split(".")
    for g in groups:
        tree = tree[g]
    return tree, name


def key_value(tree, key):
    """The value at a parameter's key in a vehicle file's tree."""
    parent, name = key_parent(tree, key)
    return float(parent[name])


def open_loop_flyer(vehicle, vehicle_file):
    """fly(factors, X, U, starts, length, forced): the vehicle's own model
    (aurora._core.OpenLoop) of `vehicle_file`, open loop (eq. I7); the file
    is read once."""
    from aurora import _core
    fly = _core.OpenLoop(vehicle, vehicle_file)
    return lambda factors, X, U, starts, length, forced: fly([float(f) for f in factors], X, U, starts, length,
                                                             forced)
