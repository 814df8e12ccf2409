"""Interbotix's Python API for its X-series arms (interbotix_ros_toolboxes noetic af96d28,
``interbotix_xs_toolbox/interbotix_xs_modules``): ``core`` (the driver's services and
topics), ``arm`` (``InterbotixManipulatorXS``: joint and end-effector poses solved with
Modern Robotics' product of exponentials), ``gripper``, ``mr_descriptions``."""
