"""Presses the MotionPlanning panel's Plan, then Execute, through MoveIt's remote-control
topics (/rviz/moveit/update_custom_goal_state, /rviz/moveit/plan, /rviz/moveit/execute:
what the panel's "Allow External Comm." serves, the buttons' own slots behind them), with a
named state of the px100's SRDF as the goal. Waits for the planned path to end at the goal,
then for /joint_states to reach it; prints the joints reached as JSON."""
import json
import sys
import xml.etree.ElementTree as ElementTree

import rospy
from moveit_msgs.msg import DisplayTrajectory, RobotState
from sensor_msgs.msg import JointState
from std_msgs.msg import Empty

ROBOT = "px100"
GROUP = "interbotix_arm"
TOLERANCE = 0.01      # rad: the goal reached
WAIT = 60.0           # s for each of: rviz listening, the plan, the execution


def named_state(name):
    semantic = ElementTree.fromstring(rospy.get_param(f"/{ROBOT}/robot_description_semantic"))
    for state in semantic.iter("group_state"):
        if state.get("name") == name and state.get("group") == GROUP:
            return {joint.get("name"): float(joint.get("value")) for joint in state.iter("joint")}
    raise SystemExit(f"no state {name} of {GROUP}")


def wait_for(condition, what):
    deadline = rospy.get_time() + WAIT
    while not condition():
        if rospy.get_time() > deadline or rospy.is_shutdown():
            raise SystemExit(f"timed out waiting for {what}")
        rospy.sleep(0.05)


def reaches(positions, goal):
    return all(abs(positions.get(name, 1e9) - value) < TOLERANCE for name, value in goal.items())


def main(name):
    rospy.init_node("rviz_remote_control", anonymous=True)
    goal = named_state(name)
    seen = {"path_end": {}, "joints": {}}

    def path(message):
        for part in message.trajectory:
            names = part.joint_trajectory.joint_names
            if part.joint_trajectory.points:
                seen["path_end"] = dict(zip(names, part.joint_trajectory.points[-1].positions))

    def joints(message):
        seen["joints"] = dict(zip(message.name, message.position))

    rospy.Subscriber(f"/{ROBOT}/move_group/display_planned_path", DisplayTrajectory, path)
    rospy.Subscriber(f"/{ROBOT}/joint_states", JointState, joints)
    custom_goal = rospy.Publisher("/rviz/moveit/update_custom_goal_state", RobotState,
                                  queue_size=1, latch=True)
    plan = rospy.Publisher("/rviz/moveit/plan", Empty, queue_size=1)
    execute = rospy.Publisher("/rviz/moveit/execute", Empty, queue_size=1)
    wait_for(lambda: all(p.get_num_connections() for p in (custom_goal, plan, execute)),
             "rviz's MotionPlanning to listen on /rviz/moveit/*")
    state = RobotState()
    state.joint_state.name, state.joint_state.position = list(goal), list(goal.values())
    custom_goal.publish(state)
    rospy.sleep(0.5)   # the goal is taken before the plan (one subscriber queue each)
    plan.publish(Empty())
    wait_for(lambda: reaches(seen["path_end"], goal), f"a planned path ending at {name}")
    execute.publish(Empty())
    wait_for(lambda: reaches(seen["joints"], goal), f"/joint_states at {name}")
    print(json.dumps({joint: seen["joints"][joint] for joint in goal}))


if __name__ == "__main__":
    main(sys.argv[1])
