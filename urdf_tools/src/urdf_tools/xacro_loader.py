"""Expands a xacro (or plain URDF) file to URDF text and parses it.

PyPI's xacro 2.x with ``$(find pkg)`` resolved through rospkg (compat/xacro's xacro_ros1),
so the workspace's environment (tools/env.bash) must be sourced for files that use it.
"""
from __future__ import annotations

from typing import Mapping, Optional

import xacro
from xacro_ros1 import use_ros1_packages

from urdf_tools.model import RobotModel, UrdfError, parse_urdf


def expand(path: str, mappings: Optional[Mapping[str, str]] = None) -> str:
    """The URDF text that ``xacro path name:=value ...`` prints."""
    use_ros1_packages()
    try:
        document = xacro.process_file(path, mappings=dict(mappings or {}))
    except Exception as error:  # xacro raises many kinds; all mean "this file is broken"
        raise UrdfError(f"{path}: xacro failed: {error}") from error
    return document.toprettyxml(indent="  ")


def load(path: str, mappings: Optional[Mapping[str, str]] = None) -> RobotModel:
    """Expands and parses a xacro or URDF file."""
    return parse_urdf(expand(path, mappings), source=path)
