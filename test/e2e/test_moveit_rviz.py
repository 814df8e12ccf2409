"""xsarm_moveit.launch (the px100, fake controllers) with its own rviz config: the
MotionPlanning display (moveit_ros_visualization's C++ plugin) draws the planning scene.
A box added by PlanningSceneInterface.add_box appears in the picture where its pose projects
under the saved view, and goes when removed; an upright cylinder (a shape's z axis is rviz's
y) is drawn between the projections of its two ends; a box attached to the gripper is drawn in the
attached-body colour on the gripper, and moves with it when the arm moves. rviz's log names
no plugin it could not load."""
import json
import os
import subprocess
import sys

import numpy as np

import headless
import rviz_view

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONFIG = os.path.join(REPO, "compat", "interbotix_xsarm_moveit", "launch", "moveit.rviz")
STEPS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "moveit_scene_steps.py")
BOX = (0.22, -0.12, 0.03)     # m, in the world: in front of the arm, clear of it
BOX_SIZE = 0.06               # m
HELD_SIZE = 0.04              # m, the attached cube
POLE = (0.22, -0.12, 0.1)     # m: an upright cylinder's centre, where the box was
POLE_HEIGHT = 0.2             # m
POLE_RADIUS = 0.01            # m
DRAWN_PIXELS = 150            # a 4-6 cm cube in this view covers about 400-900 pixels
GONE_PIXELS = 10
WHERE_PIXELS = 25             # px between a drawn object's centroid and its projected centre
MOVED_PIXELS = 30             # px the held box moves from Home to Sleep at least
SCREEN_WAIT = 30.0            # s for rviz to show a change


def scene_green(red, green, blue):
    # the display's Scene Color, 50; 230; 50 at alpha 0.9, lit: green well above red and blue
    return (green > 120) & (green > red + 60) & (green > blue + 60)


def attached_purple(red, green, blue):
    # the Attached Body Color, 150; 50; 150, lit
    return (red > 70) & (blue > 70) & (red > green + 40) & (blue > green + 40)


def step(env, *arguments):
    done = subprocess.run([sys.executable, STEPS, *arguments], env=env, capture_output=True,
                          text=True, timeout=90, check=False)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-3000:]
    return done.stdout


def test_the_planning_scene_is_drawn_where_it_is(screen_env, results_dir):
    view = rviz_view.OrbitView(CONFIG)
    display = screen_env["DISPLAY"]
    figures = {}

    def shot(name):
        return headless.screenshot(display, os.path.join(results_dir, name + ".png"))

    def wait_for(name, condition, what):
        def seen():
            picture = rviz_view.image(shot(name))
            return [picture] if condition(picture) else None
        return headless.wait_until(seen, SCREEN_WAIT, what, 0.5)[0]

    def scenario(launch):
        headless.wait_until(lambda: "You can start planning now!" in launch.output()
                            or not launch.running(), 90, "move_group")
        headless.stable_screenshot(display, os.path.join(results_dir, "empty.png"), "RViz",
                                   launch)
        empty = rviz_view.image(os.path.join(results_dir, "empty.png"))
        rect = rviz_view.view_rect(empty)
        figures["view"] = rect
        figures["green_before"] = int(rviz_view.mask(empty, scene_green, rect).sum())
        assert figures["green_before"] < GONE_PIXELS, figures

        step(screen_env, "add", "box", *map(str, BOX), str(BOX_SIZE))
        added = wait_for("box_added", lambda p: rviz_view.mask(p, scene_green, rect).sum()
                         > DRAWN_PIXELS, "the box in the scene colour")
        green = rviz_view.mask(added, scene_green, rect)
        figures["green_added"] = int(green.sum())
        figures["box_centroid"] = rviz_view.centroid(green)
        figures["box_projected"] = view.project(BOX, rect)

        step(screen_env, "remove", "box")
        removed = wait_for("box_removed", lambda p: rviz_view.mask(p, scene_green, rect).sum()
                           < GONE_PIXELS, "the box to go")
        figures["green_removed"] = int(rviz_view.mask(removed, scene_green, rect).sum())

        step(screen_env, "cylinder", "pole", *map(str, POLE), str(POLE_HEIGHT),
             str(POLE_RADIUS))
        pole = wait_for("pole", lambda p: rviz_view.mask(p, scene_green, rect).sum()
                        > DRAWN_PIXELS, "the cylinder in the scene colour")
        rows = np.nonzero(rviz_view.mask(pole, scene_green, rect).any(axis=1))[0]
        ends = [view.project(np.add(POLE, (0, 0, dz)), rect)[1]
                for dz in (-POLE_HEIGHT / 2, POLE_HEIGHT / 2)]
        figures["pole_rows"] = [int(rows.min()), int(rows.max())]
        figures["pole_ends_projected"] = sorted(ends)
        step(screen_env, "remove", "pole")

        step(screen_env, "attach", "held", str(HELD_SIZE))
        for pose in ("Home", "Sleep"):
            step(screen_env, "go", pose)
            gripper = json.loads(step(screen_env, "gripper"))
            held = wait_for(f"held_{pose}", lambda p: rviz_view.mask(p, attached_purple, rect).sum()
                            > DRAWN_PIXELS, f"the held box at {pose}")
            figures[f"held_{pose}"] = rviz_view.centroid(rviz_view.mask(held, attached_purple, rect))
            figures[f"gripper_{pose}"] = view.project(gripper, rect)
        assert launch.running(), launch.output()[-3000:]
        return launch.output()

    output = headless.run_while_node_lives(
        ["interbotix_xsarm_moveit", "xsarm_moveit.launch", "robot_model:=px100", "dof:=4",
         "use_fake:=true"], screen_env, os.path.join(results_dir, "xsarm_moveit.log"), scenario)
    with open(os.path.join(results_dir, "figures.json"), "w", encoding="utf-8") as stream:
        json.dump(figures, stream, indent=1)
    assert "PluginlibFactory" not in output and "failed to load" not in output, output[-3000:]
    assert np.hypot(*np.subtract(figures["box_centroid"], figures["box_projected"])) \
        < WHERE_PIXELS, figures
    assert np.allclose(figures["pole_rows"], figures["pole_ends_projected"], atol=WHERE_PIXELS), \
        figures
    for pose in ("Home", "Sleep"):
        assert np.hypot(*np.subtract(figures[f"held_{pose}"], figures[f"gripper_{pose}"])) \
            < WHERE_PIXELS, figures
    assert np.hypot(*np.subtract(figures["held_Home"], figures["held_Sleep"])) \
        > MOVED_PIXELS, figures
