"""``xs_sdk``, the driver of the real arm, stands here for what it cannot do: Interbotix's
C++ driver writes to Dynamixel servos through the Dynamixel Workbench on the motor config's
``port`` (``/dev/ttyDXL``), and neither is on this machine. It stops with a message saying
so and what to run instead, as the real one stops when it finds no motors
(``xs_sdk_obj.cpp``: "Failed to find all motors ... Shutting down...")."""
import sys

import rospy


def main() -> None:
    rospy.init_node("xs_sdk")
    rospy.logfatal("[xs_sdk] the driver for the real arm (Dynamixel servos on %s) is not in "
                   "this workspace. Run xsarm_control.launch with use_sim:=true for "
                   "Interbotix's simulated driver (xs_sdk_sim). Shutting down...",
                   rospy.get_param("~port", "/dev/ttyDXL"))
    sys.exit(1)
