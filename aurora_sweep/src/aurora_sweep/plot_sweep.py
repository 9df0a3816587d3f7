"""Plots of a sweep's results (DIR/results.h5, else DIR/results.csv): for
every sweep, the feasible share along each parameter and over pairs of the
most influential ones; for grids of the PD law's (Kp, Kd, delay), the
feasible volume in 3D and its three projections, as in the thesis's figure
23a, the maximum tolerable delay, and with early_stop false the region
where each check holds. Large results
stay fast: the projections aggregate every row, the 3D scatter shows a fixed
random subsample (seed 0) of at most MAX_SCATTER points and says so.

    plot_sweep DIR
    plot_sweep --compare DIR_A DIR_B OUT

--compare draws two sweeps side by side (e.g. a study with and without the
state predictor, docs/predictor.md): their max tolerable delay maps on one
colour scale (compare_max_tolerable_delay.png) and their feasible shares
against the delay and, where the plant's model factors vary, against the
largest factor error (compare_feasible_share.png).
"""
import csv
import json
import os
import sys

MAX_SCATTER = 50000


def flag_columns(summary):
    """The results' 0/1 columns (ok1 ... ok4, a formation's ok5, feasible): summary.json's
    "result_columns", which the sweep writes from its one column list
    (aurora_sweep/result_columns.h)."""
    return [c["name"] for c in summary["result_columns"] if c["type"] == "flag"]


def read_results(np, out, params, flags):
    """Columns of the results as numpy arrays, from HDF5 (h5py) or CSV:
    the sweep's parameters (summary.json "parameters") and the flags."""
    h5 = os.path.join(out, "results.h5")
    if os.path.exists(h5):
        import h5py
        with h5py.File(h5, "r") as f:
            return {k: f[k][...] for k in list(params) + list(flags)}
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    cols = {k: np.array([float(r[k]) for r in rows]) for k in params if k != "delay"}
    cols.update({k: np.array([int(r[k]) for r in rows]) for k in ["delay"] + list(flags) if k in params or k in flags})
    return cols


def share_contours(ax, x, y, grid):
    """The 50 % and 90 % contours of a feasible-share grid, those it crosses:
    a grid all above or all below a level has no such line (matplotlib would
    warn "No contour levels were found" with its source line). Returns the
    levels drawn."""
    known = grid[grid == grid]  # cells with runs (NaN: none)
    if known.size == 0 or len(x) < 2 or len(y) < 2:
        return []
    levels = [(l, c) for l, c in ((0.5, "w"), (0.9, "r")) if known.min() < l < known.max()]
    if not levels:
        return []
    cs = ax.contour(x, y, grid, levels=[l for l, _ in levels], colors=[c for _, c in levels], linewidths=1.2)
    ax.clabel(cs, fmt={0.5: "50 %", 0.9: "90 %"}, fontsize=8)
    return [l for l, _ in levels]


def cell_edges(np, centres):
    """Edges of cells centred on sorted `centres` (halfway between them)."""
    c = np.asarray(centres, dtype=float)
    mid = (c[1:] + c[:-1]) / 2.0
    return np.concatenate(([c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]))


def binned(np, values, bins=24):
    """Bin index and bin centres of `values`: its own values when it has few
    (a grid axis), else equal-width bins."""
    uniq = np.unique(values)
    if len(uniq) <= bins:
        return np.searchsorted(uniq, values), uniq.astype(float)
    edges = np.linspace(values.min(), values.max(), bins + 1)
    idx = np.clip(np.searchsorted(edges, values, side="right") - 1, 0, bins - 1)
    return idx, (edges[1:] + edges[:-1]) / 2.0


def share(np, idx, feasible, n):
    runs = np.bincount(idx, minlength=n)
    good = np.bincount(idx, weights=feasible.astype(float), minlength=n)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(runs > 0, good / np.maximum(runs, 1), np.nan)


# The model parameters a sweep varies are factors of the vehicle file's
# values ("m" would read as metres): their axes say so. summary.json names
# them (model_factors); a summary written before it did: those of the one
# vehicle whose factors a sweep took then (the thesis's drone).
FACTORS_BEFORE_MODEL_FACTORS = ("m", "Ixx", "Iyy", "Izz", "Cf", "Ct", "Km", "Jm")


def model_factors(summary):
    return tuple(summary.get("model_factors", FACTORS_BEFORE_MODEL_FACTORS))


def axis_label(name, summary):
    if name in model_factors(summary):
        return "%s factor (x vehicle file's %s)" % (name, name)
    return "delay [samples]" if name == "delay" else name


