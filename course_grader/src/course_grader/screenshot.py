"""The windows of the virtual screen as a picture for the report: once a window with the
wanted title (rviz's) is shown, the other shown windows (the sliders) that cover it are
moved beside it (below it) so that neither hides the other, and ImageMagick's ``import
-window root`` takes screenshots of the screen, cropped to the windows, until one is
drawn (more than one colour: software GL on a busy machine draws its first frame late)
and the picture has stopped changing; the last one is kept. When no picture can be had,
the reason is returned instead: the grading goes on without it. No ROS here."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass
from typing import Dict, List, Optional, Tuple

COMMAND_TIMEOUT = 20.0   # s (wall): one xwininfo, xdotool, import, compare or convert call
REPORT_FILE = "display.png"   # rviz's screenshot, in the report's folder
# a line of ``xwininfo -root -children``, a top-level window: id, title, size, place on screen
#      0x400007 "display.rviz - RViz": ("rviz" "rviz")  1024x768+0+0  +0+0
WINDOW_LINE = re.compile(r'^\s*(0x[0-9a-f]+) "(.*)":.*?\s(\d+)x(\d+)[+-]-?\d+[+-]-?\d+'
                         r'\s+\+(-?\d+)\+(-?\d+)\s*$', re.MULTILINE)
SCREEN_SIZE = re.compile(r"Width: (\d+)\s+Height: (\d+)")


@dataclass
class Shot:
    """A screenshot taken (``path``) or why none was (``why``)."""

    path: str = ""
    why: str = ""
    colours: int = 0          # distinct colours in the picture
    seconds: float = 0.0      # from the call until the picture was kept
    settled: bool = False     # the picture had stopped changing
    windows: Tuple[str, ...] = ()   # the titles of the windows in it


@dataclass(frozen=True)
class Window:
    id: str
    title: str
    width: int
    height: int
    x: int
    y: int

    def overlaps(self, other: "Window") -> bool:
        return (self.x < other.x + other.width and other.x < self.x + self.width
                and self.y < other.y + other.height and other.y < self.y + self.height)


def _run(command, display: str = "") -> subprocess.CompletedProcess:
    env = dict(os.environ, DISPLAY=display) if display else None
    return subprocess.run(command, capture_output=True, text=True, check=False, env=env,
                          timeout=COMMAND_TIMEOUT)


def windows(display: str) -> List[Window]:
    """The screen's top-level windows that have a title and are shown (mapped)."""
    listed = _run(["xwininfo", "-display", display, "-root", "-children"]).stdout
    found = []
    for match in WINDOW_LINE.finditer(listed):
        state = _run(["xwininfo", "-display", display, "-id", match.group(1)]).stdout
        if "IsViewable" in state:
            found.append(Window(match.group(1), match.group(2), *map(int, match.group(3, 4, 5, 6))))
    return found


def find_window(display: str, title: str) -> Optional[Window]:
    """The largest shown window whose title holds ``title``."""
    found = [w for w in windows(display) if title in w.title]
    return max(found, key=lambda w: w.width * w.height) if found else None


def screen_size(display: str) -> Tuple[int, int]:
    info = _run(["xwininfo", "-display", display, "-root"]).stdout
    match = SCREEN_SIZE.search(info)
    if not match:
        raise RuntimeError(f"xwininfo gave no size of the screen {display}")
    return int(match.group(1)), int(match.group(2))


def arrange(display: str, main: Window, others: List[Window]) -> None:
    """Moves each window that covers part of ``main`` below it, side by side, so that both
    show (no window manager places them on a virtual screen: they all open at 0, 0)."""
    if shutil.which("xdotool") is None:
        return      # they stay where they are; the picture shows what is on top
    x = main.x
    for window in others:
        if window.overlaps(main):
            _run(["xdotool", "windowmove", window.id, str(x), str(main.y + main.height)],
                 display)
            x += window.width


def _crop(shown: List[Window], screen: Tuple[int, int]) -> str:
    """ImageMagick's geometry of the smallest rectangle holding ``shown``, on the screen."""
    left = max(0, min(w.x for w in shown))
    top = max(0, min(w.y for w in shown))
    right = min(screen[0], max(w.x + w.width for w in shown))
    bottom = min(screen[1], max(w.y + w.height for w in shown))
    return f"{right - left}x{bottom - top}+{left}+{top}"


