#!/usr/bin/env python3
"""The speed limits served from Python (dynamic_reconfigure.server with the SpeedLimit config
generated from cfg/SpeedLimit.cfg), as a robot's Python driver serves its own; the limits in
force are published, latched, on ~max_speed."""
import rospy
from dynamic_reconfigure.server import Server
from std_msgs.msg import Float64

from limo_style_deps.cfg import SpeedLimitConfig


def main():
    rospy.init_node("speed_limit_server")
    publisher = rospy.Publisher("~max_speed", Float64, queue_size=1, latch=True)

    def on_change(config, level):
        publisher.publish(Float64(config.max_speed if config.enabled else 0.0))
        return config

    Server(SpeedLimitConfig, on_change)
    rospy.spin()


if __name__ == "__main__":
    main()
