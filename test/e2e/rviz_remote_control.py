"""Presses the MotionPlanning panel's Plan, then Execute, through MoveIt's remote-control
topics (/rviz/moveit/update_custom_goal_state, /rviz/moveit/plan, /rviz/moveit/execute:
what the panel's "Allow External Comm." serves, the buttons' own slots behind them).

``rviz_remote_control.py STATE``: the goal is a named state of the px100's SRDF. Waits for
the planned path to end at it, then for /joint_states to reach it; prints the joints
reached as JSON.

``rviz_remote_control.py --marker W S E A``: the goal is where the gripper is at those joint
values (move_group's compute_fk), set by dragging the display's goal marker there (the
feedback rviz's InteractiveMarkers display sends, on MoveIt's marker topic); plans and
executes, then prints the gripper's position wanted and reached (TF) as JSON."""
import json
import sys
import xml.etree.ElementTree as ElementTree

import rospy
import tf2_ros
from moveit_msgs.msg import DisplayTrajectory, RobotState
from moveit_msgs.srv import GetPositionFK
from sensor_msgs.msg import JointState
from std_msgs.msg import Empty
from visualization_msgs.msg import InteractiveMarkerFeedback

ROBOT = "px100"
GROUP = "interbotix_arm"
TOLERANCE = 0.01      # rad: the goal reached
WAIT = 60.0           # s for each of: rviz listening, the plan, the execution
GRIPPER_LINK = ROBOT + "/ee_gripper_link"
ARM_JOINTS = ["waist", "shoulder", "elbow", "wrist_angle"]
# the MotionPlanning display's goal marker (its server runs in rviz, in rviz's namespace)
MARKER_FEEDBACK = (f"/{ROBOT}/rviz_moveit_motion_planning_display/"
                   "robot_interaction_interactive_marker_topic/feedback")
MARKER_NAME = "EE:goal"
POSITION_TOLERANCE = 0.005   # m between the marker's position and the gripper's


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


def gripper_pose_at(joints):
    fk = rospy.ServiceProxy(f"/{ROBOT}/compute_fk", GetPositionFK)
    fk.wait_for_service(WAIT)
    state = RobotState()
    state.joint_state.name, state.joint_state.position = ARM_JOINTS, joints
    answer = fk(header=rospy.Header(frame_id="world"), fk_link_names=[GRIPPER_LINK],
                robot_state=state)
    assert answer.error_code.val == 1, answer.error_code
    return answer.pose_stamped[0]


def drag_marker(joints):
    """Sends the marker's pose-update feedback for the gripper's pose at ``joints``; returns
    the position."""
    pose = gripper_pose_at(joints)
    feedback = rospy.Publisher(MARKER_FEEDBACK, InteractiveMarkerFeedback, queue_size=1)
    wait_for(lambda: feedback.get_num_connections(), "the goal marker's server in rviz")
    message = InteractiveMarkerFeedback(header=pose.header, client_id="/rviz_test",
                                        marker_name=MARKER_NAME, control_name="move_x",
                                        event_type=InteractiveMarkerFeedback.MOUSE_UP,
                                        pose=pose.pose)
    feedback.publish(message)
    return [pose.pose.position.x, pose.pose.position.y, pose.pose.position.z]


def main(name, *marker_joints):
    rospy.init_node("rviz_remote_control", anonymous=True)
    marker = name == "--marker"
    goal = None if marker else named_state(name)
    seen = {"path_end": {}, "joints": {}, "paths": 0}

    def path(message):
        seen["paths"] += 1
        for part in message.trajectory:
            names = part.joint_trajectory.joint_names
            if part.joint_trajectory.points:
                seen["path_end"] = dict(zip(names, part.joint_trajectory.points[-1].positions))

    def joint_states(message):
        seen["joints"] = dict(zip(message.name, message.position))

    paths = rospy.Subscriber(f"/{ROBOT}/move_group/display_planned_path", DisplayTrajectory,
                             path)
    rospy.Subscriber(f"/{ROBOT}/joint_states", JointState, joint_states)
    custom_goal = rospy.Publisher("/rviz/moveit/update_custom_goal_state", RobotState,
                                  queue_size=1, latch=True)
    plan = rospy.Publisher("/rviz/moveit/plan", Empty, queue_size=1)
    execute = rospy.Publisher("/rviz/moveit/execute", Empty, queue_size=1)
    wait_for(lambda: all(p.get_num_connections() for p in (custom_goal, plan, execute)),
             "rviz's MotionPlanning to listen on /rviz/moveit/*")
    if marker:
        wanted = drag_marker([float(value) for value in marker_joints])
    else:
        state = RobotState()
        state.joint_state.name, state.joint_state.position = list(goal), list(goal.values())
        custom_goal.publish(state)
    wait_for(lambda: paths.get_num_connections(), "move_group's planned-path topic")
    rospy.sleep(0.5)   # the goal is taken before the plan (one subscriber queue each), and
    earlier = seen["paths"]   # an earlier plan, latched, has come
    plan.publish(Empty())
    if marker:
        # the plan's end is the IK solution rviz found: executed, the gripper is at the marker
        wait_for(lambda: seen["paths"] > earlier, "a new planned path")
        end = dict(seen["path_end"])
        execute.publish(Empty())
        wait_for(lambda: reaches(seen["joints"], end), "/joint_states at the plan's end")
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        rospy.sleep(0.5)   # TF of the state reached
        found = buffer.lookup_transform("world", GRIPPER_LINK, rospy.Time(0),
                                        rospy.Duration(WAIT)).transform.translation
        print(json.dumps({"wanted": wanted, "reached": [found.x, found.y, found.z]}))
        return
    wait_for(lambda: seen["paths"] > earlier and reaches(seen["path_end"], goal),
             f"a planned path ending at {name}")
    execute.publish(Empty())
    wait_for(lambda: reaches(seen["joints"], goal), f"/joint_states at {name}")
    print(json.dumps({joint: seen["joints"][joint] for joint in goal}))


if __name__ == "__main__":
    main(*sys.argv[1:])
