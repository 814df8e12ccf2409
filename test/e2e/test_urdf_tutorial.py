"""urdf_tutorial's display.launch as the URDF tutorials type it.

- ``model:=`` relative to the directory roslaunch is started in (as upstream, where xacro
  runs in roslaunch's working directory), with the sliders' window;
- an absolute ``model:=`` with ``gui:=false``: rviz draws the robot (compared with an empty
  scene), and robot_state_publisher publishes a TF frame for every link;
- a model file that does not exist stops the launch with a message naming it;
- each of the package's own tutorial steps expands as ``model:=urdf/<step>`` from the
  package's folder, and the default model is its first step.
"""
import os
import subprocess
import xml.etree.ElementTree as ElementTree

import pytest
import yaml

import headless

# The test's own robot, in a colour that nothing else on rviz's screen has (the TF axes are
# red, green and blue, the frame names white, the grid grey): a turret on a continuous joint
# (its TF comes from the joint states) and a sensor on a fixed one (from /tf_static).
ROBOT_COLOUR = "#ff00ff"
ROBOT = """<?xml version="1.0"?>
<robot name="tutorial_test_bot">
  <material name="magenta"><color rgba="1 0 1 1"/></material>
  <link name="base_link">
    <visual>
      <geometry><box size="0.6 0.4 0.2"/></geometry>
      <material name="magenta"/>
    </visual>
  </link>
  <link name="turret">
    <visual>
      <geometry><cylinder length="0.15" radius="0.15"/></geometry>
      <material name="magenta"/>
    </visual>
  </link>
  <joint name="turret_joint" type="continuous">
    <parent link="base_link"/>
    <child link="turret"/>
    <origin xyz="0 0 0.175" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
  </joint>
  <link name="sensor">
    <visual>
      <geometry><box size="0.1 0.2 0.08"/></geometry>
      <material name="magenta"/>
    </visual>
  </link>
  <joint name="sensor_joint" type="fixed">
    <parent link="turret"/>
    <child link="sensor"/>
    <origin xyz="0.15 0 0.05" rpy="0 0 0"/>
  </joint>
</robot>
"""
EMPTY = '<?xml version="1.0"?>\n<robot name="empty"><link name="base_link"/></robot>\n'
LINKS = [link.get("name") for link in ElementTree.fromstring(ROBOT.encode()).iter("link")]
RELATIVE_MODEL = os.path.join("robots", "tutorial_test_bot.urdf")
# In the default view the robot covers about 36,000 pixels of the 1024x768 screen, some
# 25,000 of them within 35% of its colour (rviz shades its sides darker); an empty scene
# has none of that colour (rviz's own warnings are orange, its errors red).
ROBOT_PIXELS = 15000
COLOUR_FUZZ = "35%"
ROBOT_COLOUR_PIXELS = 10000
EMPTY_COLOUR_PIXELS = 100

# Waits until every frame given has a transform to the first one; prints those without.
TF_CHECK = """
import sys
import rospy
import tf2_ros
rospy.init_node("urdf_tutorial_tf_check", anonymous=True)
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
root, frames = sys.argv[1], sys.argv[2:]
deadline = rospy.Time.now() + rospy.Duration(20)
missing = frames
while missing and not rospy.is_shutdown() and rospy.Time.now() < deadline:
    missing = [f for f in missing
               if not buffer.can_transform(root, f, rospy.Time(0), rospy.Duration(0.2))]
print("missing: " + " ".join(missing))
sys.exit(1 if missing else 0)
"""


