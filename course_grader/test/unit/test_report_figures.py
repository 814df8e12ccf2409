"""The report's pictures, no master: a probe's answer turned into figures under its items
(the pictures it wrote, a plot per ``samples`` entry), report.md embedding each beside
its item or saying why there is none, report.json listing the files, the reasons given
before anything runs (a course without rviz, --only leaving it out), and the screenshot
module on a virtual screen (a window drawn is kept, a window of one colour is not, a
missing window is named)."""
import json
import os
import shutil
import subprocess
import sys
import time

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.dirname(os.path.abspath(__file__))))), "tools"))
import headless  # noqa: E402  (tools/ is not a package)

from course_grader import course as course_file
from course_grader import grader, report, screenshot
from course_grader.results import Check, Figure, Report, judge

DRIVE = {"item": "cmd_vel_moves", "command": "/cmd_vel at 0.2 m/s for 3 s",
         "path": [(-0.43 + 0.02 * i, -1.32) for i in range(30)]}
SHOT = {"timeout": 3.0, "interval": 0.2, "settle": 2, "change": 0.002}
XVFB_START = 20.0          # s: the longest Xvfb may take to choose a display
# s: the longest an xmessage window may take to be mapped (3 s, SHOT's, ran out once on the
# 2-core VM while another test suite ran beside it)
WINDOW_START = 30.0


@pytest.fixture(scope="module")
def rb1():
    return course_file.load("rb1")


def graded(rb1, items):
    return [judge(item, [Check("c", True, f"{item.id} measured")]) for item in items]


def test_a_probe_answer_puts_pictures_and_plots_under_their_items(rb1, tmp_path):
    results = graded(rb1, rb1.items_of("display"))
    grader.add_figures(results, {"figures": {"display_links_tf": [
        {"title": "rviz showing display.launch", "file": "display.png", "caption": "c1"}]}},
        str(tmp_path))
    assert results[0].figures == [Figure("rviz showing display.launch", "display.png", "c1")]
    drive = graded(rb1, rb1.items_of("drive"))
    grader.add_figures(drive, {"samples": {"drive": DRIVE}}, str(tmp_path))
    assert drive[0].figures[0].file == "drive.svg"
    assert (tmp_path / "drive.svg").read_text().startswith("<svg")


def test_markdown_embeds_each_picture_under_its_item_and_json_lists_the_files(rb1, tmp_path):
    results = graded(rb1, rb1.items)
    by_id = {r.item.id: r for r in results}
    by_id["display_links_tf"].figures.append(
        Figure("rviz showing display.launch", "display.png", "the screen after TF"))
    by_id["cmd_vel_moves"].figures.append(Figure("true path while driving", "drive.svg", "p"))
    by_id["rotate_degrees"].figures.append(
        Figure("true yaw during the rotate requests", missing="the samples could not be drawn"))
    graded_report = Report(rb1, "/tmp/submission", results, build="catkin_make: ok")
    md_path, json_path = report.write(graded_report, str(tmp_path))
    text = open(md_path, encoding="utf-8").read()
    display_section = text.split("## 1. display.launch shows")[1].split("\n## ")[0]
    assert "![rviz showing display.launch](display.png)" in display_section
    assert "*the screen after TF*" in display_section
    drive_section = text.split("## 3. /cmd_vel moves the robot")[1].split("\n## ")[0]
    assert "![true path while driving](drive.svg)" in drive_section
    assert "- no picture (true yaw during the rotate requests): the samples could not be " \
           "drawn" in text
    data = json.loads(open(json_path, encoding="utf-8").read())
    assert [f["file"] for f in data["figures"] if f["file"]] == ["display.png", "drive.svg"]
    assert {f["item"] for f in data["figures"]} == {"display_links_tf", "cmd_vel_moves",
                                                    "rotate_degrees"}
    items = {i["id"]: i for i in data["items"]}
    assert items["display_links_tf"]["figures"] == ["display.png"]
    assert items["rotate_degrees"]["figures"] == []


def test_why_there_is_no_screenshot_is_known_before_anything_runs(rb1):
    hw3 = course_file.load("me495_hw3")
    none = grader.no_screenshot(hw3, hw3.scenarios())
    assert len(none) == 1 and "no scenario of this course opens rviz" in none[0].missing
    assert "rviz:=false" in none[0].missing
    skipped = grader.no_screenshot(rb1, ["rotate"])
    assert "(display) was not run (--only)" in skipped[0].missing
    assert grader.no_screenshot(rb1, rb1.scenarios()) == []
    graded_report = Report(hw3, "/tmp/hw3", graded(hw3, hw3.items), figures=none)
    assert f"- rviz screenshot: {none[0].missing}" in report.markdown(graded_report)