def marginals(np, plt, params, feasible, summary, out):
    """The feasible share along each parameter, one panel per parameter."""
    names = [n for n, v in params.items() if len(np.unique(v)) > 1]
    if not names:
        return
    ncols = min(4, len(names))
    nrows = (len(names) + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.5 * ncols, 3.8 * nrows), squeeze=False)
    for ax in axes.flat[len(names):]:
        ax.set_visible(False)
    for ax, name in zip(axes.flat, names):
        idx, centres = binned(np, params[name])
        ax.plot(centres, share(np, idx, feasible, len(centres)), "o-", ms=3)
        ax.set_xlabel(axis_label(name, summary))
        ax.set_ylabel("feasible share")
        ax.set_ylim(-0.02, 1.02)
        ax.grid(alpha=0.3)
    fig.suptitle("%s: feasible share along each parameter (%s design, %d runs)" % (
        summary.get("name", "sweep"), summary.get("design", "grid"), len(feasible)))
    fig.tight_layout(rect=(0, 0, 1, 0.96))  # room for the title
    fig.savefig(os.path.join(out, "feasible_marginals.png"), dpi=100)
    plt.close(fig)


def pairs(np, plt, params, feasible, summary, out):
    """Feasible share over pairs of the most influential parameters (the
    largest spread of their marginal share), binned."""
    spread = {}
    for name, v in params.items():
        idx, centres = binned(np, v)
        if len(centres) > 1:
            s = share(np, idx, feasible, len(centres))
            spread[name] = np.nanmax(s) - np.nanmin(s)
    top = sorted(spread, key=spread.get, reverse=True)[:3]
    combos = [(a, b) for i, a in enumerate(top) for b in top[i + 1:]]
    if not combos:
        return
    fig, axes = plt.subplots(1, len(combos), figsize=(5.2 * len(combos), 4.2), squeeze=False)
    for ax, (a, b) in zip(axes[0], combos):
        ia, ca = binned(np, params[a])
        ib, cb = binned(np, params[b])
        grid = share(np, ib * len(ca) + ia, feasible, len(ca) * len(cb)).reshape(len(cb), len(ca))
        im = ax.pcolormesh(cell_edges(np, ca), cell_edges(np, cb), grid, cmap="viridis", vmin=0, vmax=1)
        fig.colorbar(im, ax=ax, label="feasible share")
        ax.set_xlabel(axis_label(a, summary))
        ax.set_ylabel(axis_label(b, summary))
    fig.suptitle("%s: feasible share over pairs of the most influential parameters" % summary.get("name", "sweep"))
    fig.tight_layout(rect=(0, 0, 1, 0.96))  # room for the title
    fig.savefig(os.path.join(out, "feasible_pairs.png"), dpi=100)
    plt.close(fig)


# The link's values a sweep may vary (docs/links.md, "Links in a sweep").
LINK_VALUES = ("uplink_jitter", "uplink_loss", "uplink_burst", "downlink_delay", "downlink_jitter",
               "downlink_loss", "downlink_burst")


def link_margins(np, plt, cols, feasible, summary, out):
    """With repeats: the feasible share over (delay, v) for each link value v
    the sweep varies, the other link values at their smallest (a slice, not an
    average), with the 50 % and 90 % contours: the delay margin as a surface.
    Each cell is the share of the combination's repeats that flew."""
    varied = [v for v in LINK_VALUES if v in cols and len(np.unique(cols[v])) > 1]
    if summary.get("repeats", 1) <= 1 or "delay" not in cols or not varied:
        return
    fig, axes = plt.subplots(1, len(varied), figsize=(5.4 * len(varied), 4.4), squeeze=False)
    for ax, name in zip(axes[0], varied):
        keep = np.ones(len(feasible), dtype=bool)
        for other in varied:
            if other != name:
                keep &= cols[other] == cols[other].min()
        d, v, f = cols["delay"][keep], cols[name][keep], feasible[keep]
        ud, uv = np.unique(d), np.unique(v)
        cells = np.searchsorted(uv, v) * len(ud) + np.searchsorted(ud, d)
        grid = share(np, cells, f, len(ud) * len(uv)).reshape(len(uv), len(ud))
        im = ax.pcolormesh(cell_edges(np, ud), cell_edges(np, uv), grid, cmap="viridis", vmin=0, vmax=1)
        fig.colorbar(im, ax=ax, label="feasible share of %d link seeds" % summary["repeats"])
        if len(ud) > 1 and len(uv) > 1:
            share_contours(ax, ud, uv, grid)
        ax.set_xlabel("delay (uplink base) [samples]")
        ax.set_ylabel(name + (" [samples]" if "jitter" in name or name == "downlink_delay" else ""))
        rest = ", ".join("%s = %g" % (o, cols[o].min()) for o in varied if o != name)
        ax.set_title(rest if rest else name, fontsize=9)
    fig.suptitle("%s: feasible share over the delay and the link (%s)" % (
        summary.get("name", "sweep"), summary.get("controller", "")))
    fig.tight_layout(rect=(0, 0, 1, 0.94))  # room for the title
    fig.savefig(os.path.join(out, "feasible_share.png"), dpi=100)
    plt.close(fig)


