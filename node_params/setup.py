"""Installs the node_params Python package (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["node_params"], package_dir={"": "src"}))
