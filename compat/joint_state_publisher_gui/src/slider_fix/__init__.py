"""joint_state_publisher_gui on Python 3.11's PyQt5: Debian's node with QSlider patched."""
