"""The px100's MoveIt with rviz on a user's config (test/fixtures/rviz/px100_planning.rviz):
a plan from moveit_commander is animated by the Trajectory display (looping, in its Robot
Color: two screenshots at different times differ where the arm moves), and the
MotionPlanning panel's Plan and Execute, pressed through MoveIt's remote-control topics,
move the fake arm to a named goal state (/joint_states reaches it) and to where the goal
marker was dragged (the display's compute_ik call: the gripper, by TF, within 5 mm of the
marker); the panel's Scene
Objects tab, clicked with xdotool, adds its box, drawn in the display's default Scene Color
where the box's default pose projects; the RobotState display draws a DisplayRobotState
with its highlighted link in the highlight's colour where the link projects, after one
whose joint is NaN was refused (rviz keeps running and says why in the display's status)."""
import json
import os
import subprocess
import sys

import numpy as np

import headless
import rviz_view

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURE = os.path.join(os.path.dirname(HERE), "fixtures", "rviz")
PATH_PIXELS = 150        # the path robot in its colour: about 1000-3000 pixels in this view
MOVING_PIXELS = 100      # path-robot pixels that change between two moments of the animation
SCREEN_WAIT = 30.0       # s
MARKER_JOINTS = (0.4, -0.3, 0.2, 0.5)   # rad: waist, shoulder, elbow, wrist_angle; the marker
                                        # is dragged to the gripper's pose there
MARKER_TOLERANCE = 0.005                # m
SHOWN_STATE = (0.8, 0.8, 0.0, 0.0)      # rad: the DisplayRobotState's arm turned towards the
                                        # view's camera and leaning to it: nearer than the
                                        # other robots, none hides it
HIGHLIGHTED_LINK = "px100/upper_arm_link"
LINK_RADIUS = 20                        # px around the link's projected middle
LINK_PIXELS = 100                       # highlighted pixels there at least
# the panel's widgets in px100_planning.rviz's window (1024 x 768, the panel docked on the
# left as rviz places an associated widget): the Scene Objects tab, its Add Box button
SCENE_OBJECTS_TAB = (139, 99)
ADD_BOX_BUTTON = (210, 198)
PANEL_BOX = (0.3, 0.0, 0.05)   # m: the Scene Objects tab's default box position
BOX_RADIUS = 20                # px around the box's projected centre
BOX_SHARE = 0.6                # of those pixels in the scene colour


def scene_green(red, green, blue):
    # PlanningSceneDisplay's default Scene Color, 50; 230; 50 at alpha 0.9, lit
    return (green > 120) & (green > red + 60) & (green > blue + 60)


def highlight_yellow(red, green, blue):
    # the highlight's 1, 1, 0, lit; the goal state's orange has about half the green
    return (red > 150) & (green > 150) & (blue < 80)


def click(env, point):
    subprocess.run(["xdotool", "mousemove", str(point[0]), str(point[1]), "click", "1"],
                   env=env, check=True, timeout=20)


def path_cyan(red, green, blue):
    # the Trajectory display's Robot Color, 0; 220; 220, lit (no other display draws cyan:
    # the goal marker's rings are red, green and blue)
    return (green > 100) & (blue > 100) & (green > red + 60) & (blue > red + 60) \
        & (abs(green - blue) < 40)


def run(env, script, *arguments):
    done = subprocess.run([sys.executable, os.path.join(HERE, script), *arguments], env=env,
                          capture_output=True, text=True, timeout=150, check=False)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-3000:]
    return done.stdout


def test_paths_animate_and_the_panel_plans_and_executes(screen_env, results_dir):
    display = screen_env["DISPLAY"]
    figures = {}

    def scenario(launch):
        headless.wait_until(lambda: "You can start planning now!" in launch.output()
                            or not launch.running(), 90, "move_group")
        idle_path = os.path.join(results_dir, "idle.png")
        headless.stable_screenshot(display, idle_path, "RViz", launch)
        idle = rviz_view.image(idle_path)
        rect = rviz_view.view_rect(idle)
        figures["path_pixels_before"] = int(rviz_view.mask(idle, path_cyan, rect).sum())

        run(screen_env, "moveit_scene_steps.py", "plan", "Upright")

        def moment(name):
            picture = rviz_view.image(headless.screenshot(
                display, os.path.join(results_dir, name + ".png")))
            return rviz_view.mask(picture, path_cyan, rect)

        first = headless.wait_until(lambda: [m for m in [moment("animation_1")]
                                             if m.sum() > PATH_PIXELS], SCREEN_WAIT,
                                    "the planned path drawn")[0]

        def moved():
            later = moment("animation_2")
            return [later] if later.sum() > PATH_PIXELS and (later ^ first).sum() \
                > MOVING_PIXELS else None
        second = headless.wait_until(moved, SCREEN_WAIT, "the path robot to move")[0]
        figures["path_pixels"] = [int(first.sum()), int(second.sum())]
        figures["path_pixels_changed"] = int((first ^ second).sum())

        figures["reached"] = json.loads(run(screen_env, "rviz_remote_control.py", "Sleep"))
        figures["marker"] = json.loads(run(screen_env, "rviz_remote_control.py", "--marker",
                                           *map(str, MARKER_JOINTS)))

        run(screen_env, "moveit_scene_steps.py", "show_broken")
        ends = json.loads(run(screen_env, "moveit_scene_steps.py", "show", HIGHLIGHTED_LINK,
                              *map(str, SHOWN_STATE)))
        link_pixel = rviz_view.OrbitView(os.path.join(FIXTURE, "px100_planning.rviz")).project(
            np.mean(ends, axis=0), rect)

        def highlighted():
            picture = rviz_view.image(headless.screenshot(
                display, os.path.join(results_dir, "robot_state.png")))
            yellow = rviz_view.mask(picture, highlight_yellow, rect)
            rows, columns = np.nonzero(yellow)
            figures["highlight_near_link"] = int(np.sum(
                np.hypot(columns - link_pixel[0], rows - link_pixel[1]) < LINK_RADIUS))
            return figures["highlight_near_link"] > LINK_PIXELS
        headless.wait_until(highlighted, SCREEN_WAIT, "the highlighted link drawn", 0.5)

        click(screen_env, SCENE_OBJECTS_TAB)
        click(screen_env, ADD_BOX_BUTTON)
        box = rviz_view.OrbitView(os.path.join(FIXTURE, "px100_planning.rviz")).project(
            PANEL_BOX, rect)

        def box_drawn():
            picture = rviz_view.image(headless.screenshot(
                display, os.path.join(results_dir, "panel_box.png")))
            figures["panel_box"] = rviz_view.share_near(
                rviz_view.mask(picture, scene_green, rect), box, BOX_RADIUS)
            return figures["panel_box"] > BOX_SHARE
        headless.wait_until(box_drawn, SCREEN_WAIT, "the panel's box drawn", 0.5)
        assert launch.running(), launch.output()[-3000:]
        return launch.output()

    output = headless.run_while_node_lives(
        [os.path.join(FIXTURE, "px100_planning.launch")], screen_env,
        os.path.join(results_dir, "px100_planning.log"), scenario)
    with open(os.path.join(results_dir, "figures.json"), "w", encoding="utf-8") as stream:
        json.dump(figures, stream, indent=1)
    assert "PluginlibFactory" not in output and "failed to load" not in output, output[-3000:]
    assert figures["path_pixels_before"] < 10, figures
    assert figures["path_pixels_changed"] > MOVING_PIXELS, figures
    assert np.linalg.norm(np.subtract(figures["marker"]["wanted"],
                                      figures["marker"]["reached"])) < MARKER_TOLERANCE, figures
