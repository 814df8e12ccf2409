"""The TurtleSim window: Qt only, no rospy (the node hands it what to draw).

As turtlesim 0.10.2's TurtleFrame (ros/ros_tutorials noetic-devel db63288,
turtlesim/src/turtle_frame.cpp): a fixed 500 x 500 window titled "TurtleSim" (:53-54)
showing the path image, where the pens draw (:47, :232), with the turtles on top (:234-239),
each centred on its position (turtle.cpp:214-220). The path image is painted without
antialiasing and with Qt's default pen style (square caps), as upstream's painter.

The turtles are this package's own drawing (upstream's images are not used): a shell, a
head, four flippers and a tail, 40 px long, pointing along the heading; ``look`` picks the
colours.
"""
from __future__ import annotations

import math
from typing import Iterable, List, Sequence, Tuple

from python_qt_binding.QtCore import QPointF, QRectF
from python_qt_binding.QtGui import QBrush, QColor, QImage, QPainter, QPen, QPolygonF, qRgb
from python_qt_binding.QtWidgets import QFrame

from turtle_world.turtle import Segment
from turtle_world.world import HEIGHT_PX, WIDTH_PX, pixel_under, to_pixels

TITLE = "TurtleSim"

# (shell, shell pattern, skin) for each look
LOOKS: Sequence[Tuple[str, str, str]] = (
    ("#3f8f3a", "#a6d86b", "#9bc27a"),
    ("#8a5a2b", "#e0b36a", "#c7a27c"),
    ("#2a6f87", "#8fd3e8", "#a2c9b8"),
    ("#7a3f8c", "#d9a3e8", "#b9b39a"),
    ("#9c7a12", "#f2da6b", "#a9c27a"),
    ("#444444", "#bdbdbd", "#c9b79c"),
)
OUTLINE = "#1e1e1e"


class TurtleCanvas(QFrame):
    """The window: the path image, and the turtles as (x, y, heading, look) in canvas
    metres (y down) set by :meth:`show_turtles`."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setFixedSize(WIDTH_PX, HEIGHT_PX)
        self.setWindowTitle(TITLE)
        self.path = QImage(WIDTH_PX, HEIGHT_PX, QImage.Format_ARGB32)
        self._turtles: List[Tuple[float, float, float, int]] = []

    def clear(self, colour: Tuple[int, int, int]) -> None:
        """The path image filled with ``colour`` (turtle_frame.cpp:212)."""
        self.path.fill(qRgb(*colour))
        self.update()

    def draw(self, segments: Iterable[Segment]) -> None:
        """Draws pen lines on the path image."""
        painter = QPainter(self.path)
        try:
            for segment in segments:
                pen = QPen(QColor(segment.pen.r, segment.pen.g, segment.pen.b))
                pen.setWidth(segment.pen.width)
                painter.setPen(pen)
                painter.drawLine(QPointF(*to_pixels(segment.start)),
                                 QPointF(*to_pixels(segment.end)))
        finally:
            painter.end()

    def colour_at(self, point: Tuple[float, float]) -> Tuple[int, int, int]:
        """The path image's colour under a canvas point (turtle.cpp:185-192)."""
        colour = QColor(self.path.pixel(*pixel_under(point)))
        return colour.red(), colour.green(), colour.blue()

    def show_turtles(self, turtles: Iterable[Tuple[float, float, float, int]]) -> None:
        """The turtles to draw, in order; repaints."""
        self._turtles = list(turtles)
        self.update()

    def paintEvent(self, _event) -> None:  # noqa: N802 (Qt's name)
        painter = QPainter(self)
        try:
            painter.drawImage(0, 0, self.path)
            painter.setRenderHint(QPainter.Antialiasing)
            for x, y, heading, look in self._turtles:
                px, py = to_pixels((x, y))
                paint_turtle(painter, px, py, heading, look)
        finally:
            painter.end()


def paint_turtle(painter: QPainter, px: float, py: float, heading: float, look: int) -> None:
    """A turtle centred on pixel (px, py), pointing along ``heading`` (radians,
    counter-clockwise on the screen)."""
    shell, pattern, skin = (QColor(c) for c in LOOKS[look % len(LOOKS)])
    painter.save()
    painter.translate(px, py)
    painter.rotate(-math.degrees(heading))  # the screen's y points down
    painter.setPen(QPen(QColor(OUTLINE), 1.2))
    painter.setBrush(QBrush(skin))
    for side in (-1, 1):  # flippers: front ones longer, swept forward
        painter.save()
        painter.translate(7, side * 10)
        painter.rotate(side * 35)
        painter.drawEllipse(QRectF(-3, -4, 12, 8))
        painter.restore()
        painter.save()
        painter.translate(-8, side * 10)
        painter.rotate(side * 140)
        painter.drawEllipse(QRectF(-2, -3, 9, 6))
        painter.restore()
    painter.drawPolygon(QPolygonF([QPointF(-12, -3), QPointF(-19, 0), QPointF(-12, 3)]))
    painter.drawEllipse(QRectF(11, -5.5, 11, 11))  # head
    painter.setBrush(QBrush(QColor(OUTLINE)))
    for side in (-1, 1):
        painter.drawEllipse(QPointF(18, side * 2.5), 1.0, 1.0)  # eyes
    painter.setBrush(QBrush(shell))
    painter.drawEllipse(QRectF(-14, -11, 28, 22))
    painter.setBrush(QBrush(pattern))
    painter.setPen(QPen(shell.darker(140), 1.0))
    painter.drawPolygon(QPolygonF([QPointF(6 * math.cos(a), 5 * math.sin(a))
                                   for a in (k * math.pi / 3 for k in range(6))]))
    for angle in (k * math.pi / 3 for k in range(6)):
        painter.drawLine(QPointF(6 * math.cos(angle), 5 * math.sin(angle)),
                         QPointF(12 * math.cos(angle), 9.5 * math.sin(angle)))
    painter.restore()
