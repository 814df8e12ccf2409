"""Debian bookworm's joint_state_publisher_gui (1.15.1) passes floats to
``QSlider.setValue``; the PyQt5 of Python 3.11 refuses them (``TypeError: setValue(self,
a0: int)``) and the GUI dies before it shows a slider. Older PyQt5 rounded them: this
restores that, for the process that calls it."""
from __future__ import annotations


def accept_float_slider_values() -> None:
    from python_qt_binding.QtWidgets import QSlider

    set_int_value = QSlider.setValue
    if getattr(set_int_value, "accepts_floats", False):
        return

    def set_value(slider, value):
        set_int_value(slider, int(round(value)))

    set_value.accepts_floats = True
    QSlider.setValue = set_value
