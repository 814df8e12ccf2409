"""Line charts as SVG text, for the grading report's plots (no matplotlib on the grading
machines): one chart is axes with round-numbered ticks, polylines, point markers, dashed
reference lines, labelled vertical marks and a legend (a row under the plot). Pure Python,
no ROS."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import List, Sequence, Tuple
from xml.sax.saxutils import escape, quoteattr

Point = Tuple[float, float]

# layout, in SVG user units (pixels at 100 %)
WIDTH, HEIGHT = 720, 440
MARGIN_LEFT, MARGIN_RIGHT, MARGIN_TOP, MARGIN_BOTTOM = 70, 20, 40, 70
FONT_SIZE = 12
TITLE_SIZE = 14
TICK_LENGTH = 5
LEGEND_GAP = 24              # between two legend entries, in the row under the x axis
LEGEND_SWATCH = 18           # length of the legend's line sample
CHAR_WIDTH = 0.6             # of the font size: a character's width, about
MARKER_RADIUS = 3.5
TARGET_TICKS = 6             # about this many ticks per axis
PADDING = 0.05               # of the data's span, added above and below the y axis's
NICE_STEPS = (1.0, 2.0, 2.5, 5.0, 10.0)   # tick steps are these times a power of ten
DASH = "6,4"
MAX_DECIMALS = 6             # of a tick label


@dataclass
class Series:
    """A polyline (``line``), dots (``markers``), or both, with a legend entry when
    ``label`` is set. Points with a NaN coordinate break the line."""

    label: str
    points: Sequence[Point]
    colour: str = "#1f77b4"
    line: bool = True
    markers: bool = False
    dashed: bool = False
    width: float = 1.8


@dataclass
class Chart:
    title: str
    x_label: str
    y_label: str
    series: List[Series] = field(default_factory=list)
    # vertical marks across the plot: (x, text shown at the top)
    marks: List[Tuple[float, str]] = field(default_factory=list)
    mark_colour: str = "#d62728"
    equal_scale: bool = False    # one unit as long on both axes (a path in the plane)


def nice_ticks(low: float, high: float, target: int = TARGET_TICKS) -> List[float]:
    """Round-numbered ticks (1, 2, 2.5 or 5 times a power of ten apart), the first at or
    below ``low``, the last at or above ``high``."""
    if not (math.isfinite(low) and math.isfinite(high)):
        raise ValueError(f"an axis from {low} to {high} cannot be drawn")
    if high < low:
        low, high = high, low
    span = high - low or abs(high) or 1.0
    raw = span / max(1, target)
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(s * power for s in NICE_STEPS if s * power >= raw - 1e-12 * power)
    first = math.floor(low / step + 1e-9) * step
    ticks = [first]
    while ticks[-1] < high - step * 1e-9 or len(ticks) < 2:
        ticks.append(first + len(ticks) * step)
    return [0.0 if abs(t) < step * 1e-9 else t for t in ticks]


def _label(value: float, step: float) -> str:
    """``value`` with as many decimals as the tick step needs (0.25 apart: two)."""
    decimals = 0
    while decimals < MAX_DECIMALS and abs(step * 10 ** decimals
                                          - round(step * 10 ** decimals)) > 1e-6:
        decimals += 1
    return f"{value:.{decimals}f}"


def _finite(points: Sequence[Point]) -> List[Point]:
    return [(x, y) for x, y in points if math.isfinite(x) and math.isfinite(y)]


def _range(values: List[float], padding: float) -> Tuple[float, float]:
    low, high = min(values), max(values)
    pad = (high - low) * padding or max(abs(high) * padding, padding)
    return low - pad, high + pad


class _Frame:
    """Data to SVG coordinates for one chart's plot area."""

    def __init__(self, chart: Chart):
        xs = [x for s in chart.series for x, _ in _finite(s.points)] + [x for x, _ in chart.marks]
        ys = [y for s in chart.series for _, y in _finite(s.points)]
        if not xs or not ys:
            raise ValueError(f"chart '{chart.title}' has no finite point to draw")
        self.x_ticks = nice_ticks(min(xs), max(xs))     # time starts at the left edge
        self.y_ticks = nice_ticks(*_range(ys, PADDING))
        self.left, self.top = MARGIN_LEFT, MARGIN_TOP
        self.width = WIDTH - MARGIN_LEFT - MARGIN_RIGHT
        self.height = HEIGHT - MARGIN_TOP - MARGIN_BOTTOM
        self.x0, self.x1 = self.x_ticks[0], self.x_ticks[-1]
        self.y0, self.y1 = self.y_ticks[0], self.y_ticks[-1]
        if chart.equal_scale:
            self._equalise()

    def _equalise(self) -> None:
        """Widens the axis with fewer units per pixel so both have the same scale."""
        per_x = (self.x1 - self.x0) / self.width
        per_y = (self.y1 - self.y0) / self.height
        if per_x < per_y:
            middle, half = (self.x0 + self.x1) / 2, per_y * self.width / 2
            self.x0, self.x1 = middle - half, middle + half
            self.x_ticks = [t for t in nice_ticks(self.x0, self.x1)
                            if self.x0 - 1e-9 <= t <= self.x1 + 1e-9] or self.x_ticks
        else:
            middle, half = (self.y0 + self.y1) / 2, per_x * self.height / 2
            self.y0, self.y1 = middle - half, middle + half
            self.y_ticks = [t for t in nice_ticks(self.y0, self.y1)
                            if self.y0 - 1e-9 <= t <= self.y1 + 1e-9] or self.y_ticks

    def x(self, value: float) -> float:
        return self.left + (value - self.x0) / (self.x1 - self.x0) * self.width

    def y(self, value: float) -> float:
        return self.top + (self.y1 - value) / (self.y1 - self.y0) * self.height


