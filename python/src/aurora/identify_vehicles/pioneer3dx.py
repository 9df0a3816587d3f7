"""The Pioneer P3-DX's identification (docs/identify.md, eq. I6;
docs/pioneer3dx.md): its theta1..theta6 enter its commands linearly, fitted
by least squares on its forward speed and turn rate."""
import numpy as np

from aurora import identify_core as core
from aurora.identify_model import Model

# The regression's axes (the commands u_ref, omega_ref), each with its
# parameters in their columns' order; theta3 and theta5 may be negative.
AXES = {"u": ("dynamics.theta1", "dynamics.theta3", "dynamics.theta4"),
        "omega": ("dynamics.theta2", "dynamics.theta5", "dynamics.theta6")}
SIGNED = ("dynamics.theta3", "dynamics.theta5")


def speeds(X, Ts):
    """The Pioneer's forward speed and turn rate after each step j + 1 (j =
    0 .. n - 2) from the control point's positions and heading, as its model
    steps: u_(j+1) = (dx cos psi_j + dy sin psi_j) / Ts, omega_(j+1) =
    (psi_(j+1) - psi_j) / Ts. (The control point's offset cancels: dx cos
    psi + dy sin psi is the forward speed.)"""
    psi = np.unwrap(X[:, 5])
    d = np.diff(np.column_stack([X[:, 0], X[:, 1], psi]), axis=0)
    return (d[:, 0] * np.cos(psi[:-1]) + d[:, 1] * np.sin(psi[:-1])) / Ts, d[:, 2] / Ts


def rows(X, U, Ts, delay, window=1, first=0):
    """Eq. I6's regressors of a Pioneer P3-DX flight: its forward speed and
    turn rate (speeds), their differences, and the commands U (u_ref,
    omega_ref) given `delay` samples before."""
    u_next, w_next = speeds(X, Ts)  # u_(j+1), omega_(j+1)
    k = np.arange(1, len(X) - 1)
    k = k[k >= max(delay, first)]  # from step `first` on, as the Bebop's rows
    u, w = u_next[k - 1], w_next[k - 1]                    # u_k, omega_k
    du, dw = (u_next[k] - u) / Ts, (w_next[k] - w) / Ts    # their steps' rates
    cmd = U[k - delay]
    found = {"u": core.windowed(np.column_stack([du, -w * w, u]), cmd[:, 0], window),
             "omega": core.windowed(np.column_stack([dw, u * w, w]), cmd[:, 1], window)}
    return found, cmd


def state(X, Ts):
    """The Pioneer's model state: the control point's recorded 12-state and
    its forward speed and turn rate after each step (speeds, as eq. I6 takes
    them; 0 at the first), which the open-loop flights start from (eq. I7)."""
    u, w = speeds(X, Ts)
    return np.column_stack([X[:, :12], np.concatenate([[0.0], u]), np.concatenate([[0.0], w])])


def fit(X, U, Ts, delay, window=1, first=0):
    """The Pioneer's theta1..theta6 at actuation delay `delay` (eq. I6):
    u_ref = theta1 du + theta4 u - theta3 omega^2, omega_ref = theta2 domega +
    theta5 u omega + theta6 omega."""
    found, cmd = rows(X, U, Ts, delay, window, first)
    return core.fit_rows(found, AXES, {"u": float(np.std(cmd[:, 0])), "omega": float(np.std(cmd[:, 1]))})


def excited_by(key):
    """The command whose regression holds parameter `key`."""
    return next(axis for axis, keys in AXES.items() if key in keys)


MODEL = Model(lambda path, nominal: fit, excited_by=excited_by, state=state, signed=SIGNED)
