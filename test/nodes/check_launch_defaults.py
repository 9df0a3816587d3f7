#!/usr/bin/python3
"""The launch files' defaults as roslaunch reads them (aurora_config bringup/):
every shipped vehicle, driver and formation file gives the namespaces, laws,
vehicles and driver topics its bringup file says and the nodes accept, and a
name without a file is refused naming the file looked for. No node runs: each
launch is read as `roslaunch` reads it (its arguments evaluated, its params
and remaps resolved)."""
import os
import subprocess
import sys
import unittest

import roslaunch.config
import roslaunch.core
import rospkg
import rostest
import yaml

# The shared helpers sit beside this script (catkin's devel-space relay runs
# it with __file__ set to this path; an install puts them beside it too).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from tools import rosrun  # noqa: E402

CONFIG = rospkg.RosPack().get_path("aurora_config")
LAUNCH = rospkg.RosPack().get_path("aurora_bringup")


# An AR.Drone of other inertias than the shipped file's (identify_sim_ardrone.test's plant).
MODIFIED_ARDRONE = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "config", "identify",
                                "ardrone2_modified.yaml")
with open(MODIFIED_ARDRONE) as f:
    MODIFIED_IXX = yaml.safe_load(f)["inertia"]["xx"]


def names_in(folder):
    return sorted(f[:-5] for f in os.listdir(os.path.join(CONFIG, folder)) if f.endswith(".yaml"))


def bringup(kind, name):
    with open(os.path.join(CONFIG, "bringup", kind, name + ".yaml")) as f:
        return {k: ("" if v is None else str(v).lower() if isinstance(v, bool) else str(v))
                for k, v in yaml.safe_load(f).items()}


def read_launch(launch, *args):
    """The launch as roslaunch reads it with `args` (name:=value)."""
    return roslaunch.config.load_config_default([(os.path.join(LAUNCH, launch), list(args))], None,
                                                verbose=False)


def node(config, name):
    found = [n for n in config.nodes if n.name == name]
    assert found, "no node %s in %s" % (name, [n.name for n in config.nodes])
    return found[0]


def robot_query(formation, robot, what):
    """formation_robot's answer for robot `robot` (from 1): what formation.launch gives its sim."""
    return subprocess.run(rosrun("aurora_control", "formation_robot") + [
                           os.path.join(CONFIG, "formations", formation + ".yaml"), "--config-dir", CONFIG,
                           "--vehicle", os.path.join(CONFIG, "vehicles", "ardrone2.yaml"), "--robot", str(robot),
                           "--print", what], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)


def launchable(formation):
    """Whether the formation node flies the file (a kinematic triangle's only `flight --formation` does)."""
    return robot_query(formation, 1, "vehicle").returncode == 0


def remaps(n):
    return dict(n.remap_args)


