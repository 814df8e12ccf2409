"""Noetic's xacro on PyPI's xacro 2.x: ``$(find pkg)`` resolved by ROS 1's package path.

PyPI carries xacro 1.13 (Melodic's line) and 2.x (ROS 2's), not Noetic's 1.14. Noetic's
language is what robot descriptions use today: the ``xacro.`` namespace
(``xacro.load_yaml``, ``xacro.arg``, ``xacro.print_location``...), ``python.`` and ``math.``
names, yaml tags ``!degrees`` / ``!radians``, macro defaults with ``${}``. 2.x reads all of it
(and gives the same URDF as 1.13 and 1.14 on this workspace's files) but finds packages
through ament's index, which ROS 1 has not: ``$(find pkg)`` fails with "No module named
'ament_index_python'". :func:`use_ros1_packages` makes xacro's one package lookup rospkg's,
as Noetic's xacro does through roslaunch. ``$(anon)`` stays unknown to 2.x (no robot file
here or seen uses it)."""
from __future__ import annotations

# xacro 2.1.1's error handling names xml.parsers.expat without importing it: a missing file
# ended in "AttributeError: module 'xml' has no attribute 'parsers'" and three tracebacks
import os
import xml.parsers.expat  # noqa: F401

import rospkg
import xacro
import xacro.substitution_args as substitution_args

_packages = None


def find_package(name: str) -> str:
    """The package's folder, as ``rospack find`` gives it."""
    global _packages
    if _packages is None:
        _packages = rospkg.RosPack()
    try:
        return _packages.get_path(name)
    except rospkg.ResourceNotFound:
        raise substitution_args.SubstitutionException(
            f"$(find {name}): no package '{name}' on ROS_PACKAGE_PATH (source the "
            "workspace's devel/setup.bash)") from None


def use_ros1_packages() -> None:
    """``$(find pkg)`` (and ``find()`` in ``$(eval)``) through rospkg; files named as given
    in errors, as Noetic's xacro names them; safe to call again."""
    substitution_args._eval_find = find_package
    substitution_args._eval_dict["find"] = find_package
    # 2.x opens os.path.join(root_dir, name) with root_dir "." and so names a missing
    # "robots/r.urdf" as "./robots/r.urdf"; "" opens the same file (abspath("") is the
    # current folder too) and names it as the user typed it
    if xacro.root_dir == os.curdir:
        xacro.root_dir = ""
