"""gazebo_ros's gzclient node type: Gazebo's window.

sim_bridge draws its own window (pybullet's) from inside the simulator when ``gui`` is true and
a display answers, so the client has nothing to draw: it says so once and stays up until the
launch ends, so that ``required="true"`` on it (gui_required) behaves as with Gazebo."""
from __future__ import annotations

import rospy


def main() -> None:
    rospy.init_node("gazebo_gui", anonymous=True)
    rospy.loginfo("gzclient: sim_bridge shows the world in its own window when the simulator "
                  "has gui:=true and a display; watch the robot in rviz otherwise")
    rospy.spin()
