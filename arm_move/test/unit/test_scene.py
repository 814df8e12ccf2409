"""arm_move's scene: the world file puts the table, the RealSense box and the block where
config/scene.yaml (the mover's planning scene) has them; where the box may be put."""
import math
import os
import xml.etree.ElementTree as ET

import pytest
import yaml

from arm_move.scene import placement_problem, yaw_quaternion

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@pytest.fixture(scope="module")
def config():
    with open(os.path.join(PACKAGE, "config", "scene.yaml"), encoding="utf-8") as stream:
        return yaml.safe_load(stream)


def test_the_world_holds_the_scene(config):
    world = ET.parse(os.path.join(PACKAGE, "worlds", "arm_box.world")).getroot()
    models = {m.get("name"): m for m in world.iter("model")}
    pose = {name: [float(v) for v in m.find("pose").text.split()] for name, m in models.items()}
    size = {name: [float(v) for v in m.find("link/collision/geometry/box/size").text.split()]
            for name, m in models.items()}
    assert pose["table"][:3] == config["table"]["center"]
    assert size["table"] == config["table"]["size"]
    box = config["realsense_box"]
    assert pose["realsense_box"][:3] == box["position"] and pose["realsense_box"][5] == box["yaw"]
    assert size["realsense_box"] == box["size"]
    block = config["pick_object"]
    # the world's block stands on the table; the scene's floats table_clearance above it
    assert pose["pick_object"][:2] == block["position"][:2]
    assert pose["pick_object"][2] == pytest.approx(block["size"][2] / 2)
    assert block["position"][2] - block["size"][2] / 2 == pytest.approx(config["table_clearance"])
    assert pose["pick_object"][5] == block["yaw"]
    assert size["pick_object"] == block["size"]
    ground = [i for i in world.iter("include") if "ground_plane" in i.find("uri").text][0]
    assert float(ground.find("pose").text.split()[2]) == -config["table_height"]


@pytest.mark.parametrize("position, yaw, problem", [
    ((0.16, -0.17, 0.025), 0.0, None),                # resting on the table
    ((0.16, -0.17, 0.0245), 0.4, None),               # sunk in by less than the tolerance
    ((0.16, -0.17, -0.1), 0.0, "table"),
    ((0.9, 0.0, -0.76), 0.0, "floor"),
    ((0.9, 0.0, -0.72), 0.0, None),                   # beside the table, above the floor
    ((0.15, 0.09, 0.03), 0.0, "pick_object"),
    ((0.16, -0.17, 0.025), math.pi / 2, None),
])
def test_where_the_box_may_be_put(config, position, yaw, problem):
    block = config["pick_object"]
    others = {"pick_object": (block["position"], block["size"])}
    assert placement_problem(config, position, yaw_quaternion(yaw), others) == problem
