"""gazebo_ros's gzserver, gazebo and debug node types: Gazebo's command line, run by sim_bridge.

Launch files start the simulator as ``<node pkg="gazebo_ros" type="gzserver" args="-u -e ode
worlds/empty.world"/>`` (empty_world.launch does). This reads that command line as gzserver
does and hands what it means to sim_bridge's node:

  -u, --pause             start with physics paused
  --verbose               log what the simulator loads (each world model, each plugin with
                          the parameters it runs with), as gzserver --verbose does
  -e, --physics ENGINE    accepted: sim_bridge simulates with Bullet whatever is asked
  -r, --record, --record_path, --record_encoding, --record_period, --record_filter
                          accepted; Gazebo's log recording is not emulated (one warning)
  -s, --server-plugin PLUGIN
                          a Gazebo system plugin, loaded (sim_bridge.native_plugins) before
                          the world, given gzserver's command line; gazebo_ros's own
                          (libgazebo_ros_*.so: the API and paths plugins) are what sim_bridge
                          is, and are not loaded
  -g, --gui-plugin PLUGIN accepted: there is no Gazebo GUI to load it into
  --seed N                seed of the simulated noise (a whole number >= 0)
  WORLD                   the world file (relative names are looked up in the current folder,
                          then GAZEBO_RESOURCE_PATH, which includes this package's worlds)

Other options are reported once and ignored; the last word that is not an option is the
world, as for gzserver.

Values are checked where sim_bridge reads its parameters (node_params): a bad ``--seed``
is named as the option (``gzserver --seed: 'abc' is not a whole number; ...``), a bad
private parameter as the parameter, and the simulator stops with that one line.
empty_world.launch hands ``real_time_factor``, ``seed``, ``paused`` and ``gui`` over as
private parameters (roslaunch leaves ``1e9``, ``nan`` and ``maybe`` as text; the reader
converts or refuses them), so each is named as the user typed it.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
from typing import Any, Dict, List, Optional, Tuple

import rospkg
import rospy
from node_params import Given

# Options that take a value and mean nothing here.
IGNORED_WITH_VALUE = ("-g", "--gui-plugin", "--record_path",
                      "--record_encoding", "--record_period", "--record_filter", "--iters",
                      "-o", "--profile")
# gazebo_ros's own system plugins (libgazebo_ros_api_plugin.so, libgazebo_ros_paths_plugin.so),
# which sim_bridge is
GAZEBO_ROS_PLUGINS = "libgazebo_ros_"
IGNORED_FLAGS = ("-q", "--quiet", "--lockstep", "--minimal_comms", "--play")


def parse_command_line(argv: List[str]) -> Tuple[Dict[str, Any], List[str]]:
    """(overrides for sim_bridge's Config, notes for the log)."""
    parser = argparse.ArgumentParser(prog="gzserver", add_help=False)
    parser.add_argument("-u", "--pause", action="store_true")
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("-e", "--physics", default="ode")
    parser.add_argument("--seed")  # checked by sim_bridge's reader, named as the option
    parser.add_argument("-r", "--record", action="store_true")
    parser.add_argument("-s", "--server-plugin", action="append", default=[])
    for flag in IGNORED_FLAGS:
        parser.add_argument(flag, action="store_true")
    for option in IGNORED_WITH_VALUE:
        parser.add_argument(option, action="append", default=[])
    args, rest = parser.parse_known_args(argv)
    overrides: Dict[str, Any] = {}
    notes: List[str] = []
    words = [word for word in rest if word]
    worlds = [word for word in words if not word.startswith("-")]
    unknown = [word for word in words if word.startswith("-")]
    if worlds:
        overrides["world_name"] = worlds[-1]
    if args.pause:
        overrides["paused"] = True
    if args.verbose:
        overrides["verbose"] = True
    if args.seed is not None:
        overrides["seed"] = Given(args.seed, "gzserver --seed")
    system_plugins = [name for name in args.server_plugin
                      if not os.path.basename(name).startswith(GAZEBO_ROS_PLUGINS)]
    if system_plugins:
        overrides["system_plugins"] = (system_plugins, ["gzserver", *argv])
    if args.record or args.record_path:
        notes.append("recording a Gazebo log (-r) is not emulated; the run is not recorded")
    if args.physics not in ("ode", "bullet"):
        notes.append(f"physics engine '{args.physics}' asked for; sim_bridge simulates with "
                     "Bullet")
    if unknown:
        notes.append(f"ignored gzserver options: {' '.join(unknown)}")
    return overrides, notes


def _extend_path(variable: str, folders: List[str]) -> None:
    paths = [p for p in os.environ.get(variable, "").split(os.pathsep) if p]
    paths += [folder for folder in folders if folder not in paths]
    os.environ[variable] = os.pathsep.join(paths)


def exported_paths(attribute: str) -> List[str]:
    """What packages export to gazebo_ros, as gazebo_ros's paths plugin reads it:
    ``<export><gazebo_ros gazebo_model_path="${prefix}/models"/></export>``."""
    try:
        listed = subprocess.run(["rospack", "plugins", f"--attrib={attribute}", "gazebo_ros"],
                                capture_output=True, text=True, timeout=60, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return []
    folders = []
    for line in listed.stdout.splitlines():
        _package, _, folder = line.partition(" ")
        folders.extend(f for f in folder.strip().split(os.pathsep) if f)
    return folders


def add_search_paths() -> None:
    """Gazebo's search paths as gazebo_ros sets them: this package's share folder on
    GAZEBO_RESOURCE_PATH (as Gazebo's setup.sh puts /usr/share/gazebo-11 there, so that
    ``worlds/empty.world`` resolves), and what packages export as gazebo_model_path and
    gazebo_media_path."""
    here = rospkg.RosPack().get_path("gazebo_ros")
    _extend_path("GAZEBO_RESOURCE_PATH", [here] + exported_paths("gazebo_media_path"))
    _extend_path("GAZEBO_MODEL_PATH", exported_paths("gazebo_model_path"))


def main(argv: Optional[List[str]] = None, gui: Optional[bool] = None) -> None:
    """gzserver (``gui`` None: the ``~gui`` parameter decides) or gazebo (``gui`` True)."""
    from sim_bridge import ros_node  # the engine; imported late so --help stays fast

    overrides, notes = parse_command_line(
        rospy.myargv(argv if argv is not None else sys.argv)[1:])
    if gui is not None:
        overrides["gui"] = gui
    add_search_paths()
    for note in notes:
        print(f"gzserver: {note}", file=sys.stderr)
    ros_node.main(overrides)
