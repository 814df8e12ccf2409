"""``rosrun turtlesim turtlesim_node``: the TurtleSim window as a ROS node named
``turtlesim``, with turtlesim 0.10.2's topics, services and parameters.

Upstream citations are ros/ros_tutorials noetic-devel (commit db63288), folder turtlesim/.

- In the node's namespace: the services ``clear``, ``reset``, ``spawn``, ``kill``
  (turtle_frame.cpp:105-108); private parameters ``~background_r``, ``~background_g``,
  ``~background_b``, set to 69, 86, 255 when absent (:64-75) and read at every clear.
- Per turtle, under its name: ``cmd_vel`` (geometry_msgs/Twist) in, ``pose`` and
  ``color_sensor`` out at every update, the services ``set_pen``, ``teleport_absolute``,
  ``teleport_relative`` (turtle.cpp:55-60); queues of 1 as upstream's.
- turtle1 in the middle at start (turtle_frame.cpp:114).

Threads: upstream runs every ROS callback inside its 16 ms Qt timer (``ros::spinOnce``,
turtle_frame.cpp:216-226). rospy calls back from its own threads, so here a callback only
queues its request; the timer's tick runs the queue in the GUI thread (where all Qt work
stays), then updates the turtles, then answers the services of that tick: a service call
returns once its effect is done (a teleport included), or fails after SERVICE_TIMEOUT
naming why.
"""
from __future__ import annotations

import math
import queue
import signal
import sys
import threading
import time
import traceback
from typing import Callable, Dict, List, Optional

import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, EmptyResponse
from turtlesim.msg import Color, Pose
from turtlesim.srv import (Kill, KillResponse, SetPen, SetPenResponse, Spawn, SpawnResponse,
                           TeleportAbsolute, TeleportAbsoluteResponse, TeleportRelative,
                           TeleportRelativeResponse)

from turtle_world.turtle import WALL_WARNING, Turtle
from turtle_world.world import (BACKGROUND_PARAMS, CLEARING, DEFAULT_BACKGROUND,
                                NAME_TAKEN, NO_SUCH_TURTLE, RESETTING, SPAWNING, STARTING,
                                UPDATE_MS, World, background_colour, spawn_problem,
                                teleport_problem)

# s (wall): the longest a service call waits for the window's tick to serve it
SERVICE_TIMEOUT = 10.0
# s: how often a warning about a bad cmd_vel is repeated while they keep coming
BAD_COMMAND_WARNING_PERIOD = 5.0


class Pending:
    """A service request waiting for the GUI thread: ``action`` is run there, its result
    or its ServiceException kept for the caller."""

    def __init__(self, action: Callable[[], object]):
        self.action = action
        self.done = threading.Event()
        self.result: object = None
        self.error: Optional[str] = None

    def run(self) -> None:
        try:
            self.result = self.action()
        except rospy.ServiceException as error:
            self.error = str(error)
        except Exception as error:  # pylint: disable=broad-except  (a fault of this node)
            rospy.logerr("turtlesim: a request failed:\n%s", traceback.format_exc())
            self.error = f"turtlesim failed to serve it: {error!r}"


class TurtleTopics:
    """One turtle's topics and services (turtle.cpp:55-60), under its name. ``turtle`` is
    the world's turtle they serve: reset hands turtle1's to the new turtle1 instead of
    closing and opening them again (rospy subscribers that connect while a node closes a
    topic and opens it again may never connect: mimic's would lose turtle1's pose).

    The name is a namespace (a node handle, turtle_frame.cpp:193), which roscpp remaps as a
    name (``turtle1:=robot`` moves all of turtle1's topics); rospy remaps whole names only,
    so the namespace is resolved (and remapped) here first."""

    def __init__(self, name: str, turtle: Turtle, sim: "Turtlesim"):
        self.name, self.turtle = name, turtle
        base = rospy.resolve_name(name)
        self.pose = rospy.Publisher(f"{base}/pose", Pose, queue_size=1)
        self.color = rospy.Publisher(f"{base}/color_sensor", Color, queue_size=1)
        self.cmd_vel = rospy.Subscriber(f"{base}/cmd_vel", Twist,
                                        lambda twist: sim.queue_command(self, twist),
                                        queue_size=1)
        self.services = [
            rospy.Service(f"{base}/set_pen", SetPen,
                          lambda req: sim.ask(lambda: sim.set_pen(self, req))),
            rospy.Service(f"{base}/teleport_relative", TeleportRelative,
                          lambda req: sim.ask(lambda: sim.teleport_relative(self, req))),
            rospy.Service(f"{base}/teleport_absolute", TeleportAbsolute,
                          lambda req: sim.ask(lambda: sim.teleport_absolute(self, req))),
        ]

    def publish(self, pose, colour) -> None:
        self.pose.publish(Pose(*pose))
        self.color.publish(Color(*colour))

    def close(self) -> None:
        self.cmd_vel.unregister()
        self.pose.unregister()
        self.color.unregister()
        for service in self.services:
            service.shutdown()


