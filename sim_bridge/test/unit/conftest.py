"""Fixtures for sim_bridge's unit tests: a World on pybullet.DIRECT with a recording bus."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from recording_bus import RecordingBus  # noqa: E402
from world_fixtures import DATA  # noqa: E402

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec  # noqa: E402
from sim_bridge.world import World  # noqa: E402
from urdf_tools.xacro_loader import expand  # noqa: E402


@pytest.fixture
def bus():
    return RecordingBus()


@pytest.fixture
def world(bus):
    simulated = World(bus, ray_threads=1)
    simulated.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    yield simulated
    simulated.close()


@pytest.fixture
def diff_bot_xml():
    def make(**arguments):
        return expand(os.path.join(DATA, "diff_bot.urdf.xacro"), arguments)
    return make
