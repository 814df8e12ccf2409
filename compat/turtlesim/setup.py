"""Installs the turtle_world Python package (catkin_python_setup).

Not named turtlesim: the messages generated for this package are the Python package
turtlesim (turtlesim.msg, turtlesim.srv), which one of ours of that name would shadow."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["turtle_world"], package_dir={"": "src"}))
