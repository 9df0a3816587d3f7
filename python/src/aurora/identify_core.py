"""The identification core (docs/identify.md), ROS-free: the loop's timing
and a vehicle's parameters from arrays a recorded flight gives (the bag
reading is aurora.identify's). Every function takes numpy arrays and
returns plain values; nothing reads a clock or a file.

- Timing (docs/identify.md, "Timing"): the feedback delay of each cycle is
  the step the controller had minus the step of the state it used (eq. I1);
  a stream's rate, jitter and losses come from its messages' steps and
  stamps (eq. I2).
- What every vehicle's fit uses: velocities and accelerations differenced
  from positions (eq. I4) on a uniform time grid (a realtime loop's states
  resampled there, eq. I4b), least squares per axis (eqs. I3, I6), the
  actuation delay the whole samples that fit best (eq. I5), and the output
  error of open-loop segments (eq. I7) through the product's own simulator
  (a callable given in).
Each vehicle's own regression is its module of aurora.identify_vehicles."""
import math

import numpy as np

# A command whose standard deviation is below this excites nothing (fractions of cmd_vel).
MIN_EXCITATION = 0.02


def percentiles(values):
    """The distribution's summary: median, p5, p95, min, max, mean (empty: None)."""
    v = np.asarray(values, dtype=float)
    if v.size == 0:
        return None
    p5, p50, p95 = np.percentile(v, [5, 50, 95])
    return {"median": float(p50), "p5": float(p5), "p95": float(p95), "min": float(v.min()),
            "max": float(v.max()), "mean": float(v.mean())}


def feedback_delays(newest_steps, used_steps):
    """Eq. I1: each cycle's feedback delay [samples], the newest state's step
    minus the step of the state the law used."""
    return np.asarray(newest_steps, dtype=np.int64) - np.asarray(used_steps, dtype=np.int64)


def loss_bursts(steps):
    """The runs of missing steps between consecutive messages (each a burst's length)."""
    s = np.unique(np.asarray(steps, dtype=np.int64))
    gaps = np.diff(s) - 1
    return gaps[gaps > 0]


def stream_timing(steps, stamps, Ts):
    """Eq. I2: a stream's messages (their steps and stamps [s]): rate [Hz],
    the intervals' distribution [s], jitter (the intervals' standard
    deviation) [s], the share of steps missing and their bursts."""
    steps = np.asarray(steps, dtype=np.int64)
    stamps = np.asarray(stamps, dtype=float)
    if steps.size < 2:
        raise ValueError("a stream of %d message(s): at least 2 are needed to measure its timing" % steps.size)
    intervals = np.diff(stamps)
    span = int(steps.max() - steps.min()) + 1
    bursts = loss_bursts(steps)
    lost = int(bursts.sum())
    return {"messages": int(steps.size), "rate_hz": float((steps.size - 1) / (stamps[-1] - stamps[0]))
            if stamps[-1] > stamps[0] else None, "interval_s": percentiles(intervals),
            "jitter_s": float(np.std(intervals)), "expected_interval_s": Ts, "steps_spanned": span,
            "lost": lost, "loss_rate": lost / span, "bursts": int(bursts.size),
            "longest_burst": int(bursts.max()) if bursts.size else 0,
            "mean_burst": float(bursts.mean()) if bursts.size else 0.0}


def seen_share(loss, jitter_max):
    """Eq. I2b: the share of the states sent that are ever the law's newest
    over a link (docs/links.md) losing each packet with probability `loss`
    and delaying it by a uniform 0 .. jitter_max extra samples: a state is
    seen when it arrives and no newer one has arrived by then (one m steps
    newer overtakes it when m + its jitter <= this one's jitter)."""
    M = int(jitter_max)
    total = 0.0
    for J in range(M + 1):
        p = 1.0
        for m in range(1, J + 1):
            p *= 1.0 - (1.0 - loss) * (J - m + 1) / (M + 1)
        total += p
    return (1.0 - loss) * total / (M + 1)


def link_loss(seen, jitter_max):
    """Eq. I2b inverted: the loss that leaves the share `seen` of the states
    seen under a uniform jitter up to jitter_max (0 where even a lossless
    link would show fewer)."""
    from scipy.optimize import brentq
    if seen >= seen_share(0.0, jitter_max):
        return 0.0
    if seen <= 0.0:
        return 1.0
    return float(brentq(lambda l: seen_share(l, jitter_max) - seen, 0.0, 1.0 - 1e-12, xtol=1e-12))


