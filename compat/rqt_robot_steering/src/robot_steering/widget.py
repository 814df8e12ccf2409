"""The steering window: Qt widgets only, no rospy (the node hands it a way to publish).

Laid out as rqt_robot_steering's plugin, with its widgets' object names: the topic field and
the stop button at the top; the vertical linear-velocity slider between its +/0/- buttons and
its range (maximum above, current value, minimum below); the horizontal angular-velocity
slider, left positive (counter-clockwise, as the robot turns), with its </0/> buttons and its
range (maximum on the left). Keys, anywhere in the window: W/S faster/slower by 0.01 and X
zero (linear), A/D left/right by 0.01 and Z zero (angular), with Shift by 0.1; Space stops.
The +, -, < and > buttons move by 0.1.

Everything the user does goes through :mod:`robot_steering.steering`: slider positions are
thousandths, and its :class:`~robot_steering.steering.CommandGate` decides what is published,
on every slider change and every 100 ms.
"""
from __future__ import annotations

from typing import Callable, Dict, List, Optional

from python_qt_binding.QtCore import QPoint, QRect, Qt, QTimer, Signal
from python_qt_binding.QtGui import QKeySequence
from python_qt_binding.QtWidgets import (QDoubleSpinBox, QHBoxLayout, QLabel, QLineEdit,
                                         QPushButton, QShortcut, QSlider, QStyle,
                                         QStyleOptionSlider, QVBoxLayout, QWidget)

from robot_steering.steering import (PAGE_STEP, PUBLISH_PERIOD, RANGE_DECIMALS, RANGE_LIMIT,
                                     RANGE_STEP, SINGLE_STEP, CommandGate, Settings,
                                     angular_label, linear_label, slider_position,
                                     slider_velocity, topic_problem)

WINDOW_TITLE = "Robot Steering"

# the widgets a test (or a curious user) may look up by object name
WIDGET_NAMES = (
    "topic_line_edit", "stop_push_button", "topic_problem_label",
    "x_linear_slider", "increase_x_linear_push_button", "reset_x_linear_push_button",
    "decrease_x_linear_push_button", "max_x_linear_double_spin_box",
    "min_x_linear_double_spin_box", "current_x_linear_label",
    "z_angular_slider", "increase_z_angular_push_button", "reset_z_angular_push_button",
    "decrease_z_angular_push_button", "max_z_angular_double_spin_box",
    "min_z_angular_double_spin_box", "current_z_angular_label",
)


