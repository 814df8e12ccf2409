"""The arm, its planner and the table scene as the mover builds them, for unit tests."""
import os

import yaml

from arm_move.collision import ArmCollisionModel, Box, Scene
from arm_move.kinematics import ArmKinematics
from arm_move.planner import ArmPlanner, PlannerSettings

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONFIG = os.path.join(PACKAGE, "config")


def load(name):
    with open(os.path.join(CONFIG, name)) as stream:
        return yaml.safe_load(stream)


def arm_config():
    return load("px100.yaml")


def table_scene():
    scene_config = load("scene.yaml")
    scene = Scene(floor_z=-scene_config["table_height"])
    table = scene_config["table"]
    scene.add(Box.axis_aligned("table", table["center"], table["size"]))
    box = scene_config["realsense_box"]
    scene.add(Box.axis_aligned("realsense_box", box["position"], box["size"], box["yaw"]))
    return scene


def planner(padding=None, **settings):
    config = arm_config()
    mover = load("mover.yaml")
    kinematics = ArmKinematics.from_config(config)
    model = ArmCollisionModel(kinematics, config["links"], config["finger"],
                              mover["collision_padding"] if padding is None else padding,
                              config["self_collision_pairs"])
    values = {k: v for k, v in mover.items() if k in PlannerSettings.__dataclass_fields__}
    values.update(settings)
    return ArmPlanner(kinematics, model, PlannerSettings(**values))
