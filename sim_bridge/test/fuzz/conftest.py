"""The fuzz tier's set-up for sim_bridge: urdf_tools' fuzz strategies (urdf_tools/test/fuzz,
on sys.path), Hypothesis' profiles, and the spawn worker (spawn_worker.py) shared by the
spawn tests of one pytest run."""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "urdf_tools", "test", "fuzz"))
from description_fuzz import register_profiles  # noqa: E402
from spawn_client import SpawnClient  # noqa: E402

register_profiles()


@pytest.fixture(scope="session")
def spawner():
    client = SpawnClient()
    yield client
    client.close()