def differences(positions, Ts):
    """Eq. I4: v_k = (p_k - p_(k-1)) / Ts and a_k = (v_(k+1) - v_k) / Ts for
    k = 1 .. n - 2 (the models' semi-implicit Euler step: its velocity
    after a step is its position's difference). Returns v_k, a_k."""
    v = np.diff(positions, axis=0) / Ts  # v[j] = v_(j+1)
    a = np.diff(v, axis=0) / Ts          # a[j] = a_(j+1)
    return v[:-1], a


# Stamps within this of the uniform grid [s] are on it (a lockstep bag's, to the nanosecond).
ON_GRID = 1e-6
# Grid phases tried on a realtime loop's states (eq. I4b): tenths of a sample.
GRID_PHASES = 10


def on_uniform_grid(steps, stamps, Ts):
    """Eq. I4b: whether each state's stamp is its step's time on one
    uniform grid of Ts (a lockstep or offline flight's: its states are
    taken as they are)."""
    steps = np.asarray(steps, dtype=np.int64)
    stamps = np.asarray(stamps, dtype=float)
    return bool(np.all(np.abs(stamps - stamps[0] - (steps - steps[0]) * Ts) < ON_GRID))


def time_grid(stamps, Ts, phase):
    """Eq. I4b: the uniform grid of Ts from the first stamp plus `phase`
    (a fraction of Ts) up to the last stamp."""
    stamps = np.asarray(stamps, dtype=float)
    n = int(np.floor((stamps[-1] - stamps[0] - phase * Ts) / Ts)) + 1
    return stamps[0] + (phase + np.arange(max(n, 0))) * Ts


ANGLES = (3, 4, 5)  # the state's roll, pitch, yaw: interpolated unwrapped, wrapped again


def states_on_grid(stamps, X, grid):
    """Eq. I4b: the states at the grid's times, each column interpolated
    linearly between the recorded states' stamps (angles unwrapped)."""
    X = np.asarray(X, dtype=float)
    columns = []
    for i in range(X.shape[1]):
        if i in ANGLES:
            columns.append(np.angle(np.exp(1j * np.interp(grid, stamps, np.unwrap(X[:, i])))))
        else:
            columns.append(np.interp(grid, stamps, X[:, i]))
    return np.column_stack(columns)


def commands_on_grid(grid, Ts, command_stamps, commands):
    """Eq. I4b: row k, the commands in force over the grid's step [grid[k],
    grid[k] + Ts], averaged over it (each from its stamp until the next;
    zero before the first): what a vehicle flies over the step when each
    command acts at once. Shifting these rows by j samples (I5) is the
    commands in force j Ts earlier; on a lockstep loop's grid, row k is
    step k's command."""
    order = np.argsort(command_stamps, kind="stable")
    stamps, commands = np.asarray(command_stamps, dtype=float)[order], np.asarray(commands, dtype=float)[order]
    # The integral of the held commands at each stamp (exact: they are constant between stamps).
    integral = np.vstack([np.zeros((1, commands.shape[1])),
                          np.cumsum(commands[:-1] * np.diff(stamps)[:, None], axis=0)])

    def integral_at(t):
        i = np.searchsorted(stamps, t, side="right") - 1  # the command in force at t (-1: none yet)
        j = np.maximum(i, 0)
        value = integral[j] + commands[j] * (t - stamps[j])[:, None]
        value[i < 0] = 0.0
        return value
    grid = np.asarray(grid, dtype=float)
    return (integral_at(grid + Ts) - integral_at(grid)) / Ts


def windowed(A, y, window):
    """Eq. I4's sums over blocks of `window` steps: sum a_k = (v_(k+N) -
    v_k) / Ts telescopes, so a position's noise enters each block twice
    instead of each step (1: the steps as they are)."""
    if window <= 1:
        return A, y
    n = len(y) // window * window
    return (A[:n].reshape(-1, window, A.shape[1]).sum(axis=1), y[:n].reshape(-1, window).sum(axis=1))


def least_squares(A, y):
    """theta, its standard errors, the residual's RMS and the NRMSE (the
    residual's RMS over y's standard deviation)."""
    theta, _, rank, _ = np.linalg.lstsq(A, y, rcond=None)
    r = y - A @ theta
    dof = max(len(y) - A.shape[1], 1)
    sigma2 = float(r @ r) / dof
    try:
        cov = sigma2 * np.linalg.inv(A.T @ A)
        stderr = np.sqrt(np.maximum(np.diag(cov), 0.0))
    except np.linalg.LinAlgError:
        stderr = np.full(A.shape[1], np.inf)
    rms = math.sqrt(float(r @ r) / len(y))
    spread = float(np.std(y))
    return theta, stderr, rms, (rms / spread if spread > 0 else float("inf")), rank


