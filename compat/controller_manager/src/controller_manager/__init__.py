"""controller_manager's command-line tools (spawner, controller_manager) for the emulated
ros_control of sim_bridge: they call the services under ``<namespace>/controller_manager/``."""
