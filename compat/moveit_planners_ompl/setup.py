"""Installs the moveit_planners_ompl Python package (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["moveit_planners_ompl"], package_dir={"": "src"}))