def formation_delays(np, plt, cols, ok, summary, out):
    """A formation sweep varying both drones' delays: the share of the runs
    at each (delay_1, delay_2) that were feasible (over the link seeds and
    any other varied value); without early stop also the share that held
    each check, so the check that binds shows (with early stop a check not
    reached is not a check held). docs/formation.md, "Formation sweeps"."""
    if not {"delay_1", "delay_2"} <= set(cols) or "formation_file" not in summary:
        return
    d1, d2 = cols["delay_1"], cols["delay_2"]
    u1, u2 = np.unique(d1), np.unique(d2)
    if len(u1) < 2 or len(u2) < 2:
        return
    cells = np.searchsorted(u2, d2) * len(u1) + np.searchsorted(u1, d1)
    names = {"feasible": "feasible", "ok1": "check 1: position error", "ok2": "check 2: shape error",
             "ok3": "check 3: error integrals", "ok4": "check 4: no collision"}
    if "ok5" in ok and not ok["ok5"].all():  # a ground robot's commands over its limits somewhere
        names["ok5"] = "check 5: ground robot's commands"
    if summary.get("early_stop", True):
        names = {"feasible": "feasible"}
    fig, axes = plt.subplots(1, len(names), figsize=(4.6 * len(names) + 1.4, 4.4), squeeze=False)
    axes = list(axes[0])
    for ax, (key, title) in zip(axes, names.items()):
        grid = share(np, cells, ok[key], len(u1) * len(u2)).reshape(len(u2), len(u1))
        im = ax.pcolormesh(cell_edges(np, u1), cell_edges(np, u2), grid, cmap="viridis", vmin=0, vmax=1)
        share_contours(ax, u1, u2, grid)
        ax.set_xlabel("robot 1's delay [samples]")
        ax.set_ylabel("robot 2's delay [samples]")
        ax.set_title(title, fontsize=10)
    fig.colorbar(im, ax=axes, label="share of the runs (%d link seeds each)" % summary.get("repeats", 1))
    fig.suptitle("%s: %s" % (summary.get("name", "sweep"), os.path.basename(summary["formation_file"])), fontsize=10)
    fig.savefig(os.path.join(out, "formation_delays.png"), dpi=90)
    plt.close(fig)


def tolerable_delays(np, kp, kd, delay, feasible):
    """For each pair of the two gains: the largest d such that every delay
    up to d is feasible (NaN when delay 0 already fails); None unless the
    rows are a whole gains x delay grid."""
    ukp, ukd, ud = np.unique(kp), np.unique(kd), np.unique(delay)
    if len(ukp) < 2 or len(ukd) < 2 or len(ud) < 2 or len(kp) != len(ukp) * len(ukd) * len(ud):
        return None
    grid = np.zeros((len(ukd), len(ukp), len(ud)), dtype=bool)
    grid[np.searchsorted(ukd, kd), np.searchsorted(ukp, kp), np.searchsorted(ud, delay)] = feasible
    first_fail = np.where(grid.all(axis=2), len(ud), np.argmin(grid, axis=2))
    tolerable = np.where(first_fail > 0, ud[np.maximum(first_fail - 1, 0)], -1).astype(float)
    tolerable[tolerable < 0] = np.nan
    return ukp, ukd, tolerable


