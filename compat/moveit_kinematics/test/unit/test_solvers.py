"""Which solver move_group gets for a group's robot_description_kinematics entry, and the
line it logs (no master here: C++ plugins are loaded in test/e2e/test_kinematics_plugins.py)."""
import logging
import os

import pytest

from moveit_core import robot_model
from moveit_kinematics import solvers
from moveit_kinematics.kdl_solver import KDL_PLUGIN, KdlSolver
from moveit_kinematics.solvers import load_solver
from moveit_kinematics.trac_ik import TracIkSolver

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
LMA = "lma_kinematics_plugin/LMAKinematicsPlugin"
TRAC_IK = "trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin"


@pytest.fixture(scope="module")
def model():
    with open(os.path.join(DATA, "six_axis_arm.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "six_axis_arm.srdf"), encoding="utf-8") as srdf:
        return robot_model.load(urdf.read(), srdf.read())


@pytest.mark.parametrize("name, kind, by", [
    (KDL_PLUGIN, KdlSolver, ""),
    (LMA, KdlSolver, f" (answered by KDL's solver, {KDL_PLUGIN})"),
    (TRAC_IK, TracIkSolver, " (TRAC-IK's solve types on the KDL solver"),
])
def test_moveits_own_solvers_are_answered_in_python(model, caplog, name, kind, by):
    with caplog.at_level(logging.INFO, logger="rosout.moveit_kinematics"):
        solver = load_solver(model, "manipulator", {"kinematics_solver": name}, "", "")
    assert type(solver) is kind
    assert f"group 'manipulator': kinematics solver '{name}' loaded{by}" in caplog.text


def test_kinematics_solver_attempts_is_warned_about_once(model, caplog, monkeypatch):
    # kinematics_plugin_loader.cpp l. 349-358: ROS_WARN_ONCE, and the value is not used
    monkeypatch.setattr(solvers, "_warned_attempts", False)
    entry = {"kinematics_solver": KDL_PLUGIN, "kinematics_solver_attempts": 3}
    with caplog.at_level(logging.WARNING, logger="rosout.moveit_kinematics"):
        load_solver(model, "manipulator", entry, "", "")
        load_solver(model, "manipulator", entry, "", "")
    assert caplog.text.count("Kinematics solver doesn't support #attempts anymore, but only a "
                             "timeout. Please remove the parameter 'robot_description_kinematics"
                             "/manipulator/kinematics_solver_attempts'") == 1
