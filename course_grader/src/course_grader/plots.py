"""The report's plots of the measured motion, drawn from the ground-truth samples a probe
returns under ``samples`` in its answer (one entry per plot: its kind, the item it belongs
to and the samples): the rotate requests (true yaw against simulated time, each request's
target), the drive (the true path in the plane) and the flips (the body's up axis against
time, each flip marked). No ROS here."""
from __future__ import annotations

import math
import os
from typing import Callable, Dict, List, Tuple

from course_grader.results import Figure
from course_grader.svg_plot import Chart, Series, write

TRUTH = "#1f77b4"
TARGET = "#2ca02c"
ANSWER = "#d62728"
START, END = "#2ca02c", "#d62728"
GREY = "#7f7f7f"


def _rotate(data: Dict) -> Tuple[Chart, str]:
    requests = data["requests"]
    if not requests:
        raise ValueError("no rotate request was measured")
    t0 = requests[0]["began"]
    y0 = requests[0]["start"]
    truth: List[Tuple[float, float]] = []
    targets: List[Tuple[float, float]] = []
    answers: List[Tuple[float, float]] = []
    for request in requests:
        samples = request["samples"]
        if not samples:
            continue
        truth += [(t - t0, yaw - y0) for t, yaw in samples] + [(math.nan, math.nan)]
        goal = request["start"] + request["requested"] - y0
        targets += [(request["began"] - t0, goal), (samples[-1][0] - t0, goal),
                    (math.nan, math.nan)]
        answered = request.get("answered_at")
        if answered is not None and math.isfinite(answered):
            yaw = min(samples, key=lambda s: abs(s[0] - answered))[1]
            answers.append((answered - t0, yaw - y0))
    asked = ", ".join(f"{r['requested']:+g}" for r in requests)
    chart = Chart(f"rotate: true yaw for the requests {asked} deg",
                  "simulated time since the first request (s)",
                  "yaw from the start (deg)",
                  [Series("requested target", targets, TARGET, dashed=True),
                   Series("true yaw", truth, TRUTH),
                   Series("answer", answers, ANSWER, line=False, markers=True)],
                  marks=[(r["began"] - t0, f"{r['requested']:+g}") for r in requests],
                  mark_colour=GREY)
    caption = ("The robot's true yaw (/gazebo/model_states, unwrapped) from its heading "
               "before the first request; dashed: each request's target from that request's "
               "start; dots: when /rotate_robot answered.")
    return chart, caption


def _drive(data: Dict) -> Tuple[Chart, str]:
    path = [tuple(p) for p in data["path"]]
    if not path:
        raise ValueError("no pose was measured while driving")
    chart = Chart("drive: the true path on /cmd_vel", "x (m)", "y (m)",
                  [Series("true path", path, TRUTH),
                   Series("start", [path[0]], START, line=False, markers=True),
                   Series("end", [path[-1]], END, line=False, markers=True)],
                  equal_scale=True)
    moved = math.hypot(path[-1][0] - path[0][0], path[-1][1] - path[0][1])
    caption = (f"The robot's true position (/gazebo/model_states) in the world frame while "
               f"{data.get('command', '/cmd_vel')} was published: {moved:.3f} m from start "
               f"to end, both axes to the same scale.")
    return chart, caption


def _flip(data: Dict) -> Tuple[Chart, str]:
    samples = data["samples"]
    if not samples:
        raise ValueError("no orientation was measured")
    t0 = samples[0][0]
    band = float(data.get("dead_band", 0.0))
    end = samples[-1][0] - t0
    flips = data.get("flips", [])
    chart = Chart(f"flip: the body's up axis, {len(flips)} flips",
                  "simulated time (s)", "z of the body's up axis",
                  [Series("up axis z", [(t - t0, z) for t, z in samples], TRUTH),
                   Series("dead band", [(0.0, band), (end, band), (math.nan, math.nan),
                                        (0.0, -band), (end, -band)], GREY, dashed=True,
                          width=1.0)],
                  marks=[(t - t0, str(n + 1)) for n, t in enumerate(flips)])
    caption = ("The z component of the body's up axis from its true orientation "
               "(/gazebo/model_states): 1 upright, -1 upside down; each flip marked where it "
               f"crossed to the other side beyond the dead band (±{band:g}).")
    return chart, caption


KINDS: Dict[str, Callable[[Dict], Tuple[Chart, str]]] = {
    "rotate": _rotate, "drive": _drive, "flip": _flip}
TITLES = {"rotate": "true yaw during the rotate requests", "drive": "true path while driving",
          "flip": "the body's up axis during the flips"}


def draw(kind: str, data: Dict, folder: str) -> Figure:
    """Writes ``<kind>.svg`` into ``folder`` from a probe's samples; the figure, or why
    there is none (samples it cannot draw)."""
    title = TITLES.get(kind, kind)
    if kind not in KINDS:
        return Figure(title, missing=f"no plot of the kind '{kind}' (known: "
                                     f"{', '.join(sorted(KINDS))})")
    try:
        chart, caption = KINDS[kind](data)
        name = f"{kind}.svg"
        write(chart, os.path.join(folder, name))
    except (KeyError, TypeError, ValueError, IndexError) as error:
        return Figure(title, missing=f"the {kind} samples could not be drawn "
                                     f"({type(error).__name__}: {error})")
    return Figure(title, name, caption)
