"""The formation part of `report` (docs/formation.md, "Reporting a formation
flight"): from a bag of formation.launch record:=true, of any shape (the
two-drone line, the UAV-UGV line, the triangle), the formation's variables
over time against the desired ones, the formation checks' position and
shape errors, each robot's tracking of its held reference, the smallest
distance between any two robots, a top view and a video of the robots. The
errors are those `flight --formation` computes (docs/formation.md,
"Formation errors" and "Formation checks"): at tick k the robots' positions
X_k against the positions of the layer's Qd held at k. The formation node
publishes the shape's own numbers with each tick (Formation: variables,
Q_newest, desired_position, position_error, shape_error); bags recorded
before it did are the two-drone line's, whose formulas are below."""
import math
import os
import sys

from aurora import _core

FORMATION_TOPIC = "/formation/formation"
FORMATION_TYPE = "aurora_msgs/Formation"
# The formation checks' defaults (aurora_control/formation/formation_checks.h, FormationCriteria::study).
SETTLE_TIME = 10.0
MIN_DISTANCE = 0.6
VARIABLES = ("xF", "yF", "zF", "rho", "alpha", "beta")  # the two-drone line's (bags without `variables`)
LENGTHS = ("xF", "yF", "zF", "xf", "yf", "zf", "rho", "p", "q")  # variables in m; the others are angles [rad]
COLOURS = ("tab:blue", "tab:orange", "tab:purple")


def has_formation(topics):
    info = topics.get(FORMATION_TOPIC)
    return info is not None and info.msg_type == FORMATION_TYPE


def read_formation(bag, report_error):
    """Formation messages (first per tick) and each drone's states by step."""
    ticks, states = {}, {}
    for _, msg, _ in bag.read_messages(topics=[FORMATION_TOPIC]):
        ticks.setdefault(msg.step, msg)
    if not ticks:
        raise report_error("bag '%s': %s holds no message" % (bag.filename, FORMATION_TOPIC))
    drones = list(ticks[min(ticks)].drones)
    topics = ["/%s/state" % d for d in drones]
    present = bag.get_type_and_topic_info().topics
    missing = [t for t in topics if t not in present]
    if missing:
        raise report_error("bag '%s' lacks the formation's drone states %s (record them with formation.launch "
                           "record:=true)" % (bag.filename, ", ".join(missing)))
    for d in drones:
        states[d] = {}
    for topic, msg, _ in bag.read_messages(topics=topics):
        states[topic.split("/")[1]].setdefault(msg.step, msg)
    return drones, ticks, states


def variable_names(msg):
    """The shape's variables, in Q's order."""
    return tuple(getattr(msg, "variables", None) or VARIABLES)


def variables(X):
    """Q of positions X = (p1, p2) (eq. F1, line_formation.h): the two-drone line's."""
    d = [X[3 + i] - X[i] for i in range(3)]
    rho = math.sqrt(sum(v * v for v in d))
    return [X[0], X[1], X[2], rho, math.asin(d[0] / rho), math.asin(d[1] / rho)]


def positions(Q):
    """Positions of Q (eq. F2): drone 2 above drone 1."""
    sa, sb = math.sin(Q[4]), math.sin(Q[5])
    return list(Q[:3]) + [Q[0] + Q[3] * sa, Q[1] + Q[3] * sb, Q[2] + Q[3] * math.sqrt(1.0 - sa * sa - sb * sb)]


def closest_pair(X):
    """The smallest distance between any two robots of positions X [m]."""
    n = len(X) // 3
    return min(math.sqrt(sum((X[3 * b + i] - X[3 * a + i]) ** 2 for i in range(3)))
               for a in range(n) for b in range(a + 1, n))


def errors_of(m, X):
    """Q of the positions X, the desired positions and the checks' position
    and shape errors at tick m: the node's (the shape's own formulas), or,
    in a bag recorded before it published them, the two-drone line's."""
    if len(getattr(m, "Q_newest", ())) > 0:
        return list(m.Q_newest), list(m.desired_position), m.position_error, m.shape_error
    Q, Xd = variables(X), positions(list(m.Qd))
    e_position = math.sqrt(sum((m.Qd[i] - Q[i]) ** 2 for i in range(3)))
    e_shape = math.sqrt(sum(((X[3 + i] - X[i]) - (Xd[3 + i] - Xd[i])) ** 2 for i in range(3)))
    return Q, Xd, e_position, e_shape


