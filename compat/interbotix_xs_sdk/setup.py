"""Installs the xs_sdk_emulation Python package (catkin_python_setup).

Not named interbotix_xs_sdk: the messages generated for this package are that Python package
(interbotix_xs_sdk.msg, interbotix_xs_sdk.srv), which one of ours of that name would shadow."""
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["xs_sdk_emulation"], package_dir={"": "src"}))
