"""Interbotix's common Python helpers (interbotix_ros_toolboxes noetic af96d28,
``interbotix_common_toolbox/interbotix_common_modules``), as far as its arm modules use them."""
