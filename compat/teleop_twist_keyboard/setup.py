"""Installs the keyboard_teleop Python package (catkin_python_setup).

The module is not called teleop_twist_keyboard: the node is the script
teleop_twist_keyboard.py (upstream's name), and a script imports itself before a package of
its own name."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["keyboard_teleop"], package_dir={"": "src"}))
