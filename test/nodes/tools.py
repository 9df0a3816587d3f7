"""The command line of a package's executable as rosrun finds it, its path
resolved once per test process: rosrun is a shell script that runs
catkin_find and rospack on every call (0.3 to 0.8 s here, more than the
tool itself), and the tests run the tools hundreds of times."""
import functools
import subprocess


@functools.lru_cache(maxsize=None)
def tool_path(package, executable):
    """Where `rosrun package executable` finds it (catkin_find's libexec)."""
    p = subprocess.run(["catkin_find", "--first-only", "--libexec", package, executable],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    path = p.stdout.strip()
    if p.returncode != 0 or not path:
        raise AssertionError("%s's executable '%s' was not found (catkin_find --libexec %s %s: %s): build the "
                             "workspace and source its setup.bash" % (package, executable, package, executable,
                                                                     path or "nothing"))
    return path


def rosrun(package, executable):
    """The command's first words, as ["rosrun", package, executable] gives them."""
    return [tool_path(package, executable)]