class Turtlesim:
    """The node: the world, the window, the turtles' topics, and the queue between rospy's
    threads and the window's."""

    def __init__(self, world: World, canvas):
        self.world, self.canvas = world, canvas
        self._queue: "queue.Queue" = queue.Queue()
        self._topics: Dict[str, TurtleTopics] = {}
        self._last_bad_command = -math.inf
        self.clear_background()
        self._services = [
            rospy.Service("clear", Empty, lambda req: self.ask(self.clear)),
            rospy.Service("reset", Empty, lambda req: self.ask(self.reset)),
            rospy.Service("spawn", Spawn, self._spawn_request),
            rospy.Service("kill", Kill, lambda req: self.ask(lambda: self.kill(req.name))),
        ]
        rospy.loginfo(STARTING, rospy.get_name())
        self.spawn("", *world.centre(), 0.0)

    # --- rospy's threads ------------------------------------------------------------------

    def ask(self, action: Callable[[], object]):
        """Runs ``action`` in the window's next tick and returns what it returns (a
        service's response); a ServiceException when it refuses or no tick comes."""
        pending = Pending(action)
        self._queue.put(pending)
        if not pending.done.wait(SERVICE_TIMEOUT):
            raise rospy.ServiceException(
                f"the TurtleSim window did not serve the request within {SERVICE_TIMEOUT:.0f} s "
                "(is the node shutting down?)")
        if pending.error is not None:
            raise rospy.ServiceException(pending.error)
        return pending.result

    def queue_command(self, topics: TurtleTopics, twist: Twist) -> None:
        self._queue.put((topics, twist))

    def _spawn_request(self, req):
        problem = spawn_problem(req.name, req.x, req.y, req.theta)
        if problem:
            rospy.logerr("spawn: %s", problem)
            raise rospy.ServiceException(f"spawn: {problem}")
        return self.ask(lambda: SpawnResponse(self.spawn(req.name, req.x, req.y, req.theta)))

    # --- the window's thread: the services' actions ----------------------------------------

    def clear_background(self) -> None:
        colour, warnings = background_colour(rospy.get_param)
        for warning in warnings:
            rospy.logwarn(warning)
        self.canvas.clear(colour)

    def clear(self) -> EmptyResponse:
        rospy.loginfo(CLEARING)
        self.clear_background()
        return EmptyResponse()

    def reset(self) -> EmptyResponse:
        """turtle_frame.cpp:273-281: every turtle removed, turtle1 in the middle, cleared."""
        rospy.loginfo(RESETTING)
        name = self.world.reset()
        kept = self._topics.pop(name, None)
        for topics in self._topics.values():
            topics.close()
        self._topics.clear()
        if kept is not None:
            kept.turtle = self.world.turtles[name]
        self._add(name, *self.world.centre(), 0.0, kept)
        self.clear_background()
        return EmptyResponse()

    def spawn(self, name: str, x: float, y: float, theta: float) -> str:
        real_name = self.world.spawn(name, x, y, theta)
        if real_name is None:
            rospy.logerr(NAME_TAKEN, name)
            raise rospy.ServiceException(
                f"a turtle named '{name}' already exists; kill it first, or leave the name "
                "empty for a new one")
        self._add(real_name, x, y, theta)
        return real_name

    def _add(self, name: str, x: float, y: float, theta: float,
             topics: Optional[TurtleTopics] = None) -> None:
        """The topics and services of the world's new turtle ``name`` (``topics``: those
        it takes over)."""
        self._topics[name] = topics or TurtleTopics(name, self.world.turtles[name], self)
        self.show_turtles()
        rospy.loginfo(SPAWNING, name, x, y, theta)

    def kill(self, name: str) -> KillResponse:
        if not self.world.kill(name):
            rospy.logerr(NO_SUCH_TURTLE, name)
            raise rospy.ServiceException(
                f"there is no turtle named '{name}' (there are: {', '.join(sorted(self._topics))})")
        self._topics.pop(name).close()
        self.show_turtles()
        return KillResponse()

    def _alive(self, topics: TurtleTopics) -> Turtle:
        if self._topics.get(topics.name) is not topics:
            raise rospy.ServiceException(f"turtle '{topics.name}' was killed meanwhile")
        return topics.turtle

    def set_pen(self, topics: TurtleTopics, req) -> SetPenResponse:
        self._alive(topics).set_pen(req.r, req.g, req.b, req.width, req.off)
        return SetPenResponse()

    def teleport_absolute(self, topics: TurtleTopics, req) -> TeleportAbsoluteResponse:
        turtle = self._alive(topics)
        problem = teleport_problem(x=req.x, y=req.y, theta=req.theta)
        if problem:
            raise rospy.ServiceException(f"{topics.name}/teleport_absolute: {problem}")
        turtle.teleport_absolute(req.x, req.y, req.theta)
        return TeleportAbsoluteResponse()

    def teleport_relative(self, topics: TurtleTopics, req) -> TeleportRelativeResponse:
        turtle = self._alive(topics)
        problem = teleport_problem(linear=req.linear, angular=req.angular)
        if problem:
            raise rospy.ServiceException(f"{topics.name}/teleport_relative: {problem}")
        turtle.teleport_relative(req.linear, req.angular)
        return TeleportRelativeResponse()

    # --- the window's thread: the tick ------------------------------------------------------

    def _command(self, topics: TurtleTopics, twist: Twist, now: float) -> None:
        if self._topics.get(topics.name) is not topics:
            return  # killed since it was sent
        values = (twist.linear.x, twist.linear.y, twist.angular.z)
        if not all(math.isfinite(v) for v in values):
            if now - self._last_bad_command > BAD_COMMAND_WARNING_PERIOD:
                self._last_bad_command = now
                rospy.logwarn("cmd_vel: linear.x, linear.y, angular.z = %s: not finite; the "
                              "command is ignored", values)
            return
        topics.turtle.command(*values, now)

    def tick(self) -> None:
        """One 16 ms tick: the queued callbacks, then one update of every turtle
        (turtle_frame.cpp:216-263), then the answers to this tick's services."""
        now = time.monotonic()
        served: List[Pending] = []
        for item in self._queued():
            if isinstance(item, Pending):
                item.run()
                served.append(item)
            else:
                self._command(*item, now)
        modified = False
        for name, step in self.world.tick(now):
            self.canvas.draw(step.teleport_lines)
            if step.clamped_from is not None:
                rospy.logwarn(WALL_WARNING, *step.clamped_from)
            self._topics[name].publish(step.pose, self.canvas.colour_at(step.sensor))
            if step.motion_line is not None:
                self.canvas.draw([step.motion_line])
            modified |= step.modified
        if modified:
            self.show_turtles()
        for pending in served:
            pending.done.set()

    def show_turtles(self) -> None:
        self.canvas.show_turtles((t.x, t.y, t.orient, t.look)
                                 for _, t in sorted(self.world.turtles.items()))

    def _queued(self):
        """What rospy's callbacks queued, oldest first, until the queue is empty."""
        while True:
            try:
                yield self._queue.get_nowait()
            except queue.Empty:
                return

    def shutdown(self) -> None:
        """Answers what is still queued with an error (the window is closing)."""
        for item in self._queued():
            if isinstance(item, Pending):
                item.error = "turtlesim is shutting down"
                item.done.set()


