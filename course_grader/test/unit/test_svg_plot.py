"""course_grader's SVG charts and the report's plots, no master: round ticks that cover
the data, coordinates that map data into the plot area (equal scale for a path), the
document well formed, and the rotate, drive and flip plots drawn from probe samples (or
why not)."""
import math
import xml.etree.ElementTree as ET

import pytest

from course_grader import plots, svg_plot
from course_grader.measures import thin
from course_grader.svg_plot import Chart, Series

SVG = "{http://www.w3.org/2000/svg}"


@pytest.mark.parametrize("low, high", [(0, 10), (-92.3, 541.0), (0.0013, 0.0021), (5, 5),
                                       (-1.05, 1.05), (-0.43, -0.1), (1e5, 3.3e5)])
def test_ticks_are_round_evenly_spaced_and_cover_the_data(low, high):
    ticks = svg_plot.nice_ticks(low, high)
    assert ticks[0] <= low and ticks[-1] >= high and len(ticks) >= 2
    steps = {round(b - a, 12) for a, b in zip(ticks, ticks[1:])}
    assert len(steps) == 1
    step = steps.pop()
    mantissa = step / 10 ** math.floor(math.log10(step))
    assert min(abs(mantissa - m) for m in svg_plot.NICE_STEPS) < 1e-9
    assert len(ticks) <= 2 * svg_plot.TARGET_TICKS + 1


def test_tick_labels_carry_the_digits_their_step_needs():
    assert svg_plot._label(7.5, 2.5) == "7.5"
    assert svg_plot._label(0.0012000000001, 0.0002) == "0.0012"
    assert svg_plot._label(-0.19999999999996, 0.1) == "-0.2"
    assert svg_plot._label(300.0, 100.0) == "300"


def test_an_axis_without_a_finite_point_is_refused():
    with pytest.raises(ValueError, match="no finite point"):
        svg_plot.render(Chart("empty", "x", "y", [Series("nothing", [(math.nan, 1.0)])]))
    with pytest.raises(ValueError, match="cannot be drawn"):
        svg_plot.nice_ticks(0.0, math.inf)


def _polylines(svg_text):
    root = ET.fromstring(svg_text)
    return [[tuple(map(float, p.split(","))) for p in line.get("points").split()]
            for line in root.iter(f"{SVG}polyline")]


def test_points_land_inside_the_plot_area_in_order_and_nan_breaks_the_line():
    points = [(0.0, 0.0), (1.0, 2.0), (math.nan, math.nan), (2.0, -1.0), (3.0, 4.0)]
    text = svg_plot.render(Chart("t", "time (s)", "yaw (deg)", [Series("yaw", points)]))
    lines = _polylines(text)
    assert [len(line) for line in lines] == [2, 2]
    left, top = svg_plot.MARGIN_LEFT, svg_plot.MARGIN_TOP
    right = svg_plot.WIDTH - svg_plot.MARGIN_RIGHT
    bottom = svg_plot.HEIGHT - svg_plot.MARGIN_BOTTOM
    drawn = [p for line in lines for p in line]
    assert all(left <= x <= right and top <= y <= bottom for x, y in drawn)
    xs = [x for x, _ in drawn]
    assert xs == sorted(xs)                     # time runs to the right
    by_value = dict(zip([0.0, 2.0, -1.0, 4.0], [y for _, y in drawn]))
    assert by_value[4.0] < by_value[2.0] < by_value[0.0] < by_value[-1.0]   # up is up
    assert "time (s)" in text and "yaw (deg)" in text and ">yaw<" in text   # legend


def test_equal_scale_gives_a_metre_the_same_length_on_both_axes():
    path = [(0.0, 0.0), (0.6, 0.05)]
    text = svg_plot.render(Chart("path", "x (m)", "y (m)", [Series("p", path)],
                                 equal_scale=True))
    (a, b), = _polylines(text)
    per_x = (b[0] - a[0]) / 0.6
    per_y = (a[1] - b[1]) / 0.05
    assert per_x == pytest.approx(per_y, rel=0.02)


