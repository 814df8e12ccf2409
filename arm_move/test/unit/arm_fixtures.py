"""The arm, its planner and the table scene as the mover builds them, for unit tests."""
import os

import yaml

from arm_move.planner import planner_from_config
from arm_move.scene_config import world_scene

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONFIG = os.path.join(PACKAGE, "config")


def load(name):
    with open(os.path.join(CONFIG, name)) as stream:
        return yaml.safe_load(stream)


def arm_config():
    return load("px100.yaml")


def table_scene():
    """The table, and the RealSense box where the world puts it."""
    return world_scene(load("scene.yaml"))


def planner(**settings):
    values = load("mover.yaml")
    values.update(settings)
    return planner_from_config(arm_config(), values)
