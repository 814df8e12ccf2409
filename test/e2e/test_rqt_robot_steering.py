"""``rosrun rqt_robot_steering rqt_robot_steering`` as the course has students type it: the
window under Xvfb with a private master, moved with real mouse and keyboard input (xdotool),
and what it publishes read back with ``rostopic echo``.

The window tells where its widgets are and what its sliders say through its test hook
(``ROBOT_STEERING_STATE_FILE``, see robot_steering.node); the input itself is the X server's.
"""
import contextlib
import json
import os
import signal
import subprocess
import threading

import pytest

import headless

TITLE = "Robot Steering"
WAIT = 30.0  # s, the longest any one condition may take to come true


@pytest.fixture
def master(screen_env):
    port = screen_env["ROS_MASTER_URI"].rsplit(":", 1)[1]
    core = subprocess.Popen(["roscore", "-p", port], env=screen_env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.STDOUT, start_new_session=True)
    try:
        def answering():
            return subprocess.run(["rosnode", "list"], env=screen_env, capture_output=True,
                                  check=False).returncode == 0
        headless.wait_until(answering, WAIT, "the master")
        yield screen_env
    finally:
        core.terminate()
        core.wait(timeout=20)


class Echo:
    """``rostopic echo -p <topic>`` in the background: ``messages`` holds (receive time in s,
    linear.x, angular.z) for every Twist, and fails a test on any other component."""

    def __init__(self, env, topic):
        self.messages = []
        self._lock = threading.Lock()
        self.process = subprocess.Popen(
            ["rostopic", "echo", "-p", topic], env=dict(env, PYTHONUNBUFFERED="1"),
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, start_new_session=True)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.process.stdout:
            fields = line.strip().split(",")
            if len(fields) != 7 or not fields[0].isdigit():
                continue  # the header, or rostopic's notes
            stamp, lx, ly, lz, ax, ay, az = (float(f) for f in fields)
            assert (ly, lz, ax, ay) == (0.0, 0.0, 0.0, 0.0), line
            with self._lock:
                self.messages.append((stamp * 1e-9, lx, az))

    def since(self, start):
        """The (linear.x, angular.z) pairs received from index ``start`` on."""
        with self._lock:
            return [(lx, az) for _, lx, az in self.messages[start:]]

    def count(self):
        with self._lock:
            return len(self.messages)

    def stamps(self, start):
        with self._lock:
            return [stamp for stamp, _, _ in self.messages[start:]]

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


class Steering:
    """The window, started with rosrun as a user does."""

    def __init__(self, env, results_dir, *arguments):
        self.env = env
        self.display = env["DISPLAY"]
        self.state_path = os.path.join(results_dir, "steering_state.json")
        if os.path.exists(self.state_path):
            os.remove(self.state_path)
        self.log_path = os.path.join(results_dir, "rqt_robot_steering.log")
        with open(self.log_path, "w", encoding="utf-8") as log:
            self.process = subprocess.Popen(
                ["rosrun", "rqt_robot_steering", "rqt_robot_steering", *arguments],
                env=dict(env, ROBOT_STEERING_STATE_FILE=self.state_path), stdout=log,
                stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)

    def log(self):
        with open(self.log_path, encoding="utf-8", errors="replace") as stream:
            return stream.read()

    def state(self):
        if self.process.poll() is not None:
            raise RuntimeError(f"rqt_robot_steering exited with {self.process.returncode}:\n"
                               + self.log())
        try:
            with open(self.state_path, encoding="utf-8") as stream:
                return json.load(stream)
        except FileNotFoundError:
            return None

    def wait(self, condition, what):
        """Waits until ``condition(state)`` is true; returns that state."""
        def check():
            state = self.state()
            return state if state is not None and condition(state) else None
        return headless.wait_until(check, WAIT, what)

    def wait_shown(self):
        headless.wait_until(lambda: self.state() is not None
                            and headless.window_mapped(self.display, TITLE),
                            WAIT, f"the '{TITLE}' window")
        return self.wait(lambda s: s["ticks"] >= 1, "the window's first tick")

    def widget(self, name):
        return self.state()["widgets"][name]

    def centre(self, name):
        x, y, width, height = self.widget(name)
        return x + width // 2, y + height // 2

    # --- real input ---------------------------------------------------------------------

    def xdotool(self, *arguments):
        subprocess.run(["xdotool", *map(str, arguments)], env=self.env, check=True,
                       capture_output=True, timeout=20)

    def click(self, name):
        x, y = self.centre(name)
        self.xdotool("mousemove", x, y, "click", "1")

    def keys(self, *keys):
        self.xdotool("key", "--delay", "30", *keys)

    def type(self, text):
        self.xdotool("type", "--delay", "30", text)

    def drag_handle(self, slider, to_x, to_y):
        x, y = self.centre(slider + ".handle")
        middle_x, middle_y = (x + to_x) // 2, (y + to_y) // 2
        self.xdotool("mousemove", x, y, "mousedown", "1", "mousemove", middle_x, middle_y,
                     "mousemove", to_x, to_y, "mouseup", "1")

    def close(self, timeout=30.0):
        """Ctrl-C, as in the terminal; returns the exit status."""
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGINT)
        try:
            return self.process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()
            raise


