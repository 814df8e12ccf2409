"""robot_steering.widget on Qt's offscreen platform, with a recording stand-in for the
publisher: no display and no master."""
import pytest
from python_qt_binding.QtCore import Qt
from python_qt_binding.QtTest import QTest
from python_qt_binding.QtWidgets import QApplication

from robot_steering.node import parse_arguments
from robot_steering.steering import Settings
from robot_steering.widget import WIDGET_NAMES, SteeringWidget


class Topics:
    """Opens recording publishers; ``refuse`` makes opening fail with that message."""

    def __init__(self):
        self.opened = []
        self.refuse = None

    def __call__(self, topic):
        if self.refuse:
            raise ValueError(self.refuse)
        publisher = Recorder(topic)
        self.opened.append(publisher)
        return publisher

    @property
    def current(self):
        return self.opened[-1]


class Recorder:
    def __init__(self, topic):
        self.topic = topic
        self.sent = []
        self.unregistered = False

    def publish(self, twist):
        assert not self.unregistered
        self.sent.append((twist.linear.x, twist.angular.z))

    def unregister(self):
        self.unregistered = True


@pytest.fixture(scope="module")
def app():
    # the platform as an argument, not in os.environ: the e2e tests' windows need the screen
    return QApplication.instance() or QApplication(["test_widget", "-platform", "offscreen"])


@pytest.fixture
def topics():
    return Topics()


@pytest.fixture
def window(app, topics):
    widget = SteeringWidget(Settings(), topics)
    widget._timer.stop()  # the tests tick by hand
    yield widget
    widget.shutdown()
    widget.deleteLater()


def test_starts_as_upstream(window, topics):
    assert window.windowTitle() == "Robot Steering"
    assert window.topic_line_edit.text() == "/cmd_vel"
    assert [p.topic for p in topics.opened] == ["/cmd_vel"]
    assert (window.x_linear_slider.minimum(), window.x_linear_slider.maximum()) == (-1000, 1000)
    assert (window.z_angular_slider.minimum(), window.z_angular_slider.maximum()) == (-3000, 3000)
    assert window.x_linear_slider.orientation() == Qt.Vertical
    assert window.z_angular_slider.orientation() == Qt.Horizontal
    assert window.z_angular_slider.invertedAppearance()  # left is positive, turning left
    assert (window.x_linear_slider.singleStep(), window.x_linear_slider.pageStep()) == (10, 100)
    assert window.max_x_linear_double_spin_box.value() == 1.0
    assert window.min_z_angular_double_spin_box.value() == -3.0
    assert window.current_x_linear_label.text() == "0.00 m/s"
    assert window.current_z_angular_label.text() == "0.00 rad/s"
    assert window.topic_error is None


def test_the_first_tick_sends_one_zero(window, topics):
    window.tick()
    window.tick()
    assert topics.current.sent == [(0.0, 0.0)]


def test_a_slider_publishes_at_once_and_at_every_tick(window, topics):
    window.x_linear_slider.setValue(300)
    assert window.current_x_linear_label.text() == "0.30 m/s"
    window.tick()
    window.tick()
    assert topics.current.sent == [(0.3, 0.0)] * 3
    window.z_angular_slider.setValue(-1250)
    assert window.current_z_angular_label.text() == "-1.25 rad/s"
    assert topics.current.sent[-1] == (0.3, -1.25)


def test_buttons_move_by_a_tenth(window, topics):
    QTest.mouseClick(window.increase_x_linear_push_button, Qt.LeftButton)
    QTest.mouseClick(window.increase_z_angular_push_button, Qt.LeftButton)
    QTest.mouseClick(window.increase_z_angular_push_button, Qt.LeftButton)
    assert (window.linear(), window.angular()) == pytest.approx((0.1, 0.2))
    QTest.mouseClick(window.decrease_z_angular_push_button, Qt.LeftButton)
    QTest.mouseClick(window.reset_x_linear_push_button, Qt.LeftButton)
    assert (window.linear(), window.angular()) == pytest.approx((0.0, 0.1))
    QTest.mouseClick(window.reset_z_angular_push_button, Qt.LeftButton)
    assert topics.current.sent[-1] == (0.0, 0.0)


