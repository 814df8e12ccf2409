"""A URDF mesh ``filename`` to a file: ``package://pkg/path`` through rospkg,
``file://path``, or a path as it is. The simulator and move_group read meshes through here."""
from __future__ import annotations

import functools
import os

from urdf_tools.model import UrdfError


def resolve_package_uri(uri: str, source: str) -> str:
    """``package://pkg/path`` or ``file://path`` → a file path; UrdfError naming ``source``
    and the package when the package is not found."""
    if uri.startswith("file://"):
        return uri[len("file://"):]
    if not uri.startswith("package://"):
        return uri
    package, _, rest = uri[len("package://"):].partition("/")
    import rospkg  # only descriptions with package:// meshes need a ROS environment
    try:
        return os.path.join(_package_path(package, os.environ.get("ROS_PACKAGE_PATH", "")),
                            rest)
    except rospkg.ResourceNotFound:
        raise UrdfError(f"{source}: mesh '{uri}': ROS package '{package}' not found "
                        "(is the workspace sourced?)") from None


@functools.lru_cache(maxsize=256)
def _package_path(package: str, ros_package_path: str) -> str:
    """A ROS package's folder (rospkg crawls ROS_PACKAGE_PATH for each new RosPack, about
    12 ms: once per package, not once per mesh). Not found is not remembered."""
    import rospkg
    return rospkg.RosPack().get_path(package)
