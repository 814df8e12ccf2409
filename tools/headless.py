"""Running the workspace's launch files as a user would, with no screen and no shared master.

Used by ``make demo`` and by the end-to-end tests in ``test/``:

- :func:`virtual_display` starts Xvfb on a free display and waits until it answers
  (:func:`screen_or_virtual`: only when there is no real screen);
- :func:`private_master` reserves a port, so a run never meets another run's roscore;
- :func:`roslaunch` starts a launch file with a log file and stops it (and its children);
- :func:`run_while_node_lives` starts it again when its rviz died of a signal while starting;
- :func:`launch_window` finds a window by title among those a launch's own processes opened;
- :func:`stable_screenshot` waits until a window is drawn and its picture stops changing;
- :func:`dark_pixels`, :func:`differing_pixels` and :func:`pixels_near` measure
  screenshots with ImageMagick.

Every wait has a timeout and says what it was waiting for when it runs out.
"""
from __future__ import annotations

import contextlib
import fcntl
import os
import shutil
import signal
import subprocess
import tempfile
import time
from typing import Callable, Dict, Iterator, List, Optional, Sequence, TypeVar

from course_grader.master_port import PortReservation
from course_grader.screenshot import windows as shown_windows
from course_grader.platform_faults import signal_deaths


T = TypeVar("T")

# rows at the bottom of the screen left out when waiting for a still picture
STATUS_BAR_ROWS = 40


class WaitTimeout(RuntimeError):
    """A condition did not come true in time; the message says which."""


def wait_until(condition, timeout: float, what: str, interval: float = 0.1):
    """Polls ``condition`` until it returns something true; raises :class:`WaitTimeout`."""
    deadline = time.monotonic() + timeout
    while True:
        result = condition()
        if result:
            return result
        if time.monotonic() > deadline:
            raise WaitTimeout(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(interval)


@contextlib.contextmanager
def private_master(ros_home: Optional[str] = None) -> Iterator[Dict[str, str]]:
    """An environment whose ROS_MASTER_URI points at a port reserved for this run until the
    block ends (roslaunch starts the master there: one found on the port would be used
    silently, see course_grader.master_port) and whose ROS_HOME (logs) is ``ros_home`` or a
    temporary folder."""
    with contextlib.ExitStack() as stack:
        if ros_home is None:
            ros_home = stack.enter_context(tempfile.TemporaryDirectory(prefix="ros_home_"))
        port = stack.enter_context(PortReservation()).port
        env = dict(os.environ)
        env["ROS_MASTER_URI"] = f"http://127.0.0.1:{port}"
        env["ROS_HOME"] = ros_home
        env["ROS_IP"] = "127.0.0.1"
        env.pop("ROS_HOSTNAME", None)
        yield env


XVFB_START_LOCK = "/tmp/.xvfb-start.lock"
# -noreset: by default Xvfb resets itself when its last client leaves, and a client that
# connects meanwhile is refused ("Can't open display"): an rviz started again after the
# first one died, or a window opened just after the last one closed, met it (2 refusals in
# 60 close-then-open pairs here; none with -noreset)
XVFB_OPTIONS = ("-noreset",)


@contextlib.contextmanager
def virtual_display(width: int = 1024, height: int = 768,
                    timeout: float = 20.0) -> Iterator[str]:
    """Starts Xvfb on a display it picks itself (``-displayfd``), one start or stop at a time
    across processes (XVFB_START_LOCK); yields the DISPLAY value."""
    if shutil.which("Xvfb") is None:
        raise RuntimeError("Xvfb is not installed; run 'make' to set up the workspace")
    read_end, write_end = os.pipe()
    # starts serialised across processes: two Xvfb choosing at once may take one display's
    # socket (course_grader's ros_run takes the same lock)
    with open(XVFB_START_LOCK, "a", encoding="utf-8") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_end), "-screen", "0", f"{width}x{height}x24",
             "-nolisten", "tcp", *XVFB_OPTIONS], pass_fds=(write_end,),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end) as announced:
            number = wait_until(lambda: announced.readline().strip() or server.poll() is not None,
                                timeout, "Xvfb to choose a display")
    try:
        if server.poll() is not None or not str(number).isdigit():
            raise RuntimeError(f"Xvfb exited with code {server.returncode}")
        display = f":{number}"
        wait_until(lambda: subprocess.run(["xdpyinfo", "-display", display],
                                          capture_output=True, check=False).returncode == 0,
                   timeout, f"Xvfb on {display}")
        yield display
    finally:
        # stopped under the start lock too: an Xvfb that is shutting down has given up its
        # display's lock file before it removes the display's socket, so one starting then
        # may take the number and lose its socket to the old server's clean-up (pybullet's
        # "cannot connect to X server :0" beside another lane's display stopping)
        with open(XVFB_START_LOCK, "a", encoding="utf-8") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            server.terminate()
            try:
                server.wait(timeout=10)
            except subprocess.TimeoutExpired:
                server.kill()
                server.wait()


