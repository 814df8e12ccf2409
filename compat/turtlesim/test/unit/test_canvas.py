"""turtle_world.canvas on Qt's offscreen platform: the window's size and title
(turtle_frame.cpp:47, :53-54), the pen's lines on the path image (turtle.cpp:35-37, :50-53,
:201-209), the colour sensor's pixel (turtle.cpp:185-192), the drawn turtles; upstream is
ros/ros_tutorials noetic-devel db63288, turtlesim/src. No display, no ROS."""
import math

import pytest
from python_qt_binding.QtGui import QColor
from python_qt_binding.QtWidgets import QApplication

from turtle_world.canvas import TurtleCanvas
from turtle_world.turtle import DEFAULT_PEN, Pen, Segment
from turtle_world.world import DEFAULT_BACKGROUND


@pytest.fixture(scope="module")
def app():
    # the platform as an argument, not in os.environ: other tests' windows need the screen
    return QApplication.instance() or QApplication(["test_canvas", "-platform", "offscreen"])


@pytest.fixture
def canvas(app):
    widget = TurtleCanvas()
    widget.clear(DEFAULT_BACKGROUND)
    yield widget
    widget.deleteLater()


def count(image, rgb):
    wanted = QColor(*rgb).rgb()
    return sum(image.pixel(x, y) == wanted
               for x in range(image.width()) for y in range(image.height()))


def test_window_as_upstream(canvas):
    assert canvas.windowTitle() == "TurtleSim"
    assert (canvas.width(), canvas.height()) == (500, 500)
    assert (canvas.minimumSize(), canvas.maximumSize()) == (canvas.size(), canvas.size())
    assert canvas.colour_at((5.0, 5.0)) == DEFAULT_BACKGROUND


def test_a_pen_line_is_its_width_wide_and_the_sensor_reads_it(canvas):
    canvas.draw([Segment(DEFAULT_PEN, (3.0, 2.0), (1.0, 2.0))])  # 90 px along y = 90 px
    painted = count(canvas.path, (179, 184, 255))
    assert 3 * 90 <= painted <= 3 * 94  # width 3, square caps
    assert canvas.colour_at((2.0, 2.0)) == (179, 184, 255)
    assert canvas.colour_at((2.0, 2.1)) == DEFAULT_BACKGROUND
    canvas.draw([Segment(Pen(255, 0, 0, 1), (1.0, 4.0), (3.0, 4.0))])
    assert 90 <= count(canvas.path, (255, 0, 0)) <= 92
    canvas.clear((0, 0, 0))
    assert canvas.colour_at((2.0, 2.0)) == (0, 0, 0)


def test_turtles_are_drawn_on_top_turned_with_their_heading(canvas):
    canvas.show_turtles([(2.0, 2.0, 0.0, 0)])
    shown = canvas.grab().toImage()
    assert count(canvas.path, DEFAULT_BACKGROUND) == 500 * 500  # not on the path image
    around = [shown.pixel(x, y) for x in range(70, 110) for y in range(70, 110)]
    assert sum(p != QColor(*DEFAULT_BACKGROUND).rgb() for p in around) > 300
    canvas.show_turtles([(2.0, 2.0, math.pi / 2, 0)])
    turned = canvas.grab().toImage()
    assert turned != shown
    # the head leads: ahead of the centre (+x at heading 0, up at pi/2) is turtle
    assert shown.pixel(90 + 17, 90) != QColor(*DEFAULT_BACKGROUND).rgb()
    assert turned.pixel(90, 90 - 17) != QColor(*DEFAULT_BACKGROUND).rgb()
