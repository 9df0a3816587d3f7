"""The AR.Drone 2.0's identification (docs/identify.md, eq. I7): its model
is nonlinear, its factors fitted by output error, the recorded commands
flown open loop through the product's own simulator over short segments."""
import numpy as np

from aurora import identify_core as core
from aurora.identify_model import Model, key_value, open_loop_flyer

# The fitted model factors, by their vehicle file's keys: the factor's name
# (aurora._core.vehicle_factor_names, a sweep's) and the command that
# excites it. Its mass is weighed, not fitted: with it free, scaling the
# mass, inertias and thrust coefficient together flies nearly alike and a
# fit with millimetres of noise wanders along that direction; the motor's
# constants (Ct, Km, Jm) keep the vehicle file's values: with them free, two
# directions of the eight factors fly identically.
FACTORS = {"inertia.xx": ("Ixx", "roll"), "inertia.yy": ("Iyy", "pitch"), "inertia.zz": ("Izz", "yaw"),
           "rotor.thrust_coefficient": ("Cf", "climb")}
COMMANDS = ("roll", "pitch", "climb", "yaw")  # the command's components, in order


def fit(fly, names, nominal, X, U, Ts, delay, window=1, first=0):
    """The factors of FACTORS at actuation delay `delay` (eq. I7), as the
    other fits give theirs: each parameter's value and standard error (the
    factor times its `nominal` value), each pose's fit, the commands'
    spread. (`Ts` and `window` are the linear fits'; the model steps at its
    vehicle file's Ts, and a segment's open-loop flight averages noise as
    eq. I4's blocks do; its segments start after FORCED steps whatever the
    delay, so `first` is the linear fits'.)"""
    free = [f for f, _ in FACTORS.values()]
    r = core.fit_output_error(fly, names, free, X, U, delay)
    params = {key: (r["factors"][f][0] * nominal[key], r["factors"][f][1] * nominal[key])
              for key, (f, _) in FACTORS.items()}
    u = core.applied(U, delay)
    return {"parameters": params, "fit": r["fit"], "rss": r["rss"],
            "spread": {axis: float(np.std(u[:, i])) for i, axis in enumerate(COMMANDS)}}


def fit_around(nominal_path, nominal):
    """The output-error fit around the nominal file (its path and content)."""
    from aurora import _core
    values = {key: key_value(nominal, key) for key in FACTORS}
    fly, names = open_loop_flyer("ardrone2", nominal_path), _core.vehicle_factor_names("ardrone2")
    return lambda X, U, Ts, delay, window, first=0: fit(fly, names, values, X, U, Ts, delay, window)


# The output-error fit tries only the states' own grid phase (each phase
# costs a fit per delay).
MODEL = Model(fit_around, excited_by=lambda key: FACTORS[key][1], phases=[0.0], bounded=FACTORS)
