"""gazebo_ros's names over sim_bridge: the gzserver/gazebo/gzclient node types, spawn_model."""
