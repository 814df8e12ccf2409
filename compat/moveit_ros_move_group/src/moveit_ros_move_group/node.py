"""The ``move_group`` node: reads what a MoveIt config package loads, then serves MoveIt's
interfaces in its namespace (``compute_fk``, ``compute_ik``) and follows ``joint_states``.

This version holds the kinematics capability; planning, the planning scene and execution
come next (issue 22). A parameter it cannot do without (``robot_description``,
``robot_description_semantic``) stops it with a message naming what to load."""
from __future__ import annotations

import sys

import rospy
from moveit_msgs.srv import GetPositionFK, GetPositionIK
from sensor_msgs.msg import JointState

from moveit_ros_move_group import kinematics_service
from moveit_ros_move_group.context import ContextError, from_parameters


def main() -> int:
    rospy.init_node("move_group")
    try:
        context = from_parameters(rospy.get_param)
    except ContextError as error:
        rospy.logfatal("move_group cannot start: %s", error)
        return 1
    rospy.Subscriber("joint_states", JointState, context.state.update, queue_size=10)
    # each handler answers every request: a bad one gets its MoveIt error code
    services = [
        rospy.Service("compute_fk", GetPositionFK,
                      lambda request: kinematics_service.compute_fk(context, request)),
        rospy.Service("compute_ik", GetPositionIK,
                      lambda request: kinematics_service.compute_ik(context, request)),
    ]
    model = context.model
    rospy.loginfo("move_group: robot '%s', model frame '%s', groups %s; serving %s",
                  model.name, model.model_frame, ", ".join(model.groups) or "none",
                  ", ".join(s.resolved_name for s in services))
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
