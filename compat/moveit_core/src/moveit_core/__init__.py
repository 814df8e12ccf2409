"""MoveIt's core in Python: the robot model of a URDF and its SRDF (see robot_model, srdf)."""
