"""A C++ kinematics plugin (``kinematics::KinematicsBase``, found by pluginlib: IKFast's
generated plugins, any package exporting ``<moveit_core plugin="..."/>``) as move_group's
solver for a group, with :class:`~moveit_kinematics.kdl_solver.KdlSolver`'s interface.

The plugin runs in this process through the pybind11 module :mod:`moveit_kinematics._plugin_host`
(src/plugin_host/plugin_host.cpp), which loads and initialises it as MoveIt's
KinematicsPluginLoader does (its comments cite the lines). roscpp is initialised once per
process, when the first plugin is loaded, under :data:`ROS_NODE_NAME` in move_group's
namespace: plugins read their parameters (``robot_description_kinematics/<group>/...``) with
roscpp's NodeHandles.

:meth:`PluginSolver.inverse` is MoveIt's ``searchPositionIK(pose, seed, timeout, solution,
solution_callback, error_code)``: the pose in the solver's base frame, the timeout the
group's ``kinematics_solver_timeout`` when none is given (the plugin's default timeout, set
as MoveIt sets it), ``accept`` the solution callback. ``seed_iterations`` (the KDL descent's
steps from the seed) has no meaning for a plugin and is ignored.
"""
from __future__ import annotations

import atexit
import logging
from typing import Callable, Dict, List, Optional, Sequence

import numpy as np
from tf.transformations import quaternion_from_matrix, quaternion_matrix

from moveit_core.robot_model import RobotModel, RobotModelError
from moveit_kinematics.kdl_solver import MAX_ITERATIONS, SolverSettings

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_kinematics")

# the roscpp node beside move_group's rospy node (which is /move_group: a second node of that
# name would make the master shut the first down)
ROS_NODE_NAME = "move_group_kinematics"
# MoveIt's MoveItErrorCodes.SUCCESS
SUCCESS = 1

_ros_started = False


class PluginLoadError(RuntimeError):
    """The plugin cannot serve the group; the message says why (move_group falls back)."""


def _host():
    """The host module; PluginLoadError when this workspace was built without it."""
    try:
        from moveit_kinematics import _plugin_host
    except ImportError as error:
        raise PluginLoadError(f"the plugin host moveit_kinematics._plugin_host is not built "
                              f"({error})") from error
    return _plugin_host


def _namespace() -> str:
    """move_group's namespace when rospy runs in this process, else the root."""
    import rospy
    return rospy.get_namespace() if rospy.core.is_initialized() else "/"


def _start_ros(host) -> None:
    global _ros_started
    if not _ros_started:
        if host.init_ros(ROS_NODE_NAME, _namespace()):
            atexit.register(host.shutdown_ros)
        _ros_started = True


def pose_values(matrix: np.ndarray) -> List[float]:
    """(x y z qx qy qz qw) of a 4x4 pose."""
    return [float(v) for v in matrix[:3, 3]] + [float(v) for v in quaternion_from_matrix(matrix)]


def pose_of(values: Sequence[float]) -> np.ndarray:
    matrix = quaternion_matrix(values[3:])
    matrix[:3, 3] = values[:3]
    return matrix


class PluginSolver:
    """IK and FK of one group by the C++ plugin ``settings.kinematics_solver``; raises
    :class:`PluginLoadError` (naming why) when pluginlib cannot find or create it, or its
    initialize() fails or throws."""

    def __init__(self, model: RobotModel, group: str, settings: SolverSettings,
                 urdf: str, srdf: str, ik_links: Sequence[str] = ()):
        self.model, self.settings = model, settings
        self.group = model.group(group)
        host = _host()
        _start_ros(host)
        bounds = {j: (b.lower, b.upper) for j, b in model.bounds.items() if b.bounded}
        try:
            self._plugin = host.load(settings.kinematics_solver, urdf, srdf, bounds, group,
                                     list(ik_links),
                                     float(settings.kinematics_solver_search_resolution),
                                     float(settings.kinematics_solver_timeout))
        except host.PluginError as error:
            raise PluginLoadError(str(error)) from error
        self.joints: List[str] = list(self._plugin.joint_names)
        unknown = [j for j in self.joints if j not in model.bounds]
        if unknown:
            raise PluginLoadError(f"the plugin names joints the model does not move: {unknown}")
        self.base = self._plugin.base_frame
        self.tip = self._plugin.tip_frames[0]
        self.bounds = [model.bounds[j] for j in self.joints]
        self.lookup_name = settings.kinematics_solver

    def forward(self, positions: Sequence[float]) -> np.ndarray:
        """The tip's pose in the base frame (4x4), by the plugin's getPositionFK."""
        poses = self._plugin.forward([self.tip], [float(v) for v in positions])
        if not poses:
            raise RobotModelError(f"{self.lookup_name}: getPositionFK failed for {self.tip}")
        return pose_of(poses[0])

    def inverse(self, target: np.ndarray, seed: Sequence[float],
                timeout: Optional[float] = None,
                seed_iterations: int = MAX_ITERATIONS,
                accept: Optional[Callable[[List[float]], bool]] = None
                ) -> Optional[List[float]]:
        """searchPositionIK: the joints (self.joints' order) or None (see the module)."""
        del seed_iterations   # the KDL descent's; a plugin searches its own way
        timeout = self._plugin.default_timeout if not timeout else timeout
        solution, code = self._plugin.search(pose_values(np.asarray(target)),
                                             [float(v) for v in seed], float(timeout), accept)
        return list(solution) if code == SUCCESS and solution else None

    def state(self, positions: Sequence[float]) -> Dict[str, float]:
        return dict(zip(self.joints, positions))
