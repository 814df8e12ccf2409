"""turtlesim 0.10.2 (ROS noetic) in Python, under the package name turtlesim.

The module is not called turtlesim: that is the generated messages' package
(``from turtlesim.msg import Pose``), which a module of the same name would hide.

- :mod:`turtle_world.turtle`: one turtle's motion, pen and teleports (no Qt, no ROS);
- :mod:`turtle_world.world`: the window's size, the turtles by name, spawn naming, reset,
  the update clock, the background parameters (no Qt, no master);
- :mod:`turtle_world.canvas`: the TurtleSim window and the drawn turtles (Qt, no rospy);
- :mod:`turtle_world.node`: ``turtlesim_node``, joining them to ROS;
- :mod:`turtle_world.teleop_keys`, :mod:`turtle_world.teleop_node`: ``turtle_teleop_key``;
- :mod:`turtle_world.mimic`: ``mimic``; :mod:`turtle_world.draw_square`: ``draw_square``.
"""
