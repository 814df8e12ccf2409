"""Which solver answers a group's entry of ``robot_description_kinematics`` (move_group's
kinematics plugin loader, MoveIt's KinematicsPluginLoader on noetic-devel).

- ``kdl_kinematics_plugin/KDLKinematicsPlugin`` and MoveIt's other built-in solvers (LMA,
  cached, service: :data:`~moveit_kinematics.kdl_solver.SOLVER_NAMES`): the Python
  :class:`~moveit_kinematics.kdl_solver.KdlSolver` (Orocos KDL, as MoveIt's KDL plugin).
- ``trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin``: :class:`~moveit_kinematics.trac_ik.TracIkSolver`
  (TRAC-IK is not packaged by Debian), with TRAC-IK's ``solve_type`` and ``epsilon``.
- any other name: a C++ plugin loaded through pluginlib and initialised as MoveIt initialises
  it (:class:`~moveit_kinematics.plugin_solver.PluginSolver`); when it cannot be loaded (not
  found, its initialize() returned false or threw, or the plugin host is not built), the
  reason is logged and the group is answered by KDL, so that move_group still runs.

Whatever is chosen is logged once per group: ``group 'X': kinematics solver 'name' loaded``
(and by what).
"""
from __future__ import annotations

import logging
from typing import Mapping, Sequence, Union

from moveit_core.robot_model import RobotModel
from moveit_kinematics.kdl_solver import KDL_PLUGIN, SOLVER_NAMES, KdlSolver, SolverSettings
from moveit_kinematics.plugin_solver import PluginLoadError, PluginSolver
from moveit_kinematics.trac_ik import TRAC_IK_PLUGIN, TracIkSettings, TracIkSolver

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_kinematics")

# the parameter naming a solver's tip links (kinematics_plugin_loader.cpp l. 403-425)
IK_LINKS = "kinematics_solver_ik_links"
# a parameter MoveIt no longer reads, with a warning (kinematics_plugin_loader.cpp l. 349-358)
ATTEMPTS = "kinematics_solver_attempts"

Solver = Union[KdlSolver, PluginSolver]

_warned_attempts = False


def load_solver(model: RobotModel, group: str, entry: Mapping, urdf: str, srdf: str) -> Solver:
    """The solver of ``group`` for its ``robot_description_kinematics`` ``entry``
    (RobotModelError / TypeError when even KDL cannot serve it: not a chain, bad values)."""
    settings = SolverSettings.from_parameters(entry)
    name = settings.kinematics_solver
    global _warned_attempts
    if ATTEMPTS in entry and not _warned_attempts:
        _warned_attempts = True     # ROS_WARN_ONCE upstream
        LOG.warning("Kinematics solver doesn't support #attempts anymore, but only a timeout. "
                    "Please remove the parameter '%s' from your configuration.",
                    f"robot_description_kinematics/{group}/{ATTEMPTS}")
    if name == TRAC_IK_PLUGIN:
        solver = TracIkSolver(model, group, settings, TracIkSettings.from_parameters(entry))
        LOG.info("group '%s': kinematics solver '%s' loaded (TRAC-IK's solve types on the "
                 "KDL solver: TRAC-IK is not installed)", group, name)
        return solver
    if name in SOLVER_NAMES:
        solver = KdlSolver(model, group, settings)
        LOG.info("group '%s': kinematics solver '%s' loaded%s", group, name,
                 "" if name == KDL_PLUGIN else f" (answered by KDL's solver, {KDL_PLUGIN})")
        return solver
    try:
        solver = PluginSolver(model, group, settings, urdf, srdf, _ik_links(entry))
    except PluginLoadError as error:
        LOG.error("group '%s': kinematics solver '%s' could not be loaded: %s; solving with "
                  "KDL (%s) instead", group, name, error, KDL_PLUGIN)
        return KdlSolver(model, group, settings)
    LOG.info("group '%s': kinematics solver '%s' loaded (C++ plugin through pluginlib; base "
             "'%s', tip '%s', joints %s)", group, name, solver.base, solver.tip,
             ", ".join(solver.joints))
    return solver


def _ik_links(entry: Mapping) -> Sequence[str]:
    links = entry.get(IK_LINKS, ())
    return [str(link) for link in links] if isinstance(links, (list, tuple)) else ()
