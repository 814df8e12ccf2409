"""Installs xacro_ros1, the ROS 1 adapter over PyPI's xacro (catkin_python_setup)."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["xacro_ros1"], package_dir={"": "src"}))
