"""Installs the slider_fix Python package (catkin_python_setup).

The module is not called joint_state_publisher_gui: Debian's node, which this package runs,
imports Debian's module of that name, and a module of ours would hide it."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["slider_fix"], package_dir={"": "src"}))
