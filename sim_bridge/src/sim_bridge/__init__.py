"""sim_bridge: a Gazebo-compatible simulator for ROS 1 on pybullet.

The physics core (world, description readers, plugins) imports no rospy and runs under
``pybullet.DIRECT`` in unit tests; :mod:`sim_bridge.ros_node` is the ROS adapter.
"""