def max_tolerable_delay(np, plt, gains, kp, kd, delay, feasible, summary, out):
    """The thesis's question for each pair of the two gains (Kp, Kd for the
    PD law): the largest delay up to which every delay is feasible."""
    found = tolerable_delays(np, kp, kd, delay, feasible)
    if found is None:
        return
    ukp, ukd, tolerable = found
    fig, ax = plt.subplots(figsize=(7, 5.5))
    im = ax.pcolormesh(cell_edges(np, ukp), cell_edges(np, ukd), tolerable, cmap="viridis")
    fig.colorbar(im, ax=ax, label="max tolerable delay [samples]")
    ax.set_xlabel(gain_label(gains[0]))
    ax.set_ylabel(gain_label(gains[1]))
    mono = summary.get("delay_monotony", {})
    ax.set_title("%s: every delay up to this one is feasible (blank: none)\n%s of %s gain pairs not monotone in the delay"
                 % (summary.get("name", "sweep"), mono.get("not_monotone", "?"), mono.get("gain_pairs", "?")))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "max_tolerable_delay.png"), dpi=100)
    plt.close(fig)


def gain_label(name):
    """Kp, Kd for the PD law's gains; another law's gain by its name."""
    return {"kp": "Kp", "kd": "Kd"}.get(name, name)


def volume(np, plt, gains, cols, mask, title, name, summary, total, out):
    """The feasible (or one check's) set over the two gains (Kp, Kd) and the
    delay in 3D and its three projections (the thesis's figure 23a), as
    DIR/name."""
    kp, kd, delay = cols[gains[0]], cols[gains[1]], cols["delay"]
    gx, gy = gain_label(gains[0]), gain_label(gains[1])
    fig = plt.figure(figsize=(12, 9))
    ax = fig.add_subplot(2, 2, 1, projection="3d")
    shown = np.flatnonzero(mask)
    if len(shown) > MAX_SCATTER:  # a fixed subsample: the same figure every time
        shown = np.sort(np.random.default_rng(0).choice(shown, MAX_SCATTER, replace=False))
        title += "\n(3D: %d of %d points shown)" % (MAX_SCATTER, int(mask.sum()))
    ax.scatter(kp[shown], kd[shown], delay[shown], s=4, c=delay[shown], cmap="viridis", depthshade=True)
    ax.set_xlabel(gx); ax.set_ylabel(gy); ax.set_zlabel("delay [samples]")
    ax.set_xlim(kp.min(), kp.max()); ax.set_ylim(kd.min(), kd.max()); ax.set_zlim(delay.min(), delay.max())
    ax.set_title(title)
    # Projections: the largest delay that still holds at each (Kp, Kd), and
    # how many values of the third parameter hold in the other planes.
    ukp, ukd, ud = np.unique(kp), np.unique(kd), np.unique(delay)
    panels = ((2, gx, gy, ukp, ukd, kp, kd, "largest delay that holds [samples]", "max"),
              (3, gx, "delay [samples]", ukp, ud, kp, delay, "number of %s values that hold" % gy, "count"),
              (4, gy, "delay [samples]", ukd, ud, kd, delay, "number of %s values that hold" % gx, "count"))
    for panel in panels:
        projection(np, fig, panel, mask, delay)
    fig.suptitle("%s: %d of %d combinations (%s, %s)" % (
        summary.get("name", "sweep"), int(mask.sum()), total, summary.get("backend", "?"),
        summary.get("precision", "?")))
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=100)
    plt.close(fig)


def projection(np, fig, panel, mask, delay):
    """One projection of the set on a plane: the largest delay per cell
    ("max") or how many rows of the set fall in it ("count")."""
    pos, xl, yl, ux, uy, vx, vy, cl, how = panel
    ax2 = fig.add_subplot(2, 2, pos)
    ix = np.searchsorted(ux, vx[mask])
    iy = np.searchsorted(uy, vy[mask])
    if how == "max":
        grid = np.full((len(uy), len(ux)), np.nan)
        np.fmax.at(grid, (iy, ix), delay[mask].astype(float))
    else:
        grid = np.zeros((len(uy), len(ux)))
        np.add.at(grid, (iy, ix), 1)
    if len(ux) > 1 and len(uy) > 1:
        # Cell edges halfway between the values: shading="nearest" by hand,
        # which matplotlib < 3.3 lacks.
        im = ax2.pcolormesh(cell_edges(np, ux), cell_edges(np, uy), grid, cmap="viridis")
        fig.colorbar(im, ax=ax2, label=cl)
    else:
        ax2.scatter(vx[mask], vy[mask], s=6)
    ax2.set_xlabel(xl); ax2.set_ylabel(yl)


def read_sweep(np, out):
    """summary.json (empty when missing) and the columns of the results;
    raises OSError or KeyError when they cannot be read."""
    summary = {}
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        pass
    names = summary.get("parameters", ["kp", "kd", "delay"])
    flags = flag_columns(summary)
    return summary, names, flags, read_results(np, out, names, flags)