def variable_errors(m, X, Q):
    """Qd - Q at tick m, as the shape's layer and flight --formation take it
    (the shape's own angle wraps, aurora._core.formation_error: the
    triangle's psi follows a reference that turns on past pi, its Q stays
    within [-pi, pi]); a bag recorded before the message named its shape
    is the two-drone line's, which wraps nothing."""
    return _core.formation_error(getattr(m, "shape", "") or "line", X, list(m.Qd), Q)


def series_of(drones, ticks, states, ts):
    """Per tick k present for every robot: t, Q, Qd, the desired positions,
    the errors, each robot's position, reference and tracking error, the
    smallest distance between two robots. s["missing"]: the ticks between
    the bag's first and last whose Formation message or some robot's state
    the bag lacks (the recorder drops messages on a loaded machine): the
    series skip them."""
    s = {k: [] for k in ("k", "t", "Q", "Qd", "Qtil", "Xd", "e_position", "e_shape", "distance", "missing")}
    for d in drones:
        s[d] = {"pos": [], "ref": [], "track": []}
    count = getattr(ticks[min(ticks)], "ticks", 0)  # 0 in bags recorded before the field: every tick
    # The formation's ticks are 0 .. ticks - 1 (flight --formation's); later states are after its end.
    last = min(max(ticks), count - 1) if count else max(ticks)
    for k in range(min(ticks), last + 1):
        if k not in ticks or not all(k in states[d] for d in drones):
            s["missing"].append(k)
            continue
        X = []
        for d in drones:
            p = states[d][k].position
            X += [p.x, p.y, p.z]
        m = ticks[k]
        Q, Xd, e_position, e_shape = errors_of(m, X)
        s["k"].append(k)
        s["t"].append(k * ts)
        s["Q"].append(Q)
        s["Qd"].append(list(m.Qd))
        s["Qtil"].append(variable_errors(m, X, Q))
        s["Xd"].append(Xd)
        s["e_position"].append(e_position)
        s["e_shape"].append(e_shape)
        s["distance"].append(closest_pair(X))
        for j, d in enumerate(drones):
            pos, ref = X[3 * j: 3 * j + 3], list(m.reference_position[3 * j: 3 * j + 3])
            s[d]["pos"].append(pos)
            s[d]["ref"].append(ref)
            s[d]["track"].append(math.sqrt(sum((ref[i] - pos[i]) ** 2 for i in range(3))))
    return s


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else 0.0


def unit_of(name):
    return "m" if name in LENGTHS else "rad"


def metrics_of(drones, s, ts, names=VARIABLES):
    """The flight tool's figures: RMS after SETTLE_TIME of each shape
    variable (rho, alpha, beta for a line), the horizontal position and
    the height; the checks' errors; the smallest distance; tracking."""
    judged = [i for i, t in enumerate(s["t"]) if t >= SETTLE_TIME]
    err = lambda j: [s["Qtil"][i][j] for i in judged]  # noqa: E731
    horizontal = [math.hypot(a, b) for a, b in zip(err(0), err(1))]
    # A bag that ends before SETTLE_TIME has nothing judged: its figures are None (null), not 0.
    measured = (lambda v: v) if judged else (lambda v: None)  # noqa: E731
    after = {"%s_%s" % (n, unit_of(n)): measured(rms(err(j))) for j, n in enumerate(names) if j >= 3}
    after.update({"position_xy_m": measured(rms(horizontal)), "height_m": measured(rms(err(2)))})
    m = {"ticks": len(s["t"]), "first_tick": s["k"][0] if s["k"] else None, "last_tick": s["k"][-1] if s["k"] else None,
         "ticks_missing": s["missing"],
         "variables": list(names),
         "rms_after_settle": after,
         "settle_time_s": SETTLE_TIME,
         "ticks_judged": len(judged),
         "end_s": s["t"][-1] if s["t"] else 0.0,
         "max_position_error_m": measured(max([s["e_position"][i] for i in judged], default=0.0)),
         "max_shape_error_m": measured(max([s["e_shape"][i] for i in judged], default=0.0)),
         "iae_position_m_s": measured(sum(s["e_position"][i] for i in judged) * ts),
         "iae_shape_m_s": measured(sum(s["e_shape"][i] for i in judged) * ts),
         "smallest_distance_m": min(s["distance"]) if s["distance"] else None,
         "smallest_distance_at_s": s["t"][s["distance"].index(min(s["distance"]))] if s["distance"] else None,
         "drones": {}}
    for d in drones:
        m["drones"][d] = {"rms_tracking_error_m": rms(s[d]["track"]), "max_tracking_error_m": max(s[d]["track"], default=0.0)}
    return m