def test_a_failed_display_scenario_says_why_it_has_no_picture(rb1):
    results = graded(rb1, rb1.items_of("display"))
    spec = grader.scenario_spec(rb1, "display")
    grader._not_pictured(spec, results, "'display' ended (exit status 1)")
    assert "failed before or while it was measured ('display' ended" in \
        results[0].figures[0].missing
    drive = graded(rb1, rb1.items_of("drive"))
    grader._not_pictured(grader.scenario_spec(rb1, "drive"), drive, "x")
    assert drive[0].figures == []


def test_pictures_of_an_earlier_grading_are_removed(tmp_path):
    for name in ("display.png", "rotate.svg", "notes.txt"):
        (tmp_path / name).write_text("old")
    grader._forget_pictures(str(tmp_path))
    assert sorted(os.listdir(tmp_path)) == ["notes.txt"]


# --- the screenshot on a virtual screen ----------------------------------------------------


@pytest.fixture(scope="module")
def display():
    if shutil.which("Xvfb") is None or screenshot.missing_tools():
        pytest.skip("Xvfb, x11-utils or imagemagick not installed (tools/setup.sh installs them)")
    # headless's Xvfb: started and stopped under the lock every Xvfb here takes
    with headless.virtual_display(320, 240, timeout=XVFB_START) as number:
        yield number


def window(display, title, *options):
    return subprocess.Popen(["xmessage", "-display", display, "-title", title, *options],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def wait_for_window(display, title, process, deadline):
    """Waits until ``process`` (an xmessage) has mapped its window titled ``title``; fails
    saying what xmessage printed if it ended, or which windows the screen had."""
    while screenshot.find_window(display, title) is None:
        if process.poll() is not None:
            pytest.fail(f"xmessage '{title}' ended ({process.returncode}): "
                        f"{process.stderr.read()}")
        if time.monotonic() > deadline:
            tree = subprocess.run(["xwininfo", "-display", display, "-root", "-tree"],
                                  capture_output=True, text=True, check=False)
            pytest.fail(f"no window '{title}' on {display} after {WINDOW_START:g} s; the "
                        f"screen has: {tree.stdout[-1500:]}{tree.stderr[-500:]}")
        time.sleep(SHOT["interval"])


def test_a_drawn_window_is_kept_and_a_missing_one_named(display, tmp_path):
    path = str(tmp_path / "shot.png")
    shot = screenshot.take(display, path, "Fake RViz", dict(SHOT, timeout=0.5))
    assert not shot.path and "no window titled 'Fake RViz' appeared within 0.5 s" in shot.why
    message = window(display, "Fake RViz", "the robot would be here")
    try:
        wait_for_window(display, "Fake RViz", message, time.monotonic() + WINDOW_START)
        shot = screenshot.take(display, path, "Fake RViz", SHOT)
    finally:
        message.terminate()
        message.wait()
    assert shot.path == path and shot.settled and not shot.why
    assert shot.colours > 1 and screenshot.distinct_colours(path) == shot.colours
    width, height = screenshot.size(path)
    assert width < 320 and height < 240       # the window, not the whole screen
    assert os.listdir(tmp_path) == ["shot.png"]


def test_a_window_over_the_wanted_one_is_moved_beside_it_and_both_pictured(display,
                                                                          tmp_path):
    if shutil.which("xdotool") is None:
        pytest.skip("xdotool not installed (tools/setup.sh installs it)")
    main = window(display, "Fake RViz", "the robot would be here, in a wide window")
    try:
        sliders = None
        deadline = time.monotonic() + WINDOW_START
        wait_for_window(display, "Fake RViz", main, deadline)
        sliders = window(display, "Sliders", "wheel")      # opens at 0, 0: over the first
        wait_for_window(display, "Sliders", sliders, deadline)
        path = str(tmp_path / "both.png")
        shot = screenshot.take(display, path, "Fake RViz", SHOT)
        first = screenshot.find_window(display, "Fake RViz")
        second = screenshot.find_window(display, "Sliders")
    finally:
        for process in (main, sliders):
            if process is not None:
                process.terminate()
                process.wait()
    assert set(shot.windows) == {"Fake RViz", "Sliders"}
    assert not first.overlaps(second) and second.y >= first.y + first.height
    width, height = screenshot.size(path)
    assert width == first.width and height == first.height + second.height


def test_a_window_of_one_colour_is_no_picture(display, tmp_path):
    black = window(display, "Blank RViz", "-bg", "black", "-fg", "black", "-xrm",
                   "*borderWidth: 0", "-xrm", "*shadowWidth: 0", "     ")
    try:
        wait_for_window(display, "Blank RViz", black, time.monotonic() + WINDOW_START)
        shot = screenshot.take(display, str(tmp_path / "blank.png"), "Blank RViz",
                               dict(SHOT, timeout=1.0))
    finally:
        black.terminate()
        black.wait()
    assert not shot.path and "stayed one colour" in shot.why
    assert os.listdir(tmp_path) == []


def test_no_screen_is_a_reason_not_an_error(tmp_path):
    shot = screenshot.take("", str(tmp_path / "x.png"), "RViz", SHOT)
    assert not shot.path and "no screen" in shot.why