def _text(x: float, y: float, text: str, size: int = FONT_SIZE, anchor: str = "middle",
          extra: str = "") -> str:
    return (f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size}" text-anchor="{anchor}"'
            f'{extra}>{escape(text)}</text>')


def _polylines(frame: _Frame, series: Series) -> List[str]:
    """One polyline per run of finite points."""
    runs: List[List[Point]] = [[]]
    for x, y in series.points:
        if math.isfinite(x) and math.isfinite(y):
            runs[-1].append((x, y))
        elif runs[-1]:
            runs.append([])
    dash = f' stroke-dasharray="{DASH}"' if series.dashed else ""
    return [f'<polyline fill="none" stroke={quoteattr(series.colour)} '
            f'stroke-width="{series.width:g}"{dash} points="'
            + " ".join(f"{frame.x(x):.1f},{frame.y(y):.1f}" for x, y in run) + '"/>'
            for run in runs if run]


def render(chart: Chart) -> str:
    """The chart as a standalone SVG document."""
    frame = _Frame(chart)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif">',
           f'<defs><clipPath id="plot"><rect x="{frame.left}" y="{frame.top}" '
           f'width="{frame.width}" height="{frame.height}"/></clipPath></defs>',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
           _text(WIDTH / 2, MARGIN_TOP / 2 + TITLE_SIZE / 2, chart.title, TITLE_SIZE)]
    bottom, right = frame.top + frame.height, frame.left + frame.width
    x_step = frame.x_ticks[1] - frame.x_ticks[0]
    y_step = frame.y_ticks[1] - frame.y_ticks[0]
    for tick in frame.x_ticks:
        px = frame.x(tick)
        out.append(f'<line x1="{px:.1f}" y1="{frame.top}" x2="{px:.1f}" y2="{bottom}" '
                   'stroke="#e0e0e0"/>')
        out.append(f'<line x1="{px:.1f}" y1="{bottom}" x2="{px:.1f}" '
                   f'y2="{bottom + TICK_LENGTH}" stroke="black"/>')
        out.append(_text(px, bottom + TICK_LENGTH + FONT_SIZE, _label(tick, x_step)))
    for tick in frame.y_ticks:
        py = frame.y(tick)
        out.append(f'<line x1="{frame.left}" y1="{py:.1f}" x2="{right}" y2="{py:.1f}" '
                   'stroke="#e0e0e0"/>')
        out.append(f'<line x1="{frame.left - TICK_LENGTH}" y1="{py:.1f}" x2="{frame.left}" '
                   f'y2="{py:.1f}" stroke="black"/>')
        out.append(_text(frame.left - TICK_LENGTH - 2, py + FONT_SIZE / 3,
                         _label(tick, y_step), anchor="end"))
    out.append(f'<rect x="{frame.left}" y="{frame.top}" width="{frame.width}" '
               f'height="{frame.height}" fill="none" stroke="black"/>')
    out.append(_text(frame.left + frame.width / 2, bottom + TICK_LENGTH + 2.5 * FONT_SIZE,
                     chart.x_label))
    middle = frame.top + frame.height / 2
    out.append(_text(FONT_SIZE, middle, chart.y_label,
                     extra=f' transform="rotate(-90 {FONT_SIZE} {middle:.1f})"'))
    for x, text in chart.marks:
        px = frame.x(x)
        out.append(f'<line x1="{px:.1f}" y1="{frame.top}" x2="{px:.1f}" y2="{bottom}" '
                   f'stroke={quoteattr(chart.mark_colour)} stroke-dasharray="2,3"/>')
        out.append(_text(px, frame.top - 3, text, FONT_SIZE - 2,
                         extra=f" fill={quoteattr(chart.mark_colour)}"))
    out.append('<g clip-path="url(#plot)">')
    for series in chart.series:
        if series.line:
            out += _polylines(frame, series)
        if series.markers:
            out += [f'<circle cx="{frame.x(x):.1f}" cy="{frame.y(y):.1f}" r="{MARKER_RADIUS}" '
                    f'fill={quoteattr(series.colour)}/>' for x, y in _finite(series.points)]
    out.append("</g>")
    out += _legend(chart, frame.left)
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _legend(chart: Chart, left: float) -> List[str]:
    """One row under the x axis's label: a sample of each labelled series and its label."""
    out: List[str] = []
    y = HEIGHT - FONT_SIZE
    x = left
    for series in (s for s in chart.series if s.label):
        if series.line:
            dash = f' stroke-dasharray="{DASH}"' if series.dashed else ""
            out.append(f'<line x1="{x:.1f}" y1="{y:.1f}" x2="{x + LEGEND_SWATCH:.1f}" '
                       f'y2="{y:.1f}" stroke={quoteattr(series.colour)} '
                       f'stroke-width="{series.width:g}"{dash}/>')
        if series.markers:
            out.append(f'<circle cx="{x + LEGEND_SWATCH / 2:.1f}" cy="{y:.1f}" '
                       f'r="{MARKER_RADIUS}" fill={quoteattr(series.colour)}/>')
        out.append(_text(x + LEGEND_SWATCH + 6, y + FONT_SIZE / 3, series.label,
                         anchor="start"))
        x += LEGEND_SWATCH + 6 + CHAR_WIDTH * FONT_SIZE * len(series.label) + LEGEND_GAP
    return out


def write(chart: Chart, path: str) -> str:
    with open(path, "w", encoding="utf-8") as stream:
        stream.write(render(chart))
    return path

