"""moveit_commander (Noetic's API) in Python: MoveGroupCommander, RobotCommander and
PlanningSceneInterface as clients of move_group's ROS interfaces, as the real ones are."""
from moveit_commander import conversions
from moveit_commander.exception import MoveItCommanderException
from moveit_commander.move_group import MoveGroupCommander
from moveit_commander.planning_scene_interface import PlanningSceneInterface
from moveit_commander.robot import RobotCommander
from moveit_commander.roscpp_initializer import roscpp_initialize, roscpp_shutdown

__all__ = ["MoveGroupCommander", "MoveItCommanderException", "PlanningSceneInterface",
           "RobotCommander", "conversions", "roscpp_initialize", "roscpp_shutdown"]
