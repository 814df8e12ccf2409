"""Helpers for sim_bridge's unit tests (imported by conftest.py and the tests)."""
import os

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def run(world, seconds):
    """Steps the world for ``seconds`` of simulated time."""
    for _ in range(int(round(seconds / world.step_size))):
        world.step()