def figures(drones, s, out_dir, pdf, names=VARIABLES):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    files = []

    def save(fig, name):
        for ext in ("png", "pdf") if pdf else ("png",):
            path = os.path.join(out_dir, "formation_%s.%s" % (name, ext))
            fig.savefig(path, dpi=110)
            files.append(path)
        plt.close(fig)

    t = s["t"]
    units = ["m" if unit_of(n) == "m" else "deg" for n in names]
    scale = [1 if unit_of(n) == "m" else 180 / math.pi for n in names]
    for name, rows in (("shape", tuple(range(3, len(names)))), ("position", (0, 1, 2))):
        fig, axes = plt.subplots(len(rows), 1, figsize=(8, 7 if len(rows) <= 3 else 11), sharex=True)
        for ax, j in zip(axes, rows):
            # Q as the layer compares it with Qd: Qd - Q~ (an angle on the desired's branch).
            ax.plot(t, [(qd[j] - e[j]) * scale[j] for qd, e in zip(s["Qd"], s["Qtil"])], label=names[j])
            ax.plot(t, [q[j] * scale[j] for q in s["Qd"]], "--", color="tab:red", label=names[j] + " desired")
            ax.set_ylabel("%s [%s]" % (names[j], units[j]))
            ax.grid(True, alpha=0.3)
            ax.legend(loc="best")
        axes[-1].set_xlabel("t [s]")
        axes[0].set_title("formation %s against the desired (true positions, the layer's held Qd)" % name)
        save(fig, name)
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    axes[0].plot(t, s["e_position"], label="position error")
    axes[0].plot(t, s["e_shape"], label="shape error")
    axes[0].axvline(SETTLE_TIME, color="gray", lw=0.8)
    axes[0].set_ylabel("error [m]")
    for d in drones:
        axes[1].plot(t, s[d]["track"], label=d)
    axes[1].set_ylabel("|reference - position| [m]")
    axes[2].plot(t, s["distance"], color="k", label="smallest distance between two robots")
    axes[2].axhline(MIN_DISTANCE, color="tab:red", ls="--", label="min_distance %.1f m" % MIN_DISTANCE)
    axes[2].set_ylabel("distance [m]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best")
    axes[-1].set_xlabel("t [s]")
    axes[0].set_title("formation errors (checks from %.0f s), each robot's tracking, the robots' distance" % SETTLE_TIME)
    save(fig, "errors")
    fig, ax = plt.subplots(figsize=(6.4, 5.6))
    for d, c in zip(drones, COLOURS):
        ax.plot([p[0] for p in s[d]["pos"]], [p[1] for p in s[d]["pos"]], color=c, label=d)
    ax.plot([q[0] for q in s["Qd"]], [q[1] for q in s["Qd"]], "--", color="tab:red", label="desired formation position")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    ax.set_title("top view")
    save(fig, "top_view")
    return files


def video(drones, s, out_dir, fps):
    """The robots in 3D with their trails, joined as the shape joins them
    (the triangle closed), and the desired formation."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d import Axes3D  # noqa: F401  (projection="3d" on matplotlib < 3.2)
    from aurora.video import write_mp4
    t = s["t"]
    path = os.path.join(out_dir, "formation_flight.mp4")
    fig = plt.figure(figsize=(6.4, 4.8), dpi=100)
    ax = fig.add_subplot(111, projection="3d")
    every = [p for d in drones for p in s[d]["pos"]]
    pad = 0.3
    ax.set_xlim(min(p[0] for p in every) - pad, max(p[0] for p in every) + pad)
    ax.set_ylim(min(p[1] for p in every) - pad, max(p[1] for p in every) + pad)
    ax.set_zlim(0, max(p[2] for p in every) + pad)
    ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]"); ax.set_zlabel("z [m]")
    trails = [ax.plot([], [], [], color=c, lw=1.2, label=d)[0] for d, c in zip(drones, COLOURS)]
    line, = ax.plot([], [], [], "o-", color="tab:green", ms=6, label="formation")
    closed = (lambda v: v + v[:1]) if len(drones) > 2 else (lambda v: v)  # noqa: E731
    desired, = ax.plot([], [], [], "--", color="tab:red", lw=1, label="desired")
    ax.legend(loc="upper left", fontsize=7)
    label = ax.set_title("")
    total = int(math.floor((t[-1] - t[0]) * fps + 1e-9)) + 1

    def frames():
        i = 0
        for f in range(total):
            if f % max(1, total // 10) == 0:  # the video is the slow part: say how far it is
                progress("rendering the video: frame %d of %d" % (f + 1, total))
            ft = t[0] + f / fps
            while i + 1 < len(t) and t[i + 1] <= ft + 1e-9:
                i += 1
            for trail, d in zip(trails, drones):
                trail.set_data_3d(*[[p[j] for p in s[d]["pos"][: i + 1]] for j in range(3)])
            ends = [s[d]["pos"][i] for d in drones]
            line.set_data_3d(*[closed([e[j] for e in ends]) for j in range(3)])
            Xd = s["Xd"][i]
            desired.set_data_3d(*[closed(Xd[j::3]) for j in range(3)])
            label.set_text("formation   t = %5.1f s" % ft)
            yield
    written = write_mp4(fig, path, fps, trails + [line, desired, label], frames())
    plt.close(fig)
    return path, written


def missing_text(m):
    """What the report says of the ticks the bag lacks ("" if none)."""
    missing = m["ticks_missing"]
    if not missing:
        return ""
    return ("%d ticks missing from the bag, first %d: the recorder dropped their Formation message or a robot's "
            "state, and every figure, RMS and IAE here skips them" % (len(missing), missing[0]))


def unjudged_text(m):
    """What the report says of a bag that ends before the checks' settle time ("" if it does not)."""
    if m.get("ticks_judged", 1):
        return ""
    return "none: the bag ends at %.2f s, before the %.0f s the errors are judged from" % (m["end_s"], m["settle_time_s"])


