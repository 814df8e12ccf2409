"""Installs the sim_bridge Python package (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["sim_bridge", "sim_bridge.plugins", "sim_bridge.ros_control"],
                                 package_dir={"": "src"}))