@contextlib.contextmanager
def steering(env, results_dir, *arguments):
    window = Steering(env, results_dir, *arguments)
    try:
        yield window
    finally:
        if window.process.poll() is None:
            with contextlib.suppress(subprocess.TimeoutExpired):
                window.close()


@contextlib.contextmanager
def echo(env, topic):
    listener = Echo(env, topic)
    try:
        yield listener
    finally:
        listener.stop()


def wait_for_message(listener, start, message, what):
    """Waits until ``message`` (linear.x, angular.z) is received after index ``start``;
    returns the index just past it."""
    def received():
        for index, got in enumerate(listener.since(start)):
            if got == pytest.approx(message, abs=1e-9):
                return start + index + 1
        return None
    return headless.wait_until(received, WAIT, f"{what}: {message} on the topic")


def test_sliders_drive_cmd_vel(master, results_dir):
    with echo(master, "/cmd_vel") as cmd_vel, steering(master, results_dir) as window:
        shown = window.wait_shown()
        assert shown["topic"] == "/cmd_vel" and shown["topic_error"] is None
        assert shown["ranges"] == {"vx_max": 1.0, "vx_min": -1.0, "vw_max": 3.0, "vw_min": -3.0}
        assert (shown["linear"], shown["angular"]) == (0.0, 0.0)

        # keys, after a click that makes the window the active one (there is no window
        # manager to do it): Shift+W three times is 0.3 m/s, A five times 0.05 rad/s
        window.click("current_x_linear_label")
        start = cmd_vel.count()
        window.keys("shift+w", "shift+w", "shift+w")
        state = window.wait(lambda s: s["linear"] == pytest.approx(0.3), "linear 0.3 m/s")
        assert state["linear_label"] == "0.30 m/s"
        # repeated while not zero, every 100 ms
        headless.wait_until(lambda: cmd_vel.since(start).count((0.3, 0.0)) >= 12, WAIT,
                            "twelve commands of 0.3 m/s")
        stamps = [t for t, (lx, az) in zip(cmd_vel.stamps(start), cmd_vel.since(start))
                  if (lx, az) == (0.3, 0.0)]
        gaps = sorted(later - earlier for earlier, later in zip(stamps, stamps[1:]))
        assert 0.07 < gaps[len(gaps) // 2] < 0.15, gaps

        window.keys(*["a"] * 5)
        window.wait(lambda s: s["angular"] == pytest.approx(0.05), "angular 0.05 rad/s")
        start = wait_for_message(cmd_vel, start, (0.3, 0.05), "after A five times")

        # the mouse: the angular handle to the far left is the maximum, turning left
        groove = window.widget("z_angular_slider.groove")
        window.drag_handle("z_angular_slider", max(0, groove[0] - 10),
                           window.centre("z_angular_slider")[1])
        state = window.wait(lambda s: s["angular"] == 3.0, "angular at its maximum, 3 rad/s")
        assert state["angular_label"] == "3.00 rad/s"
        start = wait_for_message(cmd_vel, start, (0.3, 3.0), "after the angular drag")

        # the linear handle three quarters down its groove: whatever the slider says
        x, top, _, height = window.widget("x_linear_slider.groove")
        window.drag_handle("x_linear_slider", window.centre("x_linear_slider")[0],
                           top + (3 * height) // 4)
        # (half-way, where the drag passes, is about -0.1 m/s)
        state = window.wait(lambda s: s["linear"] < -0.35, "a backward linear velocity")
        linear = state["linear"]
        assert -0.65 < linear < -0.35
        assert state["linear_label"] == f"{linear:.2f} m/s"
        start = wait_for_message(cmd_vel, start, (linear, 3.0), "the dragged linear velocity")

        # the range: maximum linear 0.25 typed into its box, then Shift+W up to it
        window.click("max_x_linear_double_spin_box")
        window.keys("ctrl+a")
        window.type("0.25")
        window.keys("Return")
        window.wait(lambda s: s["ranges"]["vx_max"] == 0.25, "the maximum linear velocity 0.25")
        window.click("x_linear_slider.handle")  # the keys go to the window, not the box
        window.keys(*["shift+w"] * 10)
        state = window.wait(lambda s: s["linear"] == 0.25, "linear held at its new maximum")
        assert state["linear_label"] == "0.25 m/s"
        start = wait_for_message(cmd_vel, start, (0.25, 3.0), "at the new maximum")

        # stop: both to zero, the linear one first, and the zero is sent once
        window.click("stop_push_button")
        stopped = wait_for_message(cmd_vel, start, (0.0, 0.0), "after Stop")
        assert cmd_vel.since(stopped - 2)[0] == (0.0, 3.0)
        state = window.wait(lambda s: (s["linear"], s["angular"]) == (0.0, 0.0),
                            "both sliders at zero")
        assert (state["linear_label"], state["angular_label"]) == ("0.00 m/s", "0.00 rad/s")
        ticks = state["ticks"]
        window.wait(lambda s: s["ticks"] >= ticks + 10, "ten ticks (one second) after Stop")
        assert cmd_vel.since(stopped) == []
        # Stop with the sliders at zero sends one more zero
        window.click("stop_push_button")
        wait_for_message(cmd_vel, stopped, (0.0, 0.0), "after Stop at zero")
        headless.screenshot(window.display, os.path.join(results_dir, "rqt_robot_steering.png"))

        assert window.close() == 0
        assert "Traceback" not in window.log()


def test_private_parameters_and_the_topic_field(master, results_dir):
    with echo(master, "/robot/cmd_vel") as robot, echo(master, "/steer") as steer, \
            steering(master, results_dir, "_default_topic:=/robot/cmd_vel",
                     "_default_vx_max:=0.5", "_default_vw_min:=-1.5") as window:
        shown = window.wait_shown()
        assert shown["topic"] == "/robot/cmd_vel"
        assert shown["ranges"] == {"vx_max": 0.5, "vx_min": -1.0, "vw_max": 3.0, "vw_min": -1.5}

        window.click("current_x_linear_label")
        window.keys(*["shift+w"] * 8, *["shift+d"] * 20)
        window.wait(lambda s: (s["linear"], s["angular"]) == (0.5, -1.5),
                    "both sliders at their ends: 0.5 m/s, -1.5 rad/s")
        wait_for_message(robot, 0, (0.5, -1.5), "on the parameter's topic")

        # a new topic typed in the field: the command goes there from then on
        window.click("topic_line_edit")
        window.keys("ctrl+a")
        window.type("/steer")
        window.wait(lambda s: s["topic"] == "/steer" and s["topic_error"] is None,
                    "the topic /steer")
        wait_for_message(steer, 0, (0.5, -1.5), "on the typed topic")

        # an illegal name is shown, not fatal
        window.type(" x")
        state = window.wait(lambda s: s["topic_error"] is not None, "the topic's problem shown")
        assert "'/steer x' is not a legal topic name" in state["topic_error"]
        assert "topic_problem_label" in state["widgets"]

        assert window.close() == 0
        assert "Traceback" not in window.log()


def test_without_a_master_it_says_so(ros_env):
    result = subprocess.run(["rosrun", "rqt_robot_steering", "rqt_robot_steering"],
                            env=ros_env, capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 1
    assert "no ROS master at" in result.stderr and "start roscore" in result.stderr