def fit_rows(rows, axes, spread):
    """Least squares of each axis's rows: {key: (value, stderr)}, each axis's
    NRMSE and RMS, the total residual, the commands' spread."""
    params, fit, rss = {}, {}, 0.0
    for axis, (A, y) in rows.items():
        theta, stderr, rms, nrmse, _ = least_squares(A, y)
        for key, value, e in zip(axes[axis], theta, stderr):
            params[key] = (float(value), float(e))
        fit[axis] = {"nrmse": nrmse, "rms": rms, "samples": int(len(y))}
        rss += rms * rms * len(y)
    return {"parameters": params, "fit": fit, "rss": rss, "spread": spread}


def best_delay(fit_at, max_delay):
    """Eq. I5: the actuation delay [samples] in 0 .. max_delay whose fit
    leaves the smallest residual, with every delay's residual."""
    tried = {d: fit_at(d) for d in range(max_delay + 1)}
    best = min(tried, key=lambda d: tried[d]["rss"])
    return best, tried


POSE = ("x", "y", "z", "roll", "pitch", "yaw")         # the outputs compared: the state's first six
SEGMENT = 30   # steps each open-loop segment flies (1 s at 30 Hz: longer ones carry more of the noise in their start)
FORCED = 30    # steps each segment's model is forced along the recording before it
DIVERGED = 1e3  # the pose error [m, rad] of a segment whose flight diverged (a bad factor's)


def applied(U, delay):
    """The commands applied at each step when each was sent `delay` samples
    before (none before the first: zero)."""
    U = np.asarray(U, dtype=float)
    return np.vstack([np.zeros((delay, U.shape[1])), U[:len(U) - delay]]) if delay else U


def segment_starts(n, segment=SEGMENT, forced=FORCED):
    """Eq. I7's segments of a run of n steps: their first steps."""
    return list(range(forced, n - segment, segment))


def segment_poses(X, starts, segment=SEGMENT):
    """The recorded poses each segment's flight is compared with: the states
    after its steps (starts, segment, 6)."""
    return np.stack([X[s + 1:s + 1 + segment, :6] for s in starts])


def pose_error(flown, measured):
    """Flown minus measured poses (..., 6), yaw wrapped to (-pi, pi]."""
    with np.errstate(invalid="ignore", over="ignore"):
        e = flown[..., :6] - measured[..., :6]
        e[..., 5] = np.angle(np.exp(1j * e[..., 5]))
    return np.nan_to_num(e, nan=DIVERGED, posinf=DIVERGED, neginf=-DIVERGED)


def fit_output_error(fly, names, free, X, U, delay, segment=SEGMENT, forced=FORCED):
    """Eq. I7: the factors `free` (of the vehicle's factor `names`) that
    make the model, flown open loop on the commands applied (sent `delay`
    samples before) over segments of `segment` steps, each forced along
    the recording for `forced` steps and started at the recorded state,
    best match the recorded poses (metres and radians), by nonlinear least
    squares (scipy), within the sweeps' factor range [0.1, 10].
    fly(factors, X, U, starts, segment, forced) flies them (aurora._core.
    OpenLoop). Returns {name: (factor, stderr)}, each pose's NRMSE, the
    residual."""
    from scipy.optimize import least_squares as solve
    Ua = applied(U, delay)
    starts = segment_starts(len(X), segment, forced)
    if not starts:
        raise ValueError("%d steps hold no open-loop segment of %d steps after %d forced" % (len(X), segment, forced))
    measured = segment_poses(X, starts, segment)
    index = [names.index(f) for f in free]

    def residual(theta):
        factors = np.ones(len(names))
        factors[index] = theta
        return pose_error(fly(factors, X, Ua, starts, segment, forced), measured).ravel()
    r = solve(residual, np.ones(len(free)), bounds=(0.1, 10.0), xtol=1e-10, ftol=1e-10)
    dof = max(r.fun.size - len(free), 1)
    try:
        stderr = np.sqrt(np.maximum(np.diag(2.0 * r.cost / dof * np.linalg.inv(r.jac.T @ r.jac)), 0.0))
    except np.linalg.LinAlgError:
        stderr = np.full(len(free), np.inf)
    e = r.fun.reshape(-1, 6)
    spread = measured.reshape(-1, 6).std(axis=0)
    fit = {name: {"nrmse": float(np.sqrt(np.mean(e[:, i] ** 2)) / spread[i]) if spread[i] > 0 else float("inf"),
                  "rms": float(np.sqrt(np.mean(e[:, i] ** 2))), "samples": int(e.shape[0])}
           for i, name in enumerate(POSE)}
    return {"factors": {f: (float(v), float(s)) for f, v, s in zip(free, r.x, stderr)}, "fit": fit,
            "rss": float(2.0 * r.cost)}


