# The Python package `aurora_sweep` (src/aurora_sweep: plot_sweep), installed
# by catkin_python_setup() into the devel and install spaces.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["aurora_sweep"], package_dir={"": "src"}))
