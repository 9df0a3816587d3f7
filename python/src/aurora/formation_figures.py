"""The figures of docs/formation.md that show what the original line
formation gets wrong, flown by our C++ core (aurora.simulate_formation):

    python3 -m aurora.formation_figures docs/figures

formation_laws.png: the lab's scenario at zero delay with both laws. Under
position priority drone 2 never receives the formation's velocity, so the
line lags and swings sideways (rho and beta off their desired values, drone
2's path beside its desired one); inverse kinematics holds it.

formation_mirror.png: inverse kinematics with drone 2 starting below drone
1. The asin angles (eq. F1) cannot tell below from above: the layer drives
rho, alpha, beta to their desired values with drone 2 *below*, its errors
vanish, and the line settles 1.5 m from the desired one (drone 2's height
against the height eq. F2 asks for; the shape check of eq. F9, on
positions, sees it)."""
import copy
import os
import sys

import numpy as np

from aurora.formation_report import positions
from aurora.simulation import config_dir, simulate_formation

MIRROR_START = [1.0, 0.0, 0.5]  # m: drone 2 starts 0.25 m below drone 1 (at 0.75 m)


def desired_positions(Qd):
    """Each row's desired drone positions (eq. F2), n x 6."""
    return np.array([positions(list(q)) for q in Qd])


def shape_error(g):
    """Eq. F9's shape error: drone 2's offset from drone 1 against the desired offset [m]."""
    Xd = desired_positions(g.Qd)
    offset = g.states[:, 1, :3] - g.states[:, 0, :3]
    return np.linalg.norm(offset - (Xd[:, 3:] - Xd[:, :3]), axis=1)


def mirror_flight():
    """The lab's scenario with inverse kinematics, drone 2 starting below drone 1."""
    import yaml
    with open(os.path.join(config_dir(), "formations", "line_lemniscate_ik.yaml")) as f:
        formation = yaml.safe_load(f)
    mirrored = copy.deepcopy(formation)
    mirrored["formation"]["drones"][1]["start"] = list(MIRROR_START)
    return simulate_formation(mirrored)


def laws_figure(plt, out_dir):
    flights = [("position priority (the lab's)", simulate_formation("line_lemniscate"), "tab:orange"),
               ("inverse kinematics", simulate_formation("line_lemniscate_ik"), "tab:blue")]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    t = flights[0][1].t
    axes[0].plot(t, flights[0][1].Qd[:, 3], "--", color="k", label="desired")
    axes[1].plot(t, np.degrees(flights[0][1].Qd[:, 5]), "--", color="k", label="desired")
    Xd = desired_positions(flights[0][1].Qd)
    axes[2].plot(Xd[:, 3], Xd[:, 4], "--", color="k", label="drone 2 desired")
    for name, g, c in flights:
        axes[0].plot(g.t, g.Q[:, 3], color=c, label=name)
        axes[1].plot(g.t, np.degrees(g.Q[:, 5]), color=c, label=name)
        axes[2].plot(g.states[:, 1, 0], g.states[:, 1, 1], color=c, label="drone 2, " + name)
    axes[0].set(xlabel="t [s]", ylabel="rho [m]", title="line length")
    axes[1].set(xlabel="t [s]", ylabel="beta [deg]", title="sideways angle")
    axes[2].set(xlabel="x [m]", ylabel="y [m]", title="drone 2 seen from above")
    axes[2].set_aspect("equal")
    return save(plt, fig, axes, "The lab's two-drone scenario, no delay: position priority never gives drone 2 "
                "the formation's velocity", os.path.join(out_dir, "formation_laws.png"))


def mirror_figure(plt, out_dir):
    g = mirror_flight()
    Xd = desired_positions(g.Qd)
    Qtil = g.Qd - g.Q
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    axes[0].plot(g.t, g.states[:, 0, 2], color="tab:blue", label="drone 1")
    axes[0].plot(g.t, g.states[:, 1, 2], color="tab:orange", label="drone 2")
    axes[0].plot(g.t, Xd[:, 5], "--", color="tab:orange", label="drone 2 desired (eq. F2: above)")
    axes[0].set(xlabel="t [s]", ylabel="z [m]", title="heights")
    axes[1].plot(g.t, Qtil[:, 3], label="rho error [m]")
    axes[1].plot(g.t, Qtil[:, 4], label="alpha error [rad]")
    axes[1].plot(g.t, Qtil[:, 5], label="beta error [rad]")
    axes[1].set(xlabel="t [s]", title="the layer's shape errors: they vanish")
    axes[2].plot(g.t, shape_error(g), color="tab:red", label="shape error (eq. F9)")
    axes[2].axhline(1.5, color="gray", ls="--", label="the shape check's limit")
    axes[2].set(xlabel="t [s]", ylabel="[m]", title="drone 2's offset against the desired one")
    return save(plt, fig, axes, "Inverse kinematics, drone 2 starting below drone 1: the asin angles cannot tell "
                "below from above, and the line settles on the mirror", os.path.join(out_dir, "formation_mirror.png"))


def save(plt, fig, axes, title, path):
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        print("usage: python3 -m aurora.formation_figures OUT_DIR\n" + __doc__)
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(argv[0], exist_ok=True)
    for path in (laws_figure(plt, argv[0]), mirror_figure(plt, argv[0])):
        print("wrote " + path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
