"""turtle_world.teleop_keys (and the terminal mode of turtle_world.teleop_node):
turtle_teleop_key's keys as tutorials/teleop_turtle_key.cpp (ros_tutorials noetic-devel
db63288) reads them."""
import termios

import pytest

from turtle_world.teleop_keys import DEFAULT_SCALE, HELP, QUIT, command
from turtle_world.teleop_node import key_mode

ESC = 0x1B


@pytest.mark.parametrize("key, move", [
    (b"A", (2.0, 0.0)), (b"B", (-2.0, 0.0)), (b"D", (0.0, 2.0)), (b"C", (0.0, -2.0))])
def test_arrow_keys_by_the_last_byte_of_their_sequence(key, move):
    assert command(key[0]) == move  # teleop_turtle_key.cpp:12-15, :232-251, scales 2.0


def test_an_arrow_keys_whole_sequence_publishes_once():
    moves = [command(byte) for byte in b"\x1b[A"]
    assert moves == [None, None, (2.0, 0.0)]


def test_scales_multiply():
    assert command(b"A"[0], scale_linear=0.5, scale_angular=3.0) == (0.5, 0.0)
    assert command(b"D"[0], scale_linear=0.5, scale_angular=3.0) == (0.0, 3.0)


@pytest.mark.parametrize("key", [b"a", b"w", b" ", b"q", bytes([ESC]), b"["])
def test_other_keys_publish_nothing(key):
    assert command(key[0]) is None


def test_quit_key_and_words():
    assert QUIT == ord("q")
    assert DEFAULT_SCALE == 2.0
    assert HELP.splitlines() == ["Reading from keyboard", "---------------------------",
                                 "Use arrow keys to move the turtle. 'q' to quit."]


def test_key_mode_stops_echo_and_line_editing_but_keeps_ctrl_c():
    cooked = [termios.BRKINT, termios.OPOST, termios.CS8,
              termios.ICANON | termios.ECHO | termios.ISIG, 0, 0,
              [b"\x00"] * 32]
    raw = key_mode(cooked)
    assert not raw[3] & (termios.ICANON | termios.ECHO)
    assert raw[3] & termios.ISIG
    assert (raw[6][termios.VMIN], raw[6][termios.VTIME]) == (1, 0)
    assert cooked[3] & termios.ICANON  # the saved settings are left as they were
