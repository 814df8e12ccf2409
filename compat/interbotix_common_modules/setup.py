"""Installs interbotix_common_modules (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["interbotix_common_modules"], package_dir={"": "src"}))
