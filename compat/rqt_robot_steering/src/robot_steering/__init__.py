"""rqt_robot_steering's window without rqt.

- :mod:`robot_steering.steering`: the pure logic (settings, slider positions, Twists, when to
  publish), no Qt and no master;
- :mod:`robot_steering.widget`: the Qt window, no rospy;
- :mod:`robot_steering.node`: the ROS node that joins them (``rosrun rqt_robot_steering
  rqt_robot_steering``).
"""
