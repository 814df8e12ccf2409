"""MoveIt's trajectory execution manager: a RobotTrajectory split among the controllers of
the configured controller manager (fake or simple), sent, and watched until done.

As MoveIt: the robot must be within ``trajectory_execution/allowed_start_tolerance`` of the
first point (else CONTROL_FAILED); the trajectory's joints must all have a controller (else
CONTROL_FAILED naming those without); execution longer than the trajectory's duration
times ``allowed_execution_duration_scaling`` plus ``allowed_goal_duration_margin`` is
stopped (TIMED_OUT); ``stop`` (``trajectory_execution_event`` "stop", or a cancelled goal)
stops the controllers (PREEMPTED); a success is reported once joint_states show the robot
at the last point (as wait_for_trajectory_completion), a second at most."""
from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import rospy
from moveit_msgs.msg import MoveItErrorCodes as Codes
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

POLL = 0.01          # s between looks at the controllers
ARRIVAL_WAIT = 1.0   # s: the longest the reported state may lag the controllers at the end
ARRIVAL_TOLERANCE = 1e-3   # rad (m): the reported state at the last point


@dataclass(frozen=True)
class ExecutionSettings:
    """``trajectory_execution/*`` in move_group's namespace (MoveIt's defaults)."""

    allowed_execution_duration_scaling: float = 1.1
    allowed_goal_duration_margin: float = 0.5
    allowed_start_tolerance: float = 0.01
    execution_duration_monitoring: bool = True


def part(trajectory: JointTrajectory, joints: Sequence[str]) -> JointTrajectory:
    """The trajectory of ``joints`` only (positions, velocities, accelerations kept)."""
    index = [list(trajectory.joint_names).index(j) for j in joints]
    message = JointTrajectory(joint_names=list(joints))
    message.header = trajectory.header
    for point in trajectory.points:
        message.points.append(JointTrajectoryPoint(
            positions=[point.positions[i] for i in index],
            velocities=[point.velocities[i] for i in index] if point.velocities else [],
            accelerations=[point.accelerations[i] for i in index] if point.accelerations else [],
            time_from_start=point.time_from_start))
    return message


class TrajectoryExecutionManager:
    def __init__(self, manager, settings: ExecutionSettings, current):
        self.manager, self.settings, self.current = manager, settings, current
        self._stop = threading.Event()
        self._lock = threading.Lock()      # one execution at a time

    def stop(self) -> None:
        self._stop.set()

    def assign(self, joints: Sequence[str]) -> Tuple[Dict[str, List[str]], List[str]]:
        """Controllers for ``joints``: the fewest that cover them (each gets the joints it
        has); and the joints no controller has."""
        left, chosen = set(joints), {}
        controllers = dict(self.manager.controllers)
        while left:
            name = max(controllers, key=lambda n: len(left & set(controllers[n].joints)),
                       default=None)
            if name is None or not left & set(controllers[name].joints):
                break
            mine = [j for j in joints if j in controllers[name].joints and j in left]
            chosen[name] = mine
            left -= set(mine)
            controllers.pop(name)
        return chosen, sorted(left)

    def execute(self, trajectory: JointTrajectory,
                preempted: Optional[Callable[[], bool]] = None) -> Tuple[int, str]:
        """Runs ``trajectory``; (MoveIt's error code, what happened). ``preempted()``: the
        goal that asks has been preempted (a stop heard before this execution began is
        cleared here, so the goal is asked once more once it holds the manager)."""
        if not trajectory.points:
            return Codes.SUCCESS, "nothing to execute"
        with self._lock:
            self._stop.clear()
            if preempted is not None and preempted():
                return Codes.PREEMPTED, "preempted before execution: nothing was executed"
            return self._execute(trajectory)

    def _execute(self, trajectory: JointTrajectory) -> Tuple[int, str]:
        joints = list(trajectory.joint_names)
        tolerance = self.settings.allowed_start_tolerance
        if tolerance > 0:
            now = self.current.positions()
            off = [f"{j} at {now[j]:.4f}, the trajectory starts at {p:.4f}"
                   for j, p in zip(joints, trajectory.points[0].positions)
                   if j in now and abs(now[j] - p) > tolerance]
            if off:
                return Codes.CONTROL_FAILED, ("the robot is not where the trajectory starts "
                                              f"(allowed_start_tolerance {tolerance}): "
                                              + "; ".join(off))
        chosen, orphans = self.assign(joints)
        if orphans:
            return Codes.CONTROL_FAILED, (f"no controller of controller_list moves {orphans} "
                                          f"(controllers: {sorted(self.manager.controllers)})")
        duration = trajectory.points[-1].time_from_start.to_sec()
        limit = duration * self.settings.allowed_execution_duration_scaling + \
            self.settings.allowed_goal_duration_margin
        runs = [self.manager.start(name, mine, part(trajectory, mine))
                for name, mine in chosen.items()]
        began = rospy.get_time()
        while not all(run.done() for run in runs):
            if self._stop.is_set() or rospy.is_shutdown():
                for run in runs:
                    run.stop()
                return Codes.PREEMPTED, "execution stopped"
            if self.settings.execution_duration_monitoring and \
                    rospy.get_time() - began > limit:
                for run in runs:
                    run.stop()
                return Codes.TIMED_OUT, (f"execution took longer than {limit:.2f} s (the "
                                         f"trajectory's {duration:.2f} s x "
                                         f"{self.settings.allowed_execution_duration_scaling} "
                                         f"+ {self.settings.allowed_goal_duration_margin})")
            rospy.sleep(POLL)
        failed = [name for (name, _), run in zip(chosen.items(), runs) if not run.succeeded]
        if failed:
            return Codes.CONTROL_FAILED, f"controller(s) {failed} did not complete the motion"
        self._wait_for_robot(joints, trajectory.points[-1].positions)
        return Codes.SUCCESS, f"executed in {rospy.get_time() - began:.2f} s"

    def _wait_for_robot(self, joints: Sequence[str], final: Sequence[float]) -> None:
        """As MoveIt's wait_for_trajectory_completion: the robot's reported state (through
        joint_states, a publisher's period behind the controllers) has reached the last
        point before the execution is reported done, ARRIVAL_WAIT s at most."""
        deadline = rospy.get_time() + ARRIVAL_WAIT
        while rospy.get_time() < deadline and not rospy.is_shutdown():
            now = self.current.positions()
            if all(abs(now.get(j, p) - p) <= ARRIVAL_TOLERANCE for j, p in zip(joints, final)):
                return
            rospy.sleep(POLL)