def real_screen() -> bool:
    """True when DISPLAY names an X server that answers."""
    display = os.environ.get("DISPLAY")
    return bool(display) and subprocess.run(["xdpyinfo", "-display", display],
                                            capture_output=True, check=False).returncode == 0


def screen_or_virtual(who: str):
    """The real screen when there is one (a context yielding its DISPLAY), otherwise a
    :func:`virtual_display`, saying so as ``who``."""
    if real_screen():
        return contextlib.nullcontext(os.environ["DISPLAY"])
    print(f"{who}: no screen; rendering rviz under Xvfb", flush=True)
    return virtual_display()


class Launch:
    """A running ``roslaunch``; its output goes to ``log_path``."""

    def __init__(self, process: subprocess.Popen, log_path: str):
        self.process = process
        self.log_path = log_path

    def exited_early(self) -> RuntimeError:
        """The error for a launch that ended while a test still needed it: its exit code
        and the end of its log (the log file is gone with a CI machine)."""
        tail = self.output()[-3000:]
        return RuntimeError(f"roslaunch exited early with code {self.process.returncode}; "
                            f"{self.log_path} ends:\n{tail}")

    def output(self) -> str:
        with open(self.log_path, encoding="utf-8", errors="replace") as stream:
            return stream.read()

    def running(self) -> bool:
        return self.process.poll() is None

    def stop(self, timeout: float = 20.0) -> None:
        if self.process.poll() is not None:
            return
        # roslaunch shuts its nodes down on SIGINT, as on Ctrl-C
        os.killpg(self.process.pid, signal.SIGINT)
        try:
            self.process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()


@contextlib.contextmanager
def roslaunch(arguments: Sequence[str], env: Dict[str, str], log_path: str) -> Iterator[Launch]:
    """``roslaunch <arguments>`` in its own process group, stopped on exit."""
    port = env["ROS_MASTER_URI"].rsplit(":", 1)[1]
    command: List[str] = ["roslaunch", "-p", port, *arguments]
    with open(log_path, "w", encoding="utf-8") as log:
        process = subprocess.Popen(command, env=env, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
    launch = Launch(process, log_path)
    try:
        yield launch
    finally:
        launch.stop()


def died_of_signal(output: str, node: str) -> bool:
    """True when a launch's ``output`` says that its node ``node`` was killed by a signal
    (roslaunch's words, read as the grader reads them)."""
    return any(name.rsplit("-", 1)[0] == node
               for name, _, _ in signal_deaths(output.splitlines()))


# Debian's rviz, drawing in software under Xvfb, now and then aborts while it starts: a heap
# fault ("free(): invalid next size") in one CI run, Qt's "could not connect to display"
# with Xvfb answering in one of 30 starts here. Three starts make that one in thousands.
RVIZ_STARTS = 3


def run_while_node_lives(arguments: Sequence[str], env: Dict[str, str], log_path: str,
                         body: Callable[[Launch], T], node: str = "rviz",
                         starts: int = RVIZ_STARTS) -> T:
    """Runs ``body(launch)`` with ``roslaunch <arguments>`` up and returns what it returns.
    When it fails and the launch's ``node`` died of a signal meanwhile, says so and starts
    the launch again (logs ``<log>``, ``<log stem>-2<ext>``, ...), up to ``starts`` times;
    any other failure is raised at once."""
    stem, extension = os.path.splitext(log_path)
    start, log = 1, log_path
    while True:
        with roslaunch(arguments, env, log) as launch:
            try:
                return body(launch)
            except Exception:  # re-raised unless the node crashed and may start again
                if start == starts or not died_of_signal(launch.output(), node):
                    raise
        print(f"{node} died of a signal (see {log}); starting the launch again", flush=True)
        start += 1
        log = f"{stem}-{start}{extension}"


def launch_processes(launch: Launch) -> Dict[int, str]:
    """{pid: command line} of the launch's roslaunch and every process under it."""
    parents: Dict[int, int] = {}
    commands: Dict[int, str] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="utf-8", errors="replace") as stream:
                # pid (comm) state ppid ...: comm may hold spaces and brackets
                parents[int(entry)] = int(stream.read().rsplit(")", 1)[1].split()[1])
            with open(f"/proc/{entry}/cmdline", "rb") as stream:
                commands[int(entry)] = stream.read().replace(b"\0", b" ").decode(
                    errors="replace").strip()
        except (OSError, IndexError, ValueError):
            continue  # ended meanwhile
    found = {launch.process.pid}
    grew = True
    while grew:
        below = {pid for pid, parent in parents.items() if parent in found} - found
        found |= below
        grew = bool(below)
    return {pid: commands.get(pid, "") for pid in found}


