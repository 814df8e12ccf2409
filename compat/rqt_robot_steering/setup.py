"""Installs the robot_steering Python package (catkin_python_setup).

The module is not called rqt_robot_steering: the entry point is the script
scripts/rqt_robot_steering (upstream's name), and Python puts a script's own folder first on
sys.path, so ``import rqt_robot_steering`` from that script would find the script itself
(catkin's devel-space relay has the same name too) instead of a package of that name."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["robot_steering"], package_dir={"": "src"}))