class SteeringWidget(QWidget):
    """The window. ``open_topic(name)`` returns an object with ``publish(twist)`` and
    ``unregister()``, or raises an exception whose text says why it cannot."""

    # after every change the user makes and every tick of the publishing timer
    updated = Signal()

    def __init__(self, settings: Settings, open_topic: Callable[[str], object],
                 parent: Optional[QWidget] = None):
        super().__init__(parent)
        self.setObjectName("RobotSteeringUi")
        self.setWindowTitle(WINDOW_TITLE)
        self._open_topic = open_topic
        self._publisher = None
        self._gate = CommandGate()
        self.ticks = 0
        self.topic_error: Optional[str] = None
        self._build(settings)
        self._connect()
        self._add_shortcuts()
        self.topic_line_edit.setText(settings.topic)  # opens the publisher
        if not settings.topic:
            self._on_topic_changed("")  # no change of text, no signal: say there is no topic
        self._timer = QTimer(self)
        self._timer.timeout.connect(self.tick)
        self._timer.start(int(PUBLISH_PERIOD * 1000))
        self.resize(400, 344)
        # the keys work at once: with the topic field focused, W would type a W
        self.x_linear_slider.setFocus()

    # --- what the window shows -------------------------------------------------------

    def linear(self) -> float:
        """The linear velocity the slider stands at, m/s."""
        return slider_velocity(self.x_linear_slider.value())

    def angular(self) -> float:
        """The angular velocity the slider stands at, rad/s."""
        return slider_velocity(self.z_angular_slider.value())

    @property
    def published(self) -> int:
        """How many Twists the window has published."""
        return self._gate.published

    def state(self) -> Dict[str, object]:
        """What the window shows and where its widgets are on the screen (global pixel
        rectangles [x, y, width, height] of the visible ones; for the sliders also the handle
        and the groove)."""
        widgets = {name: _global_rect(getattr(self, name), getattr(self, name).rect())
                   for name in WIDGET_NAMES if getattr(self, name).isVisible()}
        for name in ("x_linear_slider", "z_angular_slider"):
            slider = getattr(self, name)
            widgets[name + ".handle"] = _global_rect(
                slider, _slider_part(slider, QStyle.SC_SliderHandle))
            widgets[name + ".groove"] = _global_rect(
                slider, _slider_part(slider, QStyle.SC_SliderGroove))
        return {
            "title": self.windowTitle(),
            "topic": self.topic_line_edit.text(),
            "topic_error": self.topic_error,
            "linear": self.linear(),
            "angular": self.angular(),
            "linear_label": self.current_x_linear_label.text(),
            "angular_label": self.current_z_angular_label.text(),
            "ranges": {"vx_max": self.max_x_linear_double_spin_box.value(),
                       "vx_min": self.min_x_linear_double_spin_box.value(),
                       "vw_max": self.max_z_angular_double_spin_box.value(),
                       "vw_min": self.min_z_angular_double_spin_box.value()},
            "ticks": self.ticks,
            "published": self.published,
            "widgets": widgets,
        }

    def shutdown(self) -> None:
        """Stops the timer and unregisters the publisher."""
        self._timer.stop()
        self._close_publisher()

    # --- building --------------------------------------------------------------------

    def _build(self, settings: Settings) -> None:
        self.topic_line_edit = QLineEdit()
        self.topic_line_edit.setToolTip("Topic the Twist messages are published on")
        self.stop_push_button = QPushButton("Stop")
        self.stop_push_button.setToolTip("Set both velocities to zero (Space)")
        self.topic_problem_label = QLabel()
        self.topic_problem_label.setStyleSheet("color: #b00000")
        self.topic_problem_label.setWordWrap(True)
        self.topic_problem_label.hide()

        self.x_linear_slider = _slider(Qt.Vertical, settings.vx_min, settings.vx_max)
        self.x_linear_slider.setTickPosition(QSlider.TicksBothSides)
        self.increase_x_linear_push_button = _button("+", "Faster forward by 0.1 (W: 0.01)")
        self.reset_x_linear_push_button = _button("0", "Linear velocity to zero (X)")
        self.decrease_x_linear_push_button = _button("-", "Faster backward by 0.1 (S: 0.01)")
        self.max_x_linear_double_spin_box = _range_box(
            "Maximum linear velocity, m/s", 0.0, RANGE_LIMIT, settings.vx_max)
        self.min_x_linear_double_spin_box = _range_box(
            "Minimum linear velocity, m/s", -RANGE_LIMIT, 0.0, settings.vx_min)
        self.current_x_linear_label = QLabel(linear_label(0.0))
        self.current_x_linear_label.setToolTip("Current linear velocity")

        self.z_angular_slider = _slider(Qt.Horizontal, settings.vw_min, settings.vw_max)
        self.z_angular_slider.setInvertedAppearance(True)  # left turns left: positive
        self.z_angular_slider.setTickPosition(QSlider.TicksBelow)
        self.increase_z_angular_push_button = _button("<", "Turn left faster by 0.1 (A: 0.01)")
        self.reset_z_angular_push_button = _button("0", "Angular velocity to zero (Z)")
        self.decrease_z_angular_push_button = _button(">", "Turn right faster by 0.1 (D: 0.01)")
        self.max_z_angular_double_spin_box = _range_box(
            "Maximum angular velocity (left), rad/s", 0.0, RANGE_LIMIT, settings.vw_max)
        self.min_z_angular_double_spin_box = _range_box(
            "Minimum angular velocity (right), rad/s", -RANGE_LIMIT, 0.0, settings.vw_min)
        self.current_z_angular_label = QLabel(angular_label(0.0))
        self.current_z_angular_label.setToolTip("Current angular velocity")

        for name in WIDGET_NAMES:
            getattr(self, name).setObjectName(name)

        top = QHBoxLayout()
        top.addWidget(self.topic_line_edit)
        top.addWidget(self.stop_push_button)

        linear_buttons = _column([self.increase_x_linear_push_button, None,
                                  self.reset_x_linear_push_button, None,
                                  self.decrease_x_linear_push_button])
        linear_range = _column([self.max_x_linear_double_spin_box, None,
                                self.current_x_linear_label, None,
                                self.min_x_linear_double_spin_box])
        linear = QHBoxLayout()
        linear.addStretch(1)
        linear.addLayout(linear_buttons)
        linear.addWidget(self.x_linear_slider)
        linear.addLayout(linear_range)
        linear.addStretch(1)

        angular_buttons = _row([self.increase_z_angular_push_button, None,
                                self.reset_z_angular_push_button, None,
                                self.decrease_z_angular_push_button])
        angular_range = _row([self.max_z_angular_double_spin_box, None,
                              self.current_z_angular_label, None,
                              self.min_z_angular_double_spin_box])

        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(self.topic_problem_label)
        layout.addLayout(linear, 1)
        layout.addWidget(self.z_angular_slider)
        layout.addLayout(angular_buttons)
        layout.addLayout(angular_range)

    def _connect(self) -> None:
        self.topic_line_edit.textChanged.connect(self._on_topic_changed)
        self.stop_push_button.pressed.connect(self._on_stop_pressed)
        self.x_linear_slider.valueChanged.connect(self._on_linear_changed)
        self.z_angular_slider.valueChanged.connect(self._on_angular_changed)

        linear, angular = self.x_linear_slider, self.z_angular_slider
        self.increase_x_linear_push_button.pressed.connect(lambda: _step(linear, PAGE_STEP))
        self.reset_x_linear_push_button.pressed.connect(lambda: linear.setValue(0))
        self.decrease_x_linear_push_button.pressed.connect(lambda: _step(linear, -PAGE_STEP))
        self.increase_z_angular_push_button.pressed.connect(lambda: _step(angular, PAGE_STEP))
        self.reset_z_angular_push_button.pressed.connect(lambda: angular.setValue(0))
        self.decrease_z_angular_push_button.pressed.connect(lambda: _step(angular, -PAGE_STEP))

        self.max_x_linear_double_spin_box.valueChanged.connect(
            lambda value: linear.setMaximum(slider_position(value)))
        self.min_x_linear_double_spin_box.valueChanged.connect(
            lambda value: linear.setMinimum(slider_position(value)))
        self.max_z_angular_double_spin_box.valueChanged.connect(
            lambda value: angular.setMaximum(slider_position(value)))
        self.min_z_angular_double_spin_box.valueChanged.connect(
            lambda value: angular.setMinimum(slider_position(value)))

    def _add_shortcuts(self) -> None:
        linear, angular = self.x_linear_slider, self.z_angular_slider
        keys = [
            (Qt.Key_W, lambda: _step(linear, SINGLE_STEP)),
            (Qt.SHIFT + Qt.Key_W, lambda: _step(linear, PAGE_STEP)),
            (Qt.Key_S, lambda: _step(linear, -SINGLE_STEP)),
            (Qt.SHIFT + Qt.Key_S, lambda: _step(linear, -PAGE_STEP)),
            (Qt.Key_X, lambda: linear.setValue(0)),
            (Qt.SHIFT + Qt.Key_X, lambda: linear.setValue(0)),
            (Qt.Key_A, lambda: _step(angular, SINGLE_STEP)),
            (Qt.SHIFT + Qt.Key_A, lambda: _step(angular, PAGE_STEP)),
            (Qt.Key_D, lambda: _step(angular, -SINGLE_STEP)),
            (Qt.SHIFT + Qt.Key_D, lambda: _step(angular, -PAGE_STEP)),
            (Qt.Key_Z, lambda: angular.setValue(0)),
            (Qt.SHIFT + Qt.Key_Z, lambda: angular.setValue(0)),
            (Qt.Key_Space, self._on_stop_pressed),
            (Qt.SHIFT + Qt.Key_Space, self._on_stop_pressed),
        ]
        self._shortcuts: List[QShortcut] = []
        for key, action in keys:
            shortcut = QShortcut(QKeySequence(key), self)
            shortcut.setContext(Qt.ApplicationShortcut)
            shortcut.activated.connect(action)
            self._shortcuts.append(shortcut)

    # --- behaviour ---------------------------------------------------------------------

    def _on_topic_changed(self, text) -> None:
        self._close_publisher()
        topic = str(text)
        problem = topic_problem(topic)
        if problem is None:
            try:
                self._publisher = self._open_topic(topic)
            except Exception as error:  # noqa: BLE001  (whatever it is, the user sees it)
                problem = f"cannot publish on '{topic}': {error}"
        self.topic_error = problem
        self.topic_problem_label.setText(problem or "")
        self.topic_problem_label.setVisible(problem is not None)
        self.updated.emit()

    def _on_stop_pressed(self) -> None:
        if self.x_linear_slider.value() == 0 and self.z_angular_slider.value() == 0:
            self._gate.stop_pressed()
            self._send()
            self.updated.emit()
        else:
            self.x_linear_slider.setValue(0)
            self.z_angular_slider.setValue(0)

    def _on_linear_changed(self, position: int) -> None:
        self.current_x_linear_label.setText(linear_label(slider_velocity(position)))
        self._send()
        self.updated.emit()

    def _on_angular_changed(self, position: int) -> None:
        self.current_z_angular_label.setText(angular_label(slider_velocity(position)))
        self._send()
        self.updated.emit()

    def tick(self) -> None:
        """What the publishing timer does every 100 ms: publish the current command."""
        self.ticks += 1
        self._send()
        self.updated.emit()

    def _send(self) -> None:
        if self._publisher is None:
            return
        twist = self._gate.offer(self.linear(), self.angular())
        if twist is not None:
            self._publisher.publish(twist)

    def _close_publisher(self) -> None:
        if self._publisher is not None:
            self._publisher.unregister()
            self._publisher = None


