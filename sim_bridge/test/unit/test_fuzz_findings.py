"""Inputs the fuzz tier (sim_bridge/test/fuzz) found that ended in another exception than
the reader's documented one, each answered now with SdfError / UrdfError naming the cause."""
import pytest

from sim_bridge import sdf_world
from sim_bridge.sdf_world import SdfError


def _box_model(collision_extra="", visual_extra=""):
    return f"""<sdf version="1.6"><model name="cart"><static>true</static><link name="link">
      <collision name="tray"><geometry><box><size>1 1 1</size></box></geometry>{collision_extra}
      </collision>
      <visual name="tray_visual"><geometry><box><size>1 1 1</size></box></geometry>{visual_extra}
      </visual></link></model></sdf>"""


@pytest.mark.parametrize("mu", [" x", "abc", "nan", "1e999", "1 2"])
def test_sdf_friction_that_is_not_a_number_is_refused_naming_it(mu):
    # was: ValueError: could not convert string to float (a <mu> of ' ' in the fuzz run)
    text = _box_model(collision_extra=f"<surface><friction><ode><mu>{mu}</mu></ode></friction>"
                                      "</surface>")
    with pytest.raises(SdfError) as refused:
        sdf_world.parse_model(text, "cart.sdf")
    message = str(refused.value)
    assert message.startswith("cart.sdf: model 'cart' link 'link' collision 'tray'")
    assert "<mu>" in message and mu.strip() in message


def test_sdf_friction_blank_is_none_and_a_number_is_read():
    blank = _box_model(collision_extra="<surface><friction><ode><mu> </mu></ode></friction>"
                                       "</surface>")
    assert sdf_world.parse_model(blank, "cart.sdf").links[0].collisions[0].friction is None
    given = _box_model(collision_extra="<surface><friction><ode><mu>0.6</mu></ode></friction>"
                                       "</surface>")
    assert sdf_world.parse_model(given, "cart.sdf").links[0].collisions[0].friction == 0.6


@pytest.mark.parametrize("colour", ["abc 0 0 1", "1 nan 0 1", "1 1 1 1e999"])
def test_sdf_material_colour_that_is_not_numbers_is_refused_naming_it(colour):
    # was: ValueError: could not convert string to float: 'abc' (a <diffuse> in the fuzz run)
    text = _box_model(visual_extra=f"<material><diffuse>{colour}</diffuse></material>")
    with pytest.raises(SdfError) as refused:
        sdf_world.parse_model(text, "cart.sdf")
    message = str(refused.value)
    assert message.startswith("cart.sdf: model 'cart' link 'link' visual 'tray_visual'")
    assert "<diffuse>" in message


def test_sdf_material_colours_as_before():
    text = _box_model(visual_extra="<material><diffuse>1 0 0</diffuse>"
                                   "<ambient>0 1 0 1</ambient></material>")
    # three values are no colour: the ambient one is taken, as before
    assert sdf_world.parse_model(text, "cart.sdf").links[0].visuals[0].rgba == (0, 1, 0, 1)