def capture(display: str, path: str, crop: str = "") -> None:
    """``import -window root`` (what the screen shows), cropped to ``crop`` when given."""
    done = _run(["import", "-display", display, "-window", "root",
                 *(["-crop", crop, "+repage"] if crop else []), path])
    if done.returncode != 0:
        raise RuntimeError(f"import -window root failed: {done.stderr.strip()[:200]}")


def distinct_colours(path: str) -> int:
    done = _run(["convert", path, "-format", "%k", "info:"])
    if done.returncode != 0:
        raise RuntimeError(f"convert could not read {path}: {done.stderr.strip()[:200]}")
    return int(done.stdout.strip())


def size(path: str) -> tuple:
    done = _run(["convert", path, "-format", "%w %h", "info:"])
    if done.returncode != 0:
        raise RuntimeError(f"convert could not read {path}: {done.stderr.strip()[:200]}")
    width, height = done.stdout.split()
    return int(width), int(height)


def changed_fraction(first: str, second: str) -> float:
    """The fraction of pixels that differ between two pictures (all: of different sizes,
    a window resized between them)."""
    width, height = size(first)
    if size(second) != (width, height):
        return 1.0
    done = _run(["compare", "-metric", "AE", first, second, "null:"])
    if done.returncode not in (0, 1):     # 1: they differ
        raise RuntimeError(f"compare failed: {done.stderr.strip()[:200]}")
    return float(done.stderr.split()[0]) / (width * height)


def missing_tools() -> str:
    """What of Xvfb's clients and ImageMagick is not installed (empty when all are)."""
    absent = [tool for tool in ("xwininfo", "import", "convert", "compare")
              if shutil.which(tool) is None]
    return ", ".join(absent)


def take(display: str, path: str, window: str, spec: Dict) -> Shot:
    """A screenshot of the windows on ``display`` once a window titled ``window`` shows and
    the picture has settled (``spec``: ``timeout`` s, ``interval`` s between shots, ``settle`` shots in
    a row changed by at most ``change`` of the pixels), saved as ``path``."""
    started = time.monotonic()
    if not display:
        return Shot(why="no screen: the scenario runs without a virtual display")
    absent = missing_tools()
    if absent:
        return Shot(why=f"not installed: {absent} (x11-utils and imagemagick; tools/setup.sh "
                        "installs them)")
    deadline = started + spec["timeout"]
    while not find_window(display, window):
        if time.monotonic() > deadline:
            return Shot(why=f"no window titled '{window}' appeared within "
                            f"{spec['timeout']:g} s")
        time.sleep(spec["interval"])
    previous = path + ".previous.png"
    alike, colours, shown = 0, 0, []
    try:
        screen = screen_size(display)

        def shoot(target: str) -> List[Window]:
            """Arranges the windows, then captures them into ``target``."""
            main = find_window(display, window)
            if main is None:
                raise RuntimeError(f"the window titled '{window}' closed")
            arrange(display, main, [w for w in windows(display) if w.id != main.id])
            now_shown = windows(display)
            capture(display, target, _crop(now_shown, screen))
            return now_shown
        shoot(previous)
        while True:
            time.sleep(spec["interval"])
            shown = shoot(path)
            colours = distinct_colours(path)
            drawn = colours > 1
            alike = alike + 1 if drawn and \
                changed_fraction(previous, path) <= spec["change"] else 0
            shutil.copyfile(path, previous)
            if alike >= spec["settle"] or time.monotonic() > deadline:
                break
    except (RuntimeError, OSError, subprocess.TimeoutExpired) as error:
        _remove(path)
        return Shot(why=f"the screenshot failed: {error}")
    finally:
        _remove(previous)
    seconds = time.monotonic() - started
    if colours <= 1:
        _remove(path)
        return Shot(why=f"the windows stayed one colour for {seconds:.0f} s "
                        f"('{window}' drew nothing)", seconds=seconds)
    return Shot(path, colours=colours, seconds=seconds, settled=alike >= spec["settle"],
                windows=tuple(w.title for w in shown))


def _remove(path: str) -> None:
    try:
        os.remove(path)
    except FileNotFoundError:
        pass
