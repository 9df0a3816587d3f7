# The Python package `aurora` (python/src/aurora), installed by
# catkin_python_setup() into the devel and install spaces.
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["aurora", "aurora.identify_vehicles"], package_dir={"": "src"}))