def launch_window(display: str, title: str, launch: Launch) -> Optional[str]:
    """The id of a shown window whose title holds ``title`` and that a process of ``launch``
    opened (its _NET_WM_PID, which Qt sets), or None: a window of an earlier launch of the
    same file that lingers is not it. Titles are read by xwininfo (UTF-8: a Qt node's title
    holds an em dash, which ``xdotool search --name`` does not match across)."""
    ours = launch_processes(launch)
    for window in shown_windows(display):
        if title not in window.title:
            continue
        owner = subprocess.run(["xdotool", "getwindowpid", window.id],
                               env=dict(os.environ, DISPLAY=display), capture_output=True,
                               text=True, timeout=20, check=False)
        if owner.returncode == 0 and owner.stdout.strip().isdigit() \
                and int(owner.stdout) in ours:
            return window.id
    return None


def window_mapped(display: str, title: str) -> bool:
    tree = subprocess.run(["xwininfo", "-display", display, "-root", "-tree"],
                          capture_output=True, text=True, check=False).stdout
    return title in tree


def screenshot(display: str, path: str) -> str:
    subprocess.run(["import", "-display", display, "-window", "root", path],
                   check=True, capture_output=True)
    return path


def differing_pixels(first: str, second: str, fuzz: str = "3%", ignore_bottom: int = 0) -> int:
    """How many pixels differ between two images of the same size (leaving out the bottom
    ``ignore_bottom`` rows)."""
    if ignore_bottom:
        first, second = (_without_bottom(path, ignore_bottom) for path in (first, second))
    result = subprocess.run(["compare", "-metric", "AE", "-fuzz", fuzz, first, second,
                             "null:"], capture_output=True, text=True, check=False)
    if result.returncode not in (0, 1):
        raise RuntimeError(f"compare failed: {result.stderr.strip()}")
    return int(float(result.stderr.split()[0]))


def _without_bottom(path: str, rows: int) -> str:
    cropped = path + ".cropped.png"
    subprocess.run(["convert", path, "-gravity", "South", "-chop", f"0x{rows}", cropped],
                   check=True, capture_output=True)
    return cropped


def dark_pixels(path: str, threshold: str = "15%") -> int:
    """How many pixels are darker than ``threshold`` of full brightness."""
    result = subprocess.run(["convert", path, "-colorspace", "Gray", "-threshold", threshold,
                             "-negate", "-format", "%[fx:round(mean*w*h)]", "info:"],
                            capture_output=True, text=True, check=True)
    return int(result.stdout.strip())


def pixels_near(path: str, colour: str, fuzz: str = "15%") -> int:
    """How many pixels are within ``fuzz`` of ``colour`` (an ImageMagick colour)."""
    result = subprocess.run(["convert", path, "-fuzz", fuzz, "-fill", "black", "+opaque", colour,
                             "-fill", "white", "-opaque", colour, "-colorspace", "Gray",
                             "-format", "%[fx:round(mean*w*h)]", "info:"],
                            capture_output=True, text=True, check=True)
    return int(result.stdout.strip())


def uniform(path: str) -> bool:
    """True when every pixel of the picture has the same colour."""
    result = subprocess.run(["convert", path, "-format", "%[fx:standard_deviation]", "info:"],
                            capture_output=True, text=True, check=True)
    return float(result.stdout.strip()) == 0.0


def stable_screenshot(display: str, path: str, window_title: str, launch: Launch,
                      timeout: float = 90.0, settle: int = 3) -> str:
    """Waits for a window titled ``window_title`` (while ``launch`` keeps running), then
    takes screenshots until ``settle`` in a row are identical; returns ``path``. Any window
    of that title will do (pybullet's sets no _NET_WM_PID for :func:`launch_window`); a
    launch started again has stopped the earlier one's processes, windows with them."""
    def mapped():
        if not launch.running():
            raise launch.exited_early()
        return window_mapped(display, window_title)

    started = time.monotonic()
    wait_until(mapped, timeout, f"a window titled '{window_title}' on {display}", 0.25)
    previous = path + ".previous.png"
    same = 0
    screenshot(display, previous)

    def settled():
        nonlocal same
        if not launch.running():
            raise launch.exited_early()
        screenshot(display, path)
        # rviz's status bar shows a frame rate that changes when rendering is slow; a screen
        # of one colour is a window that has not drawn its first frame yet (software GL on a
        # busy machine), not a settled picture
        same = same + 1 if differing_pixels(previous, path, fuzz="0%",
                                            ignore_bottom=STATUS_BAR_ROWS) == 0 \
            and not uniform(path) else 0
        shutil.copyfile(path, previous)
        return same >= settle

    remaining = max(10.0, timeout - (time.monotonic() - started))
    wait_until(settled, remaining, f"the picture on {display} to stop changing", 0.5)
    for leftover in (previous, previous + ".cropped.png", path + ".cropped.png"):
        if os.path.exists(leftover):
            os.remove(leftover)
    return path
