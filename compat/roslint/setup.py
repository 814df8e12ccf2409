"""roslint's Python package (the linters' wrappers), installed by catkin_python_setup."""
from setuptools import setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=["roslint"], package_dir={"": "src"}))