def _slider(orientation, low: float, high: float) -> QSlider:
    slider = QSlider(orientation)
    slider.setRange(slider_position(low), slider_position(high))
    slider.setSingleStep(SINGLE_STEP)
    slider.setPageStep(PAGE_STEP)
    slider.setValue(0)
    return slider


def _step(slider: QSlider, amount: int) -> None:
    slider.setValue(slider.value() + amount)


def _button(text: str, tip: str) -> QPushButton:
    button = QPushButton(text)
    button.setToolTip(tip)
    button.setMaximumWidth(30)
    return button


def _range_box(tip: str, low: float, high: float, value: float) -> QDoubleSpinBox:
    box = QDoubleSpinBox()
    box.setToolTip(tip)
    box.setDecimals(RANGE_DECIMALS)
    box.setRange(low, high)
    box.setSingleStep(RANGE_STEP)
    box.setValue(value)
    return box


def _column(items) -> QVBoxLayout:
    column = QVBoxLayout()
    for item in items:
        if item is None:
            column.addStretch(1)
        else:
            column.addWidget(item, 0, Qt.AlignHCenter)
    return column


def _row(items) -> QHBoxLayout:
    row = QHBoxLayout()
    for item in items:
        if item is None:
            row.addStretch(1)
        else:
            row.addWidget(item)
    return row


def _slider_part(slider: QSlider, part) -> QRect:
    option = QStyleOptionSlider()
    slider.initStyleOption(option)
    return slider.style().subControlRect(QStyle.CC_Slider, option, part, slider)


def _global_rect(widget: QWidget, rect: QRect) -> List[int]:
    corner = widget.mapToGlobal(rect.topLeft() if rect.isValid() else QPoint(0, 0))
    return [corner.x(), corner.y(), rect.width(), rect.height()]