def test_text_is_escaped_and_marks_drawn():
    chart = Chart("a <b> & c", "x", "y", [Series("s & t", [(0, 0), (1, 1)])],
                  marks=[(0.5, "flip 1")])
    root = ET.fromstring(svg_plot.render(chart))
    texts = [t.text for t in root.iter(f"{SVG}text")]
    assert "a <b> & c" in texts and "s & t" in texts and "flip 1" in texts


def test_thin_keeps_the_ends_and_at_most_the_number_asked():
    samples = list(range(1000))
    thinned = thin(samples, 50)
    assert len(thinned) == 50 and thinned[0] == 0 and thinned[-1] == 999
    assert thinned == sorted(thinned)
    assert thin(samples[:10], 50) == samples[:10]
    with pytest.raises(ValueError):
        thin(samples, 1)


def _rotate_samples():
    """Two requests, -90 then +270, at 1 rad/s in 10 ms steps from a heading of 30 deg."""
    requests, t, yaw = [], 0.0, 30.0
    for asked in (-90.0, 270.0):
        start, began, samples = yaw, t, []
        while abs(yaw - (start + asked)) > 0.5:
            samples.append((t, yaw))
            yaw += math.copysign(0.57, asked)
            t += 0.01
        samples.append((t, yaw))
        requests.append({"requested": asked, "began": began, "start": start,
                         "answered_at": t, "samples": samples})
        t += 1.0
    return {"item": "rotate_degrees", "requests": requests}


def test_rotate_plot_shows_the_true_yaw_each_target_and_the_answers(tmp_path):
    figure = plots.draw("rotate", _rotate_samples(), str(tmp_path))
    assert figure.file == "rotate.svg" and not figure.missing and "true yaw" in figure.caption
    root = ET.parse(tmp_path / "rotate.svg").getroot()
    texts = [t.text for t in root.iter(f"{SVG}text")]
    assert "rotate: true yaw for the requests -90, +270 deg" in texts
    assert {"true yaw", "requested target", "answer"} <= set(texts)
    assert len(list(root.iter(f"{SVG}circle"))) >= 2          # the answers (and the legend's)
    lines = [len(p) for p in _polylines(ET.tostring(root, encoding="unicode"))]
    assert lines.count(2) >= 2                                 # a target segment per request


def test_drive_and_flip_plots(tmp_path):
    drive = plots.draw("drive", {"item": "cmd_vel_moves", "command": "/cmd_vel at 0.2 m/s",
                                 "path": [(-0.43 + 0.01 * i, -1.32) for i in range(60)]},
                       str(tmp_path))
    assert drive.file == "drive.svg" and "0.590 m" in drive.caption
    flip = plots.draw("flip", {"item": "flips", "dead_band": 0.2, "flips": [2.0, 4.5],
                               "samples": [(0.1 * i, math.cos(0.1 * i)) for i in range(80)]},
                      str(tmp_path))
    root = ET.parse(tmp_path / "flip.svg").getroot()
    texts = [t.text for t in root.iter(f"{SVG}text")]
    assert flip.file == "flip.svg" and "flip: the body's up axis, 2 flips" in texts
    assert "1" in texts and "2" in texts


def test_samples_that_cannot_be_drawn_say_why(tmp_path):
    empty = plots.draw("rotate", {"item": "rotate_degrees", "requests": []}, str(tmp_path))
    assert not empty.file and "no rotate request was measured" in empty.missing
    unknown = plots.draw("dance", {"item": "x"}, str(tmp_path))
    assert not unknown.file and "no plot of the kind 'dance'" in unknown.missing
    broken = plots.draw("drive", {"item": "x"}, str(tmp_path))
    assert not broken.file and "KeyError" in broken.missing
    assert not list(tmp_path.iterdir())