@pytest.fixture
def robot_dir(tmp_path, monkeypatch):
    """A user's folder holding robots/tutorial_test_bot.urdf and empty.urdf, made the
    current directory (roslaunch, started from here, inherits it)."""
    (tmp_path / "robots").mkdir()
    (tmp_path / RELATIVE_MODEL).write_text(ROBOT, encoding="utf-8")
    (tmp_path / "empty.urdf").write_text(EMPTY, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def assert_tf_for_every_link(env):
    result = subprocess.run(["python3", "-c", TF_CHECK, LINKS[0], *LINKS[1:]], env=env,
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, f"no TF frame for some links: {result.stdout}{result.stderr}"


def render(env, results_dir, name, *launch_args, check=None):
    """Starts display.launch, waits for rviz's picture to settle, saves it as <name>.png;
    ``check(launch)`` runs while the launch is still up."""
    path = os.path.join(results_dir, f"{name}.png")

    def picture(launch):
        headless.stable_screenshot(env["DISPLAY"], path, "RViz", launch, timeout=60)
        if check:
            check(launch)
        return path

    return headless.run_while_node_lives(["urdf_tutorial", "display.launch", *launch_args],
                                         env, os.path.join(results_dir, f"{name}.log"), picture)


def test_relative_model_is_read_from_the_current_directory(screen_env, results_dir, robot_dir):
    display = screen_env["DISPLAY"]

    def sliders_and_tf(launch):
        headless.wait_until(lambda: headless.launch_window(display, "Joint State Publisher",
                                                           launch)
                            or not launch.running(), 30, "the sliders' window")
        assert launch.running(), launch.output()[-2000:]
        assert_tf_for_every_link(screen_env)

    # the sliders' window can cover part of rviz, so only the robot's colour is counted
    picture = render(screen_env, results_dir, "relative", f"model:={RELATIVE_MODEL}",
                     check=sliders_and_tf)
    coloured = headless.pixels_near(picture, ROBOT_COLOUR, COLOUR_FUZZ)
    assert coloured > ROBOT_COLOUR_PIXELS, f"only {coloured} pixels in the robot's colour"


def test_absolute_model_without_gui_draws_the_robot(screen_env, results_dir, robot_dir):
    display = screen_env["DISPLAY"]

    def no_sliders_and_tf(launch):
        assert_tf_for_every_link(screen_env)
        assert not headless.window_mapped(display, "Joint State Publisher")

    model = str(robot_dir / RELATIVE_MODEL)
    robot = render(screen_env, results_dir, "absolute", f"model:={model}", "gui:=false",
                   check=no_sliders_and_tf)
    empty = render(screen_env, results_dir, "empty", f"model:={robot_dir / 'empty.urdf'}",
                   "gui:=false")
    differing = headless.differing_pixels(robot, empty)
    assert differing > ROBOT_PIXELS, f"only {differing} pixels show the robot"
    in_colour = headless.pixels_near(robot, ROBOT_COLOUR, COLOUR_FUZZ)
    in_colour_empty = headless.pixels_near(empty, ROBOT_COLOUR, COLOUR_FUZZ)
    assert in_colour_empty < EMPTY_COLOUR_PIXELS, f"{in_colour_empty} in an empty scene"
    assert in_colour > ROBOT_COLOUR_PIXELS, f"only {in_colour} pixels in the robot's colour"


@pytest.mark.parametrize("where", ["relative", "absolute"])
def test_a_missing_model_stops_the_launch_naming_the_file(ros_env, robot_dir, where):
    missing = os.path.join("robots", "no_such_robot.urdf")
    if where == "absolute":
        missing = str(robot_dir / missing)
    result = subprocess.run(
        ["roslaunch", "-p", ros_env["ROS_MASTER_URI"].rsplit(":", 1)[1], "urdf_tutorial",
         "display.launch", f"model:={missing}", "gui:=false"],
        env=ros_env, capture_output=True, text=True, timeout=60, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert f"No such file or directory: {missing}" in output, output[-2000:]


def expanded_description(env, cwd, *launch_args):
    """robot_description as display.launch sets it (``roslaunch --dump-params``: the
    parameters are computed, nothing is started)."""
    result = subprocess.run(["roslaunch", "--dump-params", "urdf_tutorial", "display.launch",
                             *launch_args], env=env, cwd=cwd, capture_output=True, text=True,
                            timeout=60, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    return ElementTree.fromstring(yaml.safe_load(result.stdout)["/robot_description"].encode())


def test_the_default_model_is_the_first_step(ros_env, tmp_path):
    robot = expanded_description(ros_env, tmp_path)
    assert robot.get("name") == "myfirst"
    assert [link.get("name") for link in robot.iter("link")] == ["base_link"]


STEPS_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "compat", "urdf_tutorial", "urdf")


@pytest.mark.parametrize("step", sorted(os.listdir(STEPS_DIR)))
def test_each_step_loads_as_the_tutorial_types_it(ros_env, step):
    """From the package's folder, ``model:=urdf/<step>``: a plain URDF comes through xacro
    unchanged, the xacro step expands to a robot with the links of the step before it."""
    robot = expanded_description(ros_env, os.path.dirname(STEPS_DIR), f"model:=urdf/{step}")
    source = ElementTree.parse(os.path.join(STEPS_DIR, step)).getroot()
    assert robot.get("name") == source.get("name")
    links = [link.get("name") for link in robot.iter("link")]
    if step.endswith(".xacro"):
        physics = ElementTree.parse(os.path.join(STEPS_DIR, "07-physics.urdf")).getroot()
        assert sorted(links) == sorted(link.get("name") for link in physics.iter("link"))
    else:
        assert links == [link.get("name") for link in source.iter("link")]
