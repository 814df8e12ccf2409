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


LONG_NAME_ROBOT = """<robot name="{name}"><link name="base_link"><inertial><mass value="1"/>
  <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link></robot>"""


def test_pybullet_is_given_a_short_robot_name():
    from sim_bridge.gazebo_tags import read_gazebo_tags
    from sim_bridge.robot_body import PYBULLET_ROBOT_NAME, prepare_urdf
    from urdf_tools.model import parse_urdf
    text = LONG_NAME_ROBOT.format(name="n" * 100000)
    model = parse_urdf(text, "long.urdf")
    prepared = prepare_urdf(text, model, read_gazebo_tags(model), lambda warning: None)
    assert f'<robot name="{PYBULLET_ROBOT_NAME}">' in prepared


def test_a_robot_with_a_100000_character_name_spawns():
    # was: pybullet's URDF importer died with SIGSEGV (a robot name of 42,184 characters or
    # more), taking the simulator with it; run in a child process so that a regression is a
    # failure, not a crash of the test run
    import subprocess
    import sys
    import textwrap
    script = textwrap.dedent(f"""
        import sys
        sys.path.insert(0, {repr(__import__('os').path.dirname(__file__))})
        from recording_bus import RecordingBus
        from sim_bridge.world import World
        world = World(RecordingBus(), ray_threads=1)
        text = {LONG_NAME_ROBOT!r}.format(name="n" * 100000)
        world.spawn_urdf("long", text, (0, 0, 0.5))
        world.step()
        print("spawned", sorted(world.models))
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, (done.returncode, done.stderr[-2000:])
    assert "spawned ['long']" in done.stdout


def test_a_gazebo_value_that_is_not_finite_is_refused_naming_it():
    """Found by the fuzz tier: <mu1>nan</mu1> was accepted and the robot's pose became
    non-finite within ten steps."""
    from sim_bridge.gazebo_tags import read_gazebo_tags
    from urdf_tools.model import UrdfError, parse_urdf
    robot = parse_urdf("""<robot name="r"><link name="base"><inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
      <gazebo reference="base"><mu1>nan</mu1></gazebo></robot>""", "test robot")
    with pytest.raises(UrdfError, match=r"<mu1> 'nan' is not a finite number"):
        read_gazebo_tags(robot)


def test_an_sdf_model_placed_at_a_position_that_is_not_finite_is_refused(world):
    """Found by the fuzz tier: World.add_sdf_model took a NaN or 1e300 position as given."""
    from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
    from sim_bridge.world import SimError
    box = ModelSpec("box", False, links=[LinkSpec("link", collisions=[ShapeSpec("box", size=(1, 1, 1))])])
    with pytest.raises(SimError, match="the position"):
        world.add_sdf_model(box, (float("nan"), 0.0, 0.0))
    assert "box" not in world.models
