"""gzserver's command line (gazebo_ros.server.parse_command_line): -s/--server-plugin names
Gazebo system plugins for sim_bridge to load before the world, with the command line they
are given (gazebo 11's Server.cc:282-290); gazebo_ros's own system plugins are sim_bridge
itself and are not loaded; -g (GUI plugins) is accepted and ignored."""
from gazebo_ros.server import parse_command_line


def test_server_plugins_are_loaded_with_the_command_line_but_gazebo_ros_own():
    argv = ["-u", "-s", "libgazebo_ros_paths_plugin.so", "-s", "libsystem_push.so",
            "--server-plugin", "/opt/plugins/librecorder.so", "-s",
            "libgazebo_ros_api_plugin.so", "-g", "libgui_overlay.so", "-e", "ode",
            "worlds/empty.world"]
    overrides, notes = parse_command_line(argv)
    plugins, given = overrides["system_plugins"]
    assert plugins == ["libsystem_push.so", "/opt/plugins/librecorder.so"]
    assert given == ["gzserver", *argv]
    assert overrides["world_name"] == "worlds/empty.world" and overrides["paused"]
    assert notes == []


def test_gazebo_ros_own_plugins_alone_load_nothing():
    overrides, _ = parse_command_line(["-s", "libgazebo_ros_api_plugin.so",
                                       "-s", "libgazebo_ros_paths_plugin.so"])
    assert "system_plugins" not in overrides
