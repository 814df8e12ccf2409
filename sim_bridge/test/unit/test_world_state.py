"""A world saved from Gazebo places its models in <state>, as Gazebo applies it at load."""
import math

import pytest

from sim_bridge.sdf_world import SdfError, load_world

WORLD = """<sdf version="1.6"><world name="default">
  <model name="barrier"><static>true</static><pose>0.42 0 0 0 0 0</pose>
    <link name="link"><collision name="c"><geometry><box><size>2 0.3 1</size></box></geometry></collision></link></model>
  <model name="crate"><pose>5 5 0 0 0 0</pose>
    <link name="link"><collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision></link></model>
  <state world_name="default">
    <sim_time>12 0</sim_time>
    <model name="barrier"><pose>-3 2 0 0 0 2.36</pose><link name="link"><pose>-3 2 0 0 0 2.36</pose></link></model>
    <model name="gone"><pose>1 1 1 0 0 0</pose></model>
  </state>
</world></sdf>"""


def test_the_state_block_places_the_models_it_names(tmp_path):
    path = tmp_path / "saved.world"
    path.write_text(WORLD)
    models = {model.name: model for model in load_world(str(path)).models}
    assert models["barrier"].pose == pytest.approx((-3, 2, 0, 0, 0, 2.36))
    assert models["crate"].pose == pytest.approx((5, 5, 0, 0, 0, 0))  # not in the state
    assert "gone" not in models


def test_a_state_pose_that_is_not_numbers_is_refused_naming_it(tmp_path):
    path = tmp_path / "bad.world"
    path.write_text(WORLD.replace("-3 2 0 0 0 2.36</pose><link", "-3 two 0 0 0 2.36</pose><link"))
    with pytest.raises(SdfError, match="<state> model 'barrier'"):
        load_world(str(path))
