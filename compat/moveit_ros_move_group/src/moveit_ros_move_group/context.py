"""What every capability of move_group shares (MoveIt's MoveGroupContext): the robot model
from ``robot_description`` and ``robot_description_semantic``, a kinematics solver per group
that ``robot_description_kinematics`` names, and the current state. Built from plain values
(:func:`from_parameters` reads them from the parameter server), so capabilities are tested
without a master."""
from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Dict, Mapping, Optional

import numpy as np

from moveit_core import robot_model
from moveit_core.robot_model import RobotModel, RobotModelError
from moveit_kinematics.solvers import Solver, load_solver
from moveit_ros_move_group.state_monitor import CurrentState

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.move_group")


class ContextError(RuntimeError):
    """move_group cannot start: a parameter it needs is missing or unusable."""


@dataclass
class MoveGroupContext:
    model: RobotModel
    kinematics: Mapping[str, Mapping] = field(default_factory=dict)  # by group
    state: Optional[CurrentState] = None
    # the descriptions the model was built from: C++ kinematics plugins build theirs from them
    urdf: str = ""
    srdf: str = ""
    _solvers: Dict[str, Optional[Solver]] = field(default_factory=dict)

    def __post_init__(self):
        if self.state is None:
            self.state = CurrentState(self.model.default_positions())

    def solver(self, group: str) -> Solver:
        """The group's kinematics solver (:func:`moveit_kinematics.solvers.load_solver`'s
        choice: a C++ plugin through pluginlib, TRAC-IK's or KDL's); RobotModelError when the
        group has none (no entry in robot_description_kinematics, or not a chain) or does
        not exist."""
        self.model.group(group)
        if group not in self._solvers:
            entry = self.kinematics.get(group)
            if entry is None:
                self._solvers[group] = None
            else:
                try:
                    self._solvers[group] = load_solver(self.model, group, entry,
                                                       self.urdf, self.srdf)
                except (RobotModelError, TypeError) as error:
                    LOG.error("group '%s' gets no kinematics solver: %s", group, error)
                    self._solvers[group] = None
        found = self._solvers[group]
        if found is None:
            raise RobotModelError(f"group '{group}' has no kinematics solver (none in "
                                  "robot_description_kinematics, or it is not a chain)")
        return found

    def frame_pose(self, frame: str, positions: Mapping[str, float]) -> np.ndarray:
        """The pose of ``frame`` (a link, or the model frame; '' is the model frame) in the
        model frame; KeyError when the robot has no such frame."""
        if frame in ("", self.model.model_frame, self.model.root_link):
            return np.eye(4)
        return self.model.link_poses(positions)[frame]


def from_parameters(get_param) -> MoveGroupContext:
    """The context from the parameter server (``get_param(name)`` as rospy's, relative names
    in the node's namespace, as MoveIt reads them)."""
    try:
        urdf = get_param("robot_description")
    except KeyError:
        raise ContextError("no robot_description: load the robot's URDF (a config package's "
                           "planning_context.launch with load_robot_description, or the "
                           "robot's description launch) before move_group") from None
    try:
        srdf = get_param("robot_description_semantic")
    except KeyError:
        raise ContextError("no robot_description_semantic: load the config package's SRDF "
                           "(planning_context.launch) before move_group") from None
    planning = _optional(get_param, "robot_description_planning", {})
    kinematics = _optional(get_param, "robot_description_kinematics", {})
    try:
        model = robot_model.load(str(urdf), str(srdf), (planning or {}).get("joint_limits", {}))
    except ValueError as error:
        raise ContextError(f"the robot model cannot be built: {error}") from error
    for warning in model.srdf.warnings:
        LOG.warning(warning)
    context = MoveGroupContext(model, kinematics if isinstance(kinematics, dict) else {},
                               urdf=str(urdf), srdf=str(srdf))
    # the solvers are loaded as move_group starts, as MoveIt's RobotModelLoader loads the
    # kinematics plugins of every group that robot_description_kinematics names
    # (robot_model_loader.cpp, loadKinematicsSolvers): a plugin that cannot be loaded is
    # named in the log before the first request
    for group in context.kinematics:
        if group in model.groups:
            try:
                context.solver(group)
            except RobotModelError:
                pass    # logged by solver(); requests for the group are refused
    return context


def _optional(get_param, name, default):
    try:
        return get_param(name)
    except KeyError:
        return default
