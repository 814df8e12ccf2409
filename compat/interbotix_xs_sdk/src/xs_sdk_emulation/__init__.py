"""Interbotix's X-series driver (``interbotix_xs_sdk``) without motors: the motor and mode
configs, the gripper's linkage, and ``xs_sdk_sim``'s joints, as Interbotix's own simulated
driver moves them (interbotix_ros_core noetic 172841f,
``interbotix_ros_xseries/interbotix_xs_sdk/scripts/xs_sdk_sim``)."""
