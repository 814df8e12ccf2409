"""One step on a running MoveIt (the px100's, namespace px100) as a user's script takes it,
for the rviz tests: ``add NAME X Y Z SIZE``, ``cylinder NAME X Y Z HEIGHT RADIUS`` (upright),
``remove NAME``, ``attach NAME SIZE`` (a cube
on the gripper's ee_gripper_link), ``go STATE`` (a named state of interbotix_arm), ``plan
STATE`` (plans only: move_group shows the path), ``gripper`` (prints the ee_gripper_link's
position in the world, from TF), ``show LINK W S E A`` (publishes a DisplayRobotState on the
robot's display_robot_state: the arm at those joint values, LINK highlighted in yellow;
prints the world positions of LINK's origin and of its child link's, from move_group's
compute_fk), ``show_broken`` (a DisplayRobotState whose waist is NaN)."""
import json
import sys

import geometry_msgs.msg
import moveit_commander
import rospy
import tf2_ros
from moveit_msgs.msg import DisplayRobotState, ObjectColor, RobotState
from moveit_msgs.srv import GetPositionFK
from urdf_parser_py.urdf import URDF

ROBOT = "px100"
GRIPPER_LINK = "px100/ee_gripper_link"
TF_WAIT = 10.0    # s for the gripper's transform
# the hand's links a held box may touch (as a pick-and-place script lists them)
HAND_LINKS = [ROBOT + "/" + name for name in (
    "ee_arm_link", "gripper_link", "gripper_prop_link", "gripper_bar_link", "fingers_link",
    "left_finger_link", "right_finger_link", "ee_gripper_link")]


def show_state(message):
    """Publishes a DisplayRobotState on the robot's display_robot_state and stays until rviz
    has had it."""
    shown = rospy.Publisher(f"/{ROBOT}/display_robot_state", DisplayRobotState, queue_size=1,
                            latch=True)
    shown.publish(message)
    deadline = rospy.get_time() + TF_WAIT
    while shown.get_num_connections() == 0 and rospy.get_time() < deadline:
        rospy.sleep(0.05)
    rospy.sleep(1.0)   # latched: rviz has it once connected; the node stays that long


def main(step, *arguments):
    moveit_commander.roscpp_initialize(sys.argv[:1])
    rospy.init_node("moveit_scene_step", anonymous=True)
    if step in ("add", "cylinder", "remove", "attach"):
        scene = moveit_commander.PlanningSceneInterface(ns=ROBOT, synchronous=True)
        pose = geometry_msgs.msg.PoseStamped()
        pose.pose.orientation.w = 1.0
        if step == "add":
            name, x, y, z, size = arguments[0], *map(float, arguments[1:])
            pose.header.frame_id = "world"
            pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = x, y, z
            scene.add_box(name, pose, (size, size, size))
        elif step == "cylinder":
            name, x, y, z, height, radius = arguments[0], *map(float, arguments[1:])
            pose.header.frame_id = "world"
            pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = x, y, z
            scene.add_cylinder(name, pose, height, radius)
        elif step == "remove":
            scene.remove_world_object(arguments[0])
        else:
            pose.header.frame_id = GRIPPER_LINK
            size = float(arguments[1])
            scene.attach_box(GRIPPER_LINK, arguments[0], pose, (size, size, size), HAND_LINKS)
    elif step in ("go", "plan"):
        arm = moveit_commander.MoveGroupCommander("interbotix_arm",
                                                  robot_description=ROBOT + "/robot_description",
                                                  ns=ROBOT)
        arm.set_named_target(arguments[0])
        if step == "go":
            assert arm.go(wait=True), "the arm did not reach " + arguments[0]
        else:
            assert arm.plan()[0], "no plan to " + arguments[0]
    elif step == "show_broken":
        state = RobotState()
        state.joint_state.name = ["waist", "shoulder", "elbow", "wrist_angle"]
        state.joint_state.position = [float("nan"), 0.0, 0.0, 0.0]
        show_state(DisplayRobotState(state=state))
    elif step == "show":
        link, joints = arguments[0], [float(value) for value in arguments[1:]]
        state = RobotState()
        state.joint_state.name = ["waist", "shoulder", "elbow", "wrist_angle"]
        state.joint_state.position = joints
        highlight = ObjectColor(id=link)
        highlight.color.r, highlight.color.g, highlight.color.a = 1.0, 1.0, 1.0
        show_state(DisplayRobotState(state=state, highlight_links=[highlight]))
        fk = rospy.ServiceProxy(f"/{ROBOT}/compute_fk", GetPositionFK)
        fk.wait_for_service(TF_WAIT)
        child = URDF.from_xml_string(rospy.get_param(f"/{ROBOT}/robot_description")).child_map[
            link][0][1]
        found = [pose.pose.position for pose in fk(
            header=rospy.Header(frame_id="world"), fk_link_names=[link, child],
            robot_state=state).pose_stamped]
        print(json.dumps([[p.x, p.y, p.z] for p in found]))
    elif step == "gripper":
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        found = buffer.lookup_transform("world", GRIPPER_LINK, rospy.Time(0),
                                        rospy.Duration(TF_WAIT)).transform.translation
        print(json.dumps([found.x, found.y, found.z]))


if __name__ == "__main__":
    main(*sys.argv[1:])