class LaunchDefaultsTest(unittest.TestCase):
    def test_formation_robot_finds_the_files_paths_without_config_dir(self):
        """Without --config-dir the file's paths are the tools' folder's
        (aurora_config): it said '/vehicles/pioneer3dx.yaml' cannot be read."""
        given = robot_query("line_pioneer_ardrone", 1, "vehicle")
        self.assertEqual(given.returncode, 0, given.stdout)
        alone = subprocess.run(rosrun("aurora_control", "formation_robot") + [
            os.path.join(CONFIG, "formations", "line_pioneer_ardrone.yaml"), "--robot", "1", "--print", "vehicle"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
            env=dict(os.environ, AURORA_CONFIG_DIR=""))
        self.assertEqual((alone.returncode, alone.stdout), (0, given.stdout))

    def test_sim_launch_flies_each_vehicle_with_its_types_defaults(self):
        for vehicle in names_in("vehicles"):
            with open(os.path.join(CONFIG, "vehicles", vehicle + ".yaml")) as f:
                kind = yaml.safe_load(f)["type"]
            want = bringup("vehicles", kind)
            c = read_launch("sim.launch", "vehicle:=" + vehicle)
            ns = "/" + want["namespace"] + "/"
            self.assertEqual(node(c, "controller").namespace, ns, vehicle)
            self.assertEqual(c.params[ns + "vehicle/type"].value, kind)
            with open(os.path.join(CONFIG, "controllers", want["controller"] + ".yaml")) as f:
                law = yaml.safe_load(f)["controller"]["name"]
            self.assertEqual(c.params[ns + "controller/controller/name"].value, law, vehicle)
            self.assertEqual(c.params[ns + "controller/task/name"].value, want["task"], vehicle)
            self.assertEqual(bringup("laws", law)["vehicle"], kind, "%s's default law flies another vehicle" % vehicle)

    def test_a_vehicle_path_takes_its_types_defaults(self):
        c = read_launch("sim.launch", "vehicle:=" + os.path.join(CONFIG, "vehicles", "bebop2.yaml"))
        want = bringup("vehicles", "bebop2")
        self.assertEqual(node(c, "controller").namespace, "/" + want["namespace"] + "/")

    def test_real_launch_takes_each_drivers_topics_and_defaults(self):
        for driver in names_in("bringup/drivers"):
            d = bringup("drivers", driver)
            c = read_launch("real.launch", "driver:=" + driver)
            ns = "/" + d["robot_namespace"] + "/"
            ctrl = node(c, "controller")
            self.assertEqual(ctrl.namespace, ns, driver)
            r = remaps(ctrl)
            self.assertEqual(r["cmd_vel"], d["namespace"] + d["cmd_vel"], driver)
            self.assertEqual(r["takeoff"], d["namespace"] + d["takeoff_land_prefix"] + "takeoff", driver)
            law = c.params[ns + "controller/controller/name"].value
            self.assertEqual(c.params[ns + "vehicle/type"].value, bringup("laws", law)["vehicle"], driver)
            self.assertEqual(c.params[ns + "controller/task/name"].value, d["task"], driver)

    def test_real_launch_loads_the_vehicle_of_the_law_given(self):
        controllers = names_in("controllers")
        for law in names_in("bringup/laws"):
            if law not in controllers:  # a law without a shipped file of its name
                continue
            c = read_launch("real.launch", "controller:=" + law)  # with the default driver's namespace
            ns = "/" + bringup("drivers", "ardrone")["robot_namespace"] + "/"
            self.assertEqual(c.params[ns + "vehicle/type"].value, bringup("laws", law)["vehicle"], law)

    def test_formation_launch_starts_the_robots_the_formation_node_flies(self):
        for formation in names_in("formations"):
            if not launchable(formation):
                with self.assertRaises(Exception):  # its robots' query refuses it, naming why
                    read_launch("formation.launch", "formation:=" + formation)
                continue
            c = read_launch("formation.launch", "formation:=" + formation)
            drones = c.params["/formation/formation_controller/drones"].value
            for i, ns in enumerate(drones):
                out = robot_query(formation, i + 1, "namespace")
                self.assertEqual(out.returncode, 0, out.stdout)
                self.assertEqual(out.stdout.strip(), ns, "%s robot %d" % (formation, i + 1))

    def test_formation_launch_takes_vehicle_only_for_a_shape_whose_file_names_none(self):
        for formation in filter(launchable, names_in("formations")):
            c = read_launch("formation.launch", "formation:=" + formation)
            shape = c.params["/formation/formation_controller/formation_file"].value
            with open(shape) as f:
                shape = next((l.split(":", 1)[1].split("#")[0].strip() for l in f if l.strip().startswith("shape:")), "line")
            default = bringup("shapes", shape)["vehicle"]
            loaded = "/formation/formation_controller/vehicle/type"
            if default:  # the line: its drones fly vehicle:= (default: its bringup file's)
                self.assertEqual(c.params[loaded].value, default, formation)
                c = read_launch("formation.launch", "formation:=" + formation, "vehicle:=" + MODIFIED_ARDRONE)
                self.assertEqual(c.params["/formation/formation_controller/vehicle/inertia/xx"].value, MODIFIED_IXX,
                                 formation)
                for ns in c.params["/formation/formation_controller/drones"].value:  # and every robot's sim
                    self.assertEqual(c.params["/%s/vehicle" % ns].value["inertia"]["xx"], MODIFIED_IXX, formation)
                # Its drones' law flies the default's type only: formation_robot refuses another's (on
                # its stderr, the launch's terminal; roslaunch's error names the query).
                with self.assertRaises(Exception) as refused:
                    read_launch("formation.launch", "formation:=" + formation, "vehicle:=bebop2")
                self.assertIn("vehicles/bebop2.yaml', '--robot', '1', '--print', 'vehicle']] returned with code [2]",
                              str(refused.exception))
            else:  # its file names its robots' vehicles: vehicle:= would be ignored, so it is refused
                self.assertNotIn(loaded, c.params, formation)
                with self.assertRaises(Exception) as refused:
                    read_launch("formation.launch", "formation:=" + formation, "vehicle:=bebop2")
                self.assertIn("vehicle:=bebop2 is refused: a formation file of shape %s names its robots' "
                              "vehicles" % shape, str(refused.exception))

    def test_formation_launch_sends_a_ground_robots_commands_to_its_driver(self):
        ground = bringup("drivers", "rosaria")
        for formation in filter(launchable, names_in("formations")):
            c = read_launch("formation.launch", "formation:=" + formation, "driver:=ardrone")
            drones = c.params["/formation/formation_controller/drones"].value
            r = remaps(node(c, "formation_controller"))
            for i, ns in enumerate(drones):
                cmd = "/%s/cmd_vel" % ns
                on_ground = robot_query(formation, i + 1, "ground").stdout.strip()
                self.assertIn(on_ground, ("true", "false"), formation)
                if on_ground == "true":
                    self.assertEqual(r.get(cmd), "/%s/%s" % (ns, ground["cmd_vel"]), formation)
                else:
                    self.assertNotIn(cmd, r, formation)
                    self.assertEqual(r["/%s/takeoff" % ns], "/%s/%stakeoff" % (
                        ns, bringup("drivers", "ardrone")["takeoff_land_prefix"]), formation)

    def assert_refused(self, launch, arg, *words):
        with self.assertRaises(Exception) as refused:
            read_launch(launch, arg)
        for w in words:
            self.assertIn(w, str(refused.exception))

    def test_a_name_without_a_file_is_refused_naming_the_file(self):
        self.assert_refused("real.launch", "driver:=nosuch", "bringup/drivers/nosuch.yaml")
        self.assert_refused("sim.launch", "vehicle:=nosuch", "vehicles/nosuch.yaml")
        self.assert_refused("formation.launch", "driver:=nosuch", "bringup/drivers/nosuch.yaml")

    def test_formation_driver_of_a_ground_robot_is_refused(self):
        grounded = [d for d in names_in("bringup/drivers") if bringup("drivers", d)["airborne"] == "false"]
        self.assertTrue(grounded)
        for d in grounded:
            self.assert_refused("formation.launch", "driver:=" + d, "drives a ground robot", "ground_driver:=" + d)


if __name__ == "__main__":
    rostest.rosrun("aurora_tests", "launch_defaults", LaunchDefaultsTest)