def sweep_label(summary, fallback):
    """A sweep by its name and its predictor (docs/predictor.md)."""
    predictor = summary.get("predictor", "off")
    form = predictor.get("form", "off") if isinstance(predictor, dict) else predictor
    return "%s (predictor %s)" % (summary.get("name", fallback), form)


def delay_scales(summaries):
    """How two sweeps' delays are drawn side by side: (factors, unit). In
    samples when their sample times agree; in seconds (each sweep's samples
    times its sample_time_s) when they differ, a drone's 1/30 s against a
    ground robot's 0.1 s say; in samples, said, when a summary predates
    sample_time_s."""
    ts = [s.get("sample_time_s") for s in summaries]
    if None in ts or len(set(ts)) == 1:
        return [1.0] * len(summaries), "samples"
    return ts, "s"


def compare_tolerable(np, plt, runs, out, scales):
    """Two sweeps' max tolerable delay maps side by side, one colour scale."""
    scale, unit = scales
    maps = []
    for summary, names, cols, ok in runs:
        gains = summary.get("delay_monotony", {}).get("gains", ["kp", "kd"])
        if not set(gains + ["delay"]) <= set(names):
            return
        found = tolerable_delays(np, cols[gains[0]], cols[gains[1]], cols["delay"], ok)
        if found is None:
            return
        maps.append((gains, tuple(found[:2]) + (found[2] * scale[len(maps)],)))
    top = max(np.nanmax(t) if np.isfinite(t).any() else 0 for _, (_, _, t) in maps)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    for ax, (summary, _, _, _), (gains, (ukp, ukd, tolerable)) in zip(axes, runs, maps):
        im = ax.pcolormesh(cell_edges(np, ukp), cell_edges(np, ukd), tolerable, cmap="viridis", vmin=0, vmax=top)
        ax.set_xlabel(gain_label(gains[0]))
        ax.set_ylabel(gain_label(gains[1]))
        ax.set_title("%s\n%d gain pairs tolerate some delay" % (sweep_label(summary, "?"), np.isfinite(tolerable).sum()))
    fig.colorbar(im, ax=axes, label="max tolerable delay [%s] (blank: none)" % unit)
    fig.savefig(os.path.join(out, "compare_max_tolerable_delay.png"), dpi=100)
    plt.close(fig)


def compare_shares(np, plt, runs, out, scales):
    """The feasible share of each sweep against the delay and, where the
    plant's model factors vary, against the largest factor error max |f - 1|
    (what model error leaves of a remedy)."""
    scale, unit = scales
    axes_of = [("delay", "delay [%s]" % unit, lambda cols, i: cols["delay"] * scale[i])]
    factors = [f for f in model_factors(runs[0][0]) if all(f in names for _, names, _, _ in runs)]
    if factors:
        axes_of.append(("model error", "largest model factor error max |f - 1| over " + ", ".join(factors),
                        lambda cols, i: np.max(np.abs(np.stack([cols[f] for f in factors]) - 1.0), axis=0)))
    axes_of = [a for a in axes_of if all(a[0] != "delay" or "delay" in names for _, names, _, _ in runs)]
    if not axes_of:
        return
    fig, axes = plt.subplots(1, len(axes_of), figsize=(6.5 * len(axes_of), 4.5), squeeze=False)
    for ax, (_, label, values) in zip(axes[0], axes_of):
        for i, (summary, _, cols, ok) in enumerate(runs):
            idx, centres = binned(np, values(cols, i), bins=16)
            ax.plot(centres, share(np, idx, ok, len(centres)), "o-", label=sweep_label(summary, "?"))
        ax.set_xlabel(label)
        ax.set_ylabel("feasible share")
        ax.set_ylim(-0.02, 1.02)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "compare_feasible_share.png"), dpi=100)
    plt.close(fig)


def compare(argv):
    """plot_sweep --compare DIR_A DIR_B OUT: two sweeps' results side by side."""
    if len(argv) != 3:
        print("plot_sweep --compare: give two sweeps' output folders and a folder for the figures "
              "(plot_sweep --compare DIR_A DIR_B OUT)", file=sys.stderr)
        return 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    runs = []
    for d in argv[:2]:
        try:
            summary, names, flags, cols = read_sweep(np, d)
        except (OSError, KeyError) as e:
            print("plot_sweep: cannot read the results in %s: %s" % (d, e), file=sys.stderr)
            return 2
        runs.append((summary, names, cols, cols["feasible"] == 1))
    os.makedirs(argv[2], exist_ok=True)
    scales = delay_scales([r[0] for r in runs])
    if scales[1] == "s":
        print("plot_sweep --compare: the sample times differ (%s s): delays drawn in seconds"
              % ", ".join("%g" % t for t in scales[0]))
    compare_tolerable(np, plt, runs, argv[2], scales)
    compare_shares(np, plt, runs, argv[2], scales)
    return 0


