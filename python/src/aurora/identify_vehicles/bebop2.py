"""The Bebop 2's identification (docs/identify.md, eq. I3; docs/bebop2.md):
its model is linear in its input gains and damping, a = F(psi) Ku U - Kv v,
fitted by least squares per axis."""
import numpy as np

from aurora import identify_core as core
from aurora.identify_model import Model

# The regression's axes, each with its parameters in their columns' order.
AXES = {"xy": ("input_gain.x", "input_gain.y", "damping.x", "damping.y"),
        "z": ("input_gain.z", "damping.z"), "yaw": ("input_gain.yaw", "damping.yaw")}


def rows(X, U, Ts, delay, window=1, first=0):
    """Eq. I3's regressors and outputs of a Bebop 2 flight: states X (n x
    12, docs/bebop2.md), the commands U (n x 4, row k given at step k),
    the actuation delay `delay` [samples]: step k applies U_(k - delay).
    Returns {axis: (A, y)} for 'xy' (Ku_x, Ku_y, Kv_x, Kv_y), 'z', 'yaw',
    each summed over blocks of `window` steps (eq. I4) from step `first`
    on (at least `delay`: I5 compares the delays on the same steps), and the
    commands."""
    p = np.column_stack([X[:, 0], X[:, 1], X[:, 2], np.unwrap(X[:, 5])])
    v, a = core.differences(p, Ts)                  # k = 1 .. n - 2
    k = np.arange(1, len(X) - 1)
    keep = k >= max(delay, first)
    k, v, a = k[keep], v[keep], a[keep]
    u = U[k - delay]
    psi = p[k, 3]
    c, s = np.cos(psi), np.sin(psi)
    zero = np.zeros_like(c)
    # a_x = c Ku_x u1 - s Ku_y u2 - Kv_x v_x ; a_y = s Ku_x u1 + c Ku_y u2 - Kv_y v_y
    rows_x = core.windowed(np.column_stack([c * u[:, 0], -s * u[:, 1], -v[:, 0], zero]), a[:, 0], window)
    rows_y = core.windowed(np.column_stack([s * u[:, 0], c * u[:, 1], zero, -v[:, 1]]), a[:, 1], window)
    xy = (np.vstack([rows_x[0], rows_y[0]]), np.concatenate([rows_x[1], rows_y[1]]))
    return {"xy": xy, "z": core.windowed(np.column_stack([u[:, 2], -v[:, 2]]), a[:, 2], window),
            "yaw": core.windowed(np.column_stack([u[:, 3], -v[:, 3]]), a[:, 3], window)}, u


def fit(X, U, Ts, delay, window=1, first=0):
    """The Bebop 2's eight parameters at actuation delay `delay` (eq. I3)
    over the steps from `first` on."""
    found, u = rows(X, U, Ts, delay, window, first)
    spread = {"x": float(np.std(u[:, 0])), "y": float(np.std(u[:, 1])), "z": float(np.std(u[:, 2])),
              "yaw": float(np.std(u[:, 3]))}
    return core.fit_rows(found, AXES, spread)


# Each parameter is excited by its key's own axis (input_gain.x: x).
MODEL = Model(lambda path, nominal: fit, excited_by=lambda key: key.split(".")[1])
