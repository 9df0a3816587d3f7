"""A study with an identified loop (docs/identify.md, "A study of the
identified loop"): `identify --study NAME|FILE` runs a single-robot sweep
file twice, as shipped and with the identified vehicle file and link file
of the identify folder, and draws both side by side (plot_sweep --compare),
so the gains that fly safely on this robot over this link can be read
beside the nominal answer."""
import os
import subprocess

import yaml

from aurora import sweep_runner


def study_file(study):
    """The sweep file of a shipped study's name or a path (flight's rule)."""
    from aurora import _core
    from aurora.simulation import config_dir
    path = _core.shipped_or_path(study, config_dir(), "sweeps")
    if os.path.isfile(path):
        return os.path.abspath(path)
    raise ValueError("--study '%s' is neither a file nor a shipped study (config/sweeps/NAME.yaml)" % study)


def sweep_vehicle(sweep, path):
    """The vehicle type the sweep flies (its vehicle file's, or its controller's)."""
    from aurora import _core
    from aurora.simulation import config_dir
    s = sweep["sweep"]
    if "vehicle" in s:
        name = s["vehicle"]
        candidate = name if os.path.isabs(name) else os.path.join(os.path.dirname(path), name)
        vehicle = candidate if os.path.isfile(candidate) else os.path.join(config_dir(), name)
        with open(vehicle) as f:
            return yaml.safe_load(f)["type"]
    controller = s.get("controller", "pd_saturated")
    return _core.controller_vehicle(_core.shipped_or_path(controller, config_dir(), "controllers"))


def study_sweep(study, vehicle):
    """The study's file (study_file) and its sweep as read; refused
    (ValueError) unless it is a single-robot sweep of `vehicle`."""
    path = study_file(study)
    with open(path) as f:
        sweep = yaml.safe_load(f)
    if not isinstance(sweep, dict) or "sweep" not in sweep:
        raise ValueError("--study '%s' is not a sweep file (its top level must be 'sweep:')" % path)
    if "formation" in sweep["sweep"]:
        raise ValueError("--study '%s' is a formation's sweep: identify studies one robot (a single-robot "
                         "sweep file, e.g. bebop2_delay)" % path)
    flies = sweep_vehicle(sweep, path)
    if flies != vehicle:
        raise ValueError("--study '%s' flies a %s, the bag a %s: give a study of the bag's vehicle" % (path, flies, vehicle))
    return path, sweep


def identified_sweep(path, sweep, out):
    """The sweep file as shipped, its vehicle and link the identified ones
    (absolute paths), written beside the identify files."""
    s = sweep["sweep"]
    s["name"] = s.get("name", "sweep") + "_identified"
    s["vehicle"] = os.path.abspath(os.path.join(out, "vehicle.yaml"))
    s["link"] = os.path.abspath(os.path.join(out, "link.yaml"))
    target = os.path.join(out, "study_identified.yaml")
    with open(target, "w") as f:
        f.write("# %s with the vehicle and link identified here (rosrun aurora identify --study)\n" % path)
        yaml.safe_dump(sweep, f, sort_keys=False)
    return target


def run_study(path, sweep, out, backend="cpu"):
    """Both sweeps of a study study_sweep read and checked, and their
    comparison, into out/study_*; returns what identify.json records of them."""
    identified = identified_sweep(path, sweep, out)
    program = sweep_runner.sweep_program()
    result = {"study": path, "sweep_file": identified}
    for name, config in (("nominal", path), ("identified", identified)):
        folder = os.path.join(out, "study_" + name)
        p = subprocess.run([program, "--config", config, "--out", folder, "--backend", backend, "--quiet",
                            "--overwrite"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        if p.returncode != 0:
            raise ValueError("the %s study failed: %s" % (name, p.stdout.strip()[-2000:]))
        summary = sweep_runner.read_summary(folder)
        result[name] = {"folder": folder, "combinations": summary["combinations"], "feasible": summary["feasible"]}
    compare = os.path.join(out, "study_compare")
    p = subprocess.run(["rosrun", "aurora_sweep", "plot_sweep", "--compare", result["nominal"]["folder"],
                        result["identified"]["folder"], compare], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    if p.returncode != 0:
        raise ValueError("plot_sweep --compare failed: %s" % p.stdout.strip()[-2000:])
    result["figures"] = compare
    return result