def formation_laws(np, plt, cols, ok, summary, out):
    """A formation sweep varying its shape's law (the triangle's) and its
    robots' delays: for each law (its name from summary.json's
    formation_laws; a summary from before them gives its index),
    the share of its runs that were feasible against the largest of the
    robots' delays, and the delay up to which every combination was
    feasible. docs/formation.md, "Sweeps of AuRoRA's formations"."""
    delays = sorted(k for k in cols if k.startswith("delay_"))
    if "formation_law" not in cols or len(np.unique(cols["formation_law"])) < 2 or not delays:
        return
    largest = np.max(np.stack([cols[k] for k in delays]), axis=0)
    levels = np.unique(largest)
    names = summary.get("formation_laws", [])
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for law in np.unique(cols["formation_law"]):
        mine = cols["formation_law"] == law
        feasible = ok["feasible"][mine]
        at = largest[mine]
        shares = [feasible[at == d].mean() if np.any(at == d) else np.nan for d in levels]
        every = [d for d in levels if np.all(feasible[at <= d])]
        label = names[int(law)] if 0 <= int(law) < len(names) else "formation_law %g" % law
        ax.plot(levels, shares, marker="o", ms=3,
                label="%s (all feasible up to %s)" % (label, "%d" % every[-1] if every else "none"))
    ax.set_xlabel("the largest of %s [samples]" % ", ".join(delays))
    ax.set_ylabel("share of the runs feasible")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("%s: %s" % (summary.get("name", "sweep"), os.path.basename(summary.get("formation_file", ""))),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "formation_law_delays.png"), dpi=90)
    plt.close(fig)


def main(argv):
    if argv and argv[0] == "--compare":
        return compare(argv[1:])
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    out = argv[0]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    # Registers projection="3d" on matplotlib < 3.2 (Ubuntu 20.04 has 3.1).
    from mpl_toolkits.mplot3d import Axes3D  # noqa: F401
    import numpy as np

    try:
        summary, names, flags, cols = read_sweep(np, out)
    except (OSError, KeyError) as e:
        print("plot_sweep: cannot read the results in %s: %s (summary.json and results.csv or .h5, "
              "as the sweep writes them)" % (out, e), file=sys.stderr)
        return 2
    ok = {k: cols[k] == 1 for k in flags}
    total = summary.get("combinations", len(ok["feasible"]))  # --rows feasible holds fewer rows
    if len(ok["feasible"]) == 0:
        print("plot_sweep: no rows to plot in %s" % out, file=sys.stderr)
        return 0
    # The repeat is which link seed, not a parameter: shares average over it.
    params = {("delay [samples]" if n == "delay" else n): cols[n] for n in names if n != "repeat"}
    marginals(np, plt, params, ok["feasible"], summary, out)
    pairs(np, plt, params, ok["feasible"], summary, out)
    link_margins(np, plt, cols, ok["feasible"], summary, out)
    formation_delays(np, plt, cols, ok, summary, out)
    formation_laws(np, plt, cols, ok, summary, out)
    # The (Kp, Kd, delay) figures of the thesis: the PD law's grids, or
    # another law's grid of two gains and the delay (summary's delay_monotony).
    gains = summary.get("delay_monotony", {}).get("gains", ["kp", "kd"])
    if not set(gains + ["delay"]) <= set(names):
        return 0
    if summary.get("design", "grid") == "grid" and total == len(cols[gains[0]]) and summary.get("repeats", 1) == 1:
        volume(np, plt, gains, cols, ok["feasible"], "feasible set", "feasible_volume.png", summary, total, out)
        max_tolerable_delay(np, plt, gains, cols[gains[0]], cols[gains[1]], cols["delay"], ok["feasible"], summary,
                            out)
    if summary.get("early_stop") is False:
        titles = {"ok1": "check 1: e <= 5 m", "ok2": "check 2: IAE limit", "ok3": "check 3: ITAE limit",
                  "ok4": "check 4: e <= 2 |e0|"}
        for k, title in titles.items():
            volume(np, plt, gains, cols, ok[k], title, "check%s_region.png" % k[-1], summary, total, out)
    return 0
