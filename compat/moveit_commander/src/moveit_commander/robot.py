"""``RobotCommander``: the robot's model (groups, joints, links, the planning frame) and its
current state from ``joint_states``; ``robot.<name>`` is a group's commander, a joint or a
link, as MoveIt's."""
from __future__ import annotations

from typing import Dict, List, Optional

from geometry_msgs.msg import PoseStamped
from moveit_msgs.msg import RobotState
from visualization_msgs.msg import MarkerArray

from moveit_commander import _shared
from moveit_commander.exception import MoveItCommanderException
from moveit_commander.move_group import MoveGroupCommander, _matrix_pose


class RobotCommander:
    class Joint:
        def __init__(self, robot: "RobotCommander", name: str):
            self._robot, self._name = robot, name

        def name(self) -> str:
            return self._name

        def variable_count(self) -> int:
            return 1 if self._name in self._robot._model.bounds else 0

        def bounds(self) -> Optional[List[float]]:
            b = self._robot._model.bounds.get(self._name)
            return [b.lower, b.upper] if b else None

        def min_bound(self) -> Optional[float]:
            bounds = self.bounds()
            return bounds[0] if bounds else None

        def max_bound(self) -> Optional[float]:
            bounds = self.bounds()
            return bounds[1] if bounds else None

        def value(self) -> Optional[float]:
            return self._robot._shared.positions().get(self._name)

        def move(self, position, wait: bool = True) -> bool:
            group = self._robot.get_default_owner_group(self._name)
            if group is None:
                raise MoveItCommanderException(f"There is no known group containing joint "
                                               f"{self._name}. Cannot move.")
            commander = self._robot.get_group(group)
            commander.set_joint_value_target(self._name, position)
            return commander.go(wait=wait)

    class Link:
        def __init__(self, robot: "RobotCommander", name: str):
            self._robot, self._name = robot, name

        def name(self) -> str:
            return self._name

        def pose(self) -> PoseStamped:
            poses = self._robot._model.link_poses(self._robot._shared.positions())
            stamped = PoseStamped(pose=_matrix_pose(poses[self._name]))
            stamped.header.frame_id = self._robot.get_planning_frame()
            return stamped

    def __init__(self, robot_description: str = "robot_description", ns: str = ""):
        self._shared = _shared.robot(robot_description, ns)
        self._model = self._shared.model
        self._description, self._ns = robot_description, ns
        self._groups: Dict[str, MoveGroupCommander] = {}

    def get_planning_frame(self) -> str:
        return self._model.model_frame

    def get_robot_markers(self, *args) -> MarkerArray:
        return MarkerArray()

    def get_root_link(self) -> str:
        return self._model.root_link

    def get_group_names(self) -> List[str]:
        return list(self._model.groups)

    def _group_or_all(self, group, of_group, everything):
        if group is None:
            return everything
        if group not in self._model.groups:
            raise MoveItCommanderException(f"There is no group named {group}")
        return of_group(self._model.group(group))

    def get_active_joint_names(self, group: Optional[str] = None) -> List[str]:
        return self._group_or_all(group, lambda g: list(g.variables), list(self._model.variables))

    def get_joint_names(self, group: Optional[str] = None) -> List[str]:
        return self._group_or_all(group, lambda g: list(g.joints), list(self._model.joint_order))

    def get_link_names(self, group: Optional[str] = None) -> List[str]:
        return self._group_or_all(group, lambda g: list(g.links),
                                  [self._model.root_link] +
                                  [self._model.urdf.joints[j].child
                                   for j in self._model.joint_order])

    def get_current_state(self) -> RobotState:
        return _shared.state_message(self._shared)

    def get_current_variable_values(self) -> Dict[str, float]:
        positions = self._shared.positions()
        return {j: positions[j] for j in self._model.variables}

    def get_joint(self, name: str) -> "RobotCommander.Joint":
        if name not in self._model.urdf.joints:
            raise MoveItCommanderException(f"There is no joint named {name}")
        return self.Joint(self, name)

    def get_link(self, name: str) -> "RobotCommander.Link":
        if name not in self._model.urdf.links:
            raise MoveItCommanderException(f"There is no link named {name}")
        return self.Link(self, name)

    def get_group(self, name: str) -> MoveGroupCommander:
        if name not in self._groups:
            if not self.has_group(name):
                raise MoveItCommanderException(f"There is no group named {name}")
            self._groups[name] = MoveGroupCommander(name, self._description, self._ns)
        return self._groups[name]

    def has_group(self, name: str) -> bool:
        return name in self._model.groups

    def get_default_owner_group(self, joint_name: str) -> Optional[str]:
        owners = [g for g in self._model.groups.values() if joint_name in g.joints]
        return min(owners, key=lambda g: len(g.links)).name if owners else None

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        if name in self._model.groups:
            return self.get_group(name)
        if name in self._model.urdf.joints:
            return self.get_joint(name)
        if name in self._model.urdf.links:
            return self.get_link(name)
        raise AttributeError(f"'RobotCommander' object has no attribute '{name}'")
