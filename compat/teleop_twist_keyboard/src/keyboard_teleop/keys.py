"""teleop_twist_keyboard's key map, as pure logic: a key press changes the commanded
direction or the speeds. No terminal, no ROS."""
from __future__ import annotations

from dataclasses import dataclass

# key -> (forward, turn), each -1, 0 or 1; times the current speeds
MOVES = {
    "i": (1, 0), ",": (-1, 0),
    "j": (0, 1), "l": (0, -1),
    "u": (1, 1), "o": (1, -1),
    "m": (-1, -1), ".": (-1, 1),
    "k": (0, 0),
}
# key -> (factor on the linear speed, factor on the angular speed)
SPEEDS = {
    "q": (1.1, 1.1), "z": (0.9, 0.9),
    "w": (1.1, 1.0), "x": (0.9, 1.0),
    "e": (1.0, 1.1), "c": (1.0, 0.9),
}

HELP = """Moving around:        Speeds:
   u    i    o          q/z : both speeds up/down by 10%
   j    k    l          w/x : linear speed only
   m    ,    .          e/c : angular speed only
k or any other key stops; Ctrl-C quits."""


@dataclass
class Teleop:
    linear_speed: float = 0.5   # m/s
    angular_speed: float = 1.0  # rad/s
    forward: int = 0
    turn: int = 0

    def press(self, key: str) -> None:
        if key in MOVES:
            self.forward, self.turn = MOVES[key]
        elif key in SPEEDS:
            linear, angular = SPEEDS[key]
            self.linear_speed *= linear
            self.angular_speed *= angular
        else:
            self.forward, self.turn = 0, 0

    @property
    def command(self):
        """(linear.x, angular.z) to publish."""
        return self.forward * self.linear_speed, self.turn * self.angular_speed

    def status(self) -> str:
        return (f"speed {self.linear_speed:.2f} m/s, turn {self.angular_speed:.2f} rad/s; "
                f"command linear {self.command[0]:+.2f}, angular {self.command[1]:+.2f}")
