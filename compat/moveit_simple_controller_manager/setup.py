"""Installs the moveit_simple_controller_manager Python package (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["moveit_simple_controller_manager"], package_dir={"": "src"}))
