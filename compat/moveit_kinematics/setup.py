"""Installs the moveit_kinematics Python package (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["moveit_kinematics"], package_dir={"": "src"}))