def shape_rms_text(m):
    """The shape variables' RMS after the settle time ("rho 0.0039 m, ..."), or why there is none."""
    return unjudged_text(m) or ", ".join("%s %.4f %s" % (k.rsplit("_", 1)[0], v, k.rsplit("_", 1)[1])
                                         for k, v in m["rms_after_settle"].items() if k not in ("position_xy_m", "height_m"))


def judged_lines(m):
    """The markdown rows of the errors judged after the settle time."""
    r, after = m["rms_after_settle"], m["settle_time_s"]
    lines = ["| RMS after %.0f s: %s | %s |" % (after, ", ".join(m["variables"][3:]), shape_rms_text(m))]
    if unjudged_text(m):
        return lines
    return lines + [
        "| RMS after %.0f s: position (x, y) / height | %.4f m / %.4f m |" % (after, r["position_xy_m"], r["height_m"]),
        "| largest position / shape error after %.0f s | %.4f m / %.4f m |" % (
            after, m["max_position_error_m"], m["max_shape_error_m"]),
        "| IAE position / shape after %.0f s | %.4f / %.4f m s |" % (after, m["iae_position_m_s"], m["iae_shape_m_s"])]


def markdown(m, files):
    missing = missing_text(m)
    lines = ["## Formation", "",
             "| metric | value |", "|---|---|",
             "| ticks | %d (steps %d to %d%s) |" % (m["ticks"], m["first_tick"], m["last_tick"],
                                                  ("; " + missing) if missing else "")] + judged_lines(m) + [
             "| smallest distance between two robots | %.4f m at %.2f s |" % (
                 m["smallest_distance_m"], m["smallest_distance_at_s"])]
    for d, v in m["drones"].items():
        lines.append("| %s: RMS / max tracking of its reference | %.4f m / %.4f m |" % (
            d, v["rms_tracking_error_m"], v["max_tracking_error_m"]))
    lines.append("")
    lines += ["![%s](%s)" % (os.path.basename(f), os.path.basename(f)) for f in files if f.endswith(".png")]
    if m.get("video"):
        lines += ["", "Video: [%s](%s) (%d frames)" % (os.path.basename(m["video"]), os.path.basename(m["video"]),
                                                      m["video_frames"])]
    return lines + [""]


def progress(what):
    print("report: formation: %s ..." % what, file=sys.stderr, flush=True)


def report(bag, out_dir, pdf, with_video, fps, report_error):
    """The formation's metrics (a dict for metrics.json), its files and its
    report.md lines; progress on stderr."""
    progress("reading the bag")
    drones, ticks, states = read_formation(bag, report_error)
    first = ticks[min(ticks)]
    ts, names = first.sample_time, variable_names(first)
    s = series_of(drones, ticks, states, ts)
    if len(s["t"]) < 2:
        raise report_error("bag '%s': fewer than 2 ticks with every robot's state" % bag.filename)
    m = metrics_of(drones, s, ts, names)
    m["shape"] = getattr(first, "shape", "") or "line"
    progress("drawing the figures")
    files = figures(drones, s, out_dir, pdf, names)
    if with_video:
        m["video"], m["video_frames"] = video(drones, s, out_dir, fps)
        files.append(m["video"])
    m["files"] = [os.path.basename(f) for f in files]
    return m, files, markdown(m, files)