def test_stop_zeroes_both_and_sends_zero_once(window, topics):
    window.x_linear_slider.setValue(500)
    window.z_angular_slider.setValue(1000)
    QTest.mouseClick(window.stop_push_button, Qt.LeftButton)
    assert (window.linear(), window.angular()) == (0.0, 0.0)
    # as upstream: the linear slider goes first, then the angular one
    assert topics.current.sent[-2:] == [(0.0, 1.0), (0.0, 0.0)]
    count = len(topics.current.sent)
    window.tick()
    window.tick()
    assert len(topics.current.sent) == count


def test_stop_at_zero_sends_another_zero(window, topics):
    window.tick()
    assert topics.current.sent == [(0.0, 0.0)]
    QTest.mouseClick(window.stop_push_button, Qt.LeftButton)
    QTest.mouseClick(window.stop_push_button, Qt.LeftButton)
    assert topics.current.sent == [(0.0, 0.0)] * 3


def test_range_boxes_set_the_slider_ends(window, topics):
    window.x_linear_slider.setValue(800)
    window.max_x_linear_double_spin_box.setValue(0.5)
    assert window.x_linear_slider.maximum() == 500
    assert window.linear() == 0.5  # the slider follows its new end, and says so
    assert topics.current.sent[-1] == (0.5, 0.0)
    window.min_z_angular_double_spin_box.setValue(-0.57)
    assert window.z_angular_slider.minimum() == -570
    window.max_z_angular_double_spin_box.setValue(12)  # beyond the box's range
    assert window.max_z_angular_double_spin_box.value() == 10.0
    assert window.z_angular_slider.maximum() == 10000


def test_settings_set_the_ranges(app, topics):
    widget = SteeringWidget(Settings("/robot/cmd_vel", 0.5, -0.2, 1.0, -1.5), topics)
    try:
        assert (widget.x_linear_slider.minimum(), widget.x_linear_slider.maximum()) == (-200, 500)
        angular = widget.z_angular_slider
        assert (angular.minimum(), angular.maximum()) == (-1500, 1000)
        assert widget.max_x_linear_double_spin_box.value() == 0.5
        assert [p.topic for p in topics.opened] == ["/robot/cmd_vel"]
    finally:
        widget.shutdown()


def test_a_new_topic_gets_a_new_publisher(window, topics):
    first = topics.current
    window.topic_line_edit.setText("/robot/cmd_vel")
    assert first.unregistered
    assert topics.current.topic == "/robot/cmd_vel"
    window.x_linear_slider.setValue(100)
    assert topics.current.sent == [(0.1, 0.0)]
    assert first.sent == []


def test_an_illegal_or_empty_topic_is_shown_and_publishes_nothing(window, topics):
    window.topic_line_edit.setText("cmd vel")
    assert topics.opened[0].unregistered and len(topics.opened) == 1
    assert "'cmd vel' is not a legal topic name" in window.topic_problem_label.text()
    assert not window.topic_problem_label.isHidden()
    window.topic_line_edit.setText("")
    assert "no topic" in window.topic_error
    window.x_linear_slider.setValue(100)
    window.tick()
    assert topics.opened[0].sent == []
    window.topic_line_edit.setText("/cmd_vel")
    assert window.topic_error is None and window.topic_problem_label.isHidden()
    window.tick()
    assert topics.current.sent == [(0.1, 0.0)]


def test_a_topic_that_cannot_be_opened_is_shown(window, topics):
    topics.refuse = "type clash"
    window.topic_line_edit.setText("/other")
    assert window.topic_error == "cannot publish on '/other': type clash"
    window.x_linear_slider.setValue(100)  # nothing to publish on, nothing breaks


def test_state_reports_values_and_places(window):
    window.show()
    window.x_linear_slider.setValue(-250)
    state = window.state()
    assert (state["linear"], state["linear_label"]) == (-0.25, "-0.25 m/s")
    assert state["ranges"] == {"vx_max": 1.0, "vx_min": -1.0, "vw_max": 3.0, "vw_min": -3.0}
    assert state["topic"] == "/cmd_vel" and state["published"] == 1
    for name in WIDGET_NAMES:
        if name != "topic_problem_label":  # hidden while the topic is fine
            assert len(state["widgets"][name]) == 4
    handle = state["widgets"]["x_linear_slider.handle"]
    slider = state["widgets"]["x_linear_slider"]
    assert slider[1] <= handle[1] and handle[1] + handle[3] <= slider[1] + slider[3]


def test_rqt_options_are_accepted():
    assert parse_arguments(["--force-discover"]) == ["--force-discover"]
    assert parse_arguments([]) == []