def main(argv: Optional[List[str]] = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    # Qt first, as upstream (turtlesim.cpp:41-45): without a display it stops here, with Qt's
    # own message
    from python_qt_binding.QtCore import QTimer
    from python_qt_binding.QtWidgets import QApplication

    from turtle_world.canvas import TurtleCanvas

    app = QApplication(argv)
    rospy.init_node("turtlesim", argv=argv, disable_signals=True)
    for name, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND):
        if not rospy.has_param(name):
            rospy.set_param(name, default)
    canvas = TurtleCanvas()
    sim = Turtlesim(World(), canvas)
    canvas.show()

    for number in (signal.SIGINT, signal.SIGTERM):
        signal.signal(number, lambda *_: app.quit())

    def tick():
        try:
            sim.tick()
        except Exception:  # pylint: disable=broad-except  (PyQt would abort the process)
            rospy.logerr("turtlesim: an update failed; the window goes on:\n%s",
                         traceback.format_exc())
        if rospy.is_shutdown():  # turtle_frame.cpp:222-225
            app.quit()

    timer = QTimer()  # its ticks also let Python run the signal handlers
    timer.timeout.connect(tick)
    timer.start(UPDATE_MS)
    try:
        app.exec_()
    finally:
        timer.stop()
        sim.shutdown()
        rospy.signal_shutdown("window closed")
    return 0

