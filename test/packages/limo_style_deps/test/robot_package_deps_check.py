#!/usr/bin/env python3
"""rostest node: a robot package's C++ speed loop (test/packages/limo_style_deps) on this
workspace's control_toolbox, realtime_tools, ackermann_msgs, dynamic_reconfigure and roslint.

- Each command it publishes (ackermann_msgs/AckermannDriveStamped, through a
  RealtimePublisher) is control_toolbox::Pid's formula for the errors sent, computed here
  independently (control_toolbox noetic-devel de05a5c src/pid.cpp l. 305-324 the derivative,
  l. 344-369 the terms: the integral's term clamped to [i_min, i_max] without antiwindup;
  l. 125-128 i_clamp's bounds), and the Pid's control_msgs/PidState on ~pid/state carries its
  terms (l. 372-391).
- `dynparam set` on the Pid's server (~pid, ParametersConfig) changes its gain and the next
  command follows the new gain; on the node's own SpeedLimit server it limits the command;
  `dynparam get` shows the gains Pid::init read (l. 149-152, 251-264).
- The package's Python dynamic_reconfigure server serves the same generated config.
- ackermann_msgs' and PidState's md5sums are upstream's (the subscriptions connect only when
  the C++ node's equal these).
- The package's roslint_cpp() made the target roslint_limo_style_deps, and it lints.
"""
import os
import subprocess
import threading
import unittest
import xmlrpc.client

import rosgraph
import rosnode
import rospkg
import rospy
import rostest
import yaml
from ackermann_msgs.msg import AckermannDriveStamped
from control_msgs.msg import PidState
from std_msgs.msg import Float64

NODE = "/speed_pid"
PID_NAMESPACE = NODE + "/pid"
PYTHON_SERVER = "/speed_limit_server"
# the launch file's settings: the loop's period and the Pid's gains under ~pid
PERIOD = 0.1
GAINS = {"p": 2.0, "i": 5.0, "d": 0.1, "i_clamp": 0.3}
TARGET = 1.0
MEASURED = (0.0, 0.2, 0.5, 0.8)  # a run-up: the integral's term reaches its clamp at once
NEW_P = 4.0
LIMIT = 0.5  # m/s, set on the node's own SpeedLimit config
PYTHON_DEFAULT_LIMIT = 1.5  # cfg/SpeedLimit.cfg's default
NEW_PYTHON_LIMIT = 2.5
# upstream's md5sums: genmsg on ros-drivers/ackermann_msgs 1.0.2 (843a483) and
# ros-controls/control_msgs 1.5.2 (kinetic-devel) msg files
ACKERMANN_DRIVE_STAMPED_MD5 = "1fd5d7f58889cefd44d29f6653240d0c"
PID_STATE_MD5 = "b138ec00e886c10e73f27e8712252ea6"
TIMEOUT = 10.0  # s, for any one reply
CONNECTION_POLL = 0.01  # s, between looks at a topic's connections
TOLERANCE = 1e-5  # the node's command crosses as float32 (AckermannDrive.speed)


class ReferencePid:
    """control_toolbox::Pid's computeCommand(error, dt) without antiwindup, as pid.cpp writes it."""

    def __init__(self, p, i, d, i_clamp):
        self.p, self.i, self.d = p, i, d
        self.i_max, self.i_min = abs(i_clamp), -abs(i_clamp)  # l. 125-128
        self.last_error = 0.0  # l. 197-201: after reset, the last error is a valid 0
        self.integral = 0.0

    def step(self, error, dt):
        error_dot = (error - self.last_error) / dt  # l. 316-317
        self.last_error = error
        self.integral += dt * error  # l. 347
        p_term = self.p * error  # l. 344
        i_term = min(max(self.i * self.integral, self.i_min), self.i_max)  # l. 357-363
        d_term = self.d * error_dot  # l. 366
        return {"error": error, "error_dot": error_dot, "p_term": p_term, "i_term": i_term,
                "d_term": d_term, "i_error": self.integral, "output": p_term + i_term + d_term}


class Inbox:
    """The messages of one topic, waited on by count."""

    def __init__(self, topic, message_type):
        self.messages = []
        self.condition = threading.Condition()
        self.subscriber = rospy.Subscriber(topic, message_type, self._receive)

    def _receive(self, message):
        with self.condition:
            self.messages.append(message)
            self.condition.notify_all()

    def wait_for(self, count):
        with self.condition:
            if not self.condition.wait_for(lambda: len(self.messages) >= count, TIMEOUT):
                raise AssertionError(f"{self.subscriber.name}: {len(self.messages)} messages "
                                     f"within {TIMEOUT} s, {count} wanted")
            return self.messages[count - 1]


def wait_for_connection(endpoint):
    """A publisher's or subscriber's first connection: messages sent before it are lost."""
    deadline = rospy.Time.now() + rospy.Duration(TIMEOUT)
    while endpoint.get_num_connections() == 0 and rospy.Time.now() < deadline:
        rospy.rostime.wallsleep(CONNECTION_POLL)
    assert endpoint.get_num_connections(), f"{endpoint.name}: speed_pid_node never connected"


def wait_until_received(node, topic, count):
    """Until ``node`` has received ``count`` messages on ``topic``, by the node's own bus
    statistics (roscpp's getBusStats: per subscription, per connection, the messages
    received). The node spins one queue, so a message received before another is handled
    before it: the latched target before the first measured speed (two topics are two
    connections, and nothing else orders them)."""
    api = rosnode.get_api_uri(rosgraph.Master(rospy.get_name()), node, skip_cache=True)
    server = xmlrpc.client.ServerProxy(api)
    deadline = rospy.Time.now() + rospy.Duration(TIMEOUT)
    received = 0
    while rospy.Time.now() < deadline:
        # roscpp answers [publications, subscriptions] itself, without rospy's code and
        # message around it
        subscriptions = server.getBusStats(rospy.get_name())[1]
        received = sum(connection[2] for name, connections in subscriptions
                       if name == topic for connection in connections)
        if received >= count:
            return
        rospy.rostime.wallsleep(CONNECTION_POLL)
    raise AssertionError(f"{node} received {received} of {count} messages on {topic} "
                         f"within {TIMEOUT} s")


def dynparam(*arguments):
    run = subprocess.run(["rosrun", "dynamic_reconfigure", "dynparam", *arguments],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         timeout=TIMEOUT)
    assert run.returncode == 0, f"dynparam {' '.join(arguments)}: {run.stdout}"
    return run.stdout


class RobotPackageDeps(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("robot_package_deps_check")
        cls.commands = Inbox("ackermann_cmd", AckermannDriveStamped)
        cls.states = Inbox(PID_NAMESPACE + "/state", PidState)
        cls.target = rospy.Publisher("target_speed", Float64, queue_size=1, latch=True)
        cls.measured = rospy.Publisher("measured_speed", Float64, queue_size=1)
        for endpoint in (cls.commands.subscriber, cls.states.subscriber, cls.target, cls.measured):
            wait_for_connection(endpoint)
        cls.target.publish(Float64(TARGET))
        wait_until_received(NODE, "/target_speed", 1)
        cls.reference = ReferencePid(**GAINS)
        cls.steps = 0

    def step(self, measured):
        """One control step; the node's command and PidState, and the reference's terms."""
        type(self).steps += 1
        self.measured.publish(Float64(measured))
        command = self.commands.wait_for(self.steps)
        state = self.states.wait_for(self.steps)
        return command, state, self.reference.step(TARGET - measured, PERIOD)

    def check_state(self, state, expected):
        for field, value in expected.items():
            self.assertAlmostEqual(getattr(state, field), value, delta=TOLERANCE, msg=field)
        self.assertAlmostEqual(state.timestep.to_sec(), PERIOD, delta=1e-9)
        self.assertEqual((state.i_max, state.i_min), (GAINS["i_clamp"], -GAINS["i_clamp"]))

    def test_1_commands_are_the_pid_formula(self):
        clamped = 0
        for measured in MEASURED:
            command, state, expected = self.step(measured)
            self.assertAlmostEqual(command.drive.speed, expected["output"], delta=TOLERANCE)
            self.check_state(state, expected)
            clamped += abs(expected["i_term"]) == GAINS["i_clamp"]
        self.assertGreater(clamped, 0, "the run never reached the integral's clamp")

    def test_2_dynparam_changes_the_gain(self):
        shown = yaml.safe_load(dynparam("get", PID_NAMESPACE))
        self.assertEqual({key: shown[key] for key in ("p", "i", "d", "i_clamp_max", "i_clamp_min")},
                         {"p": GAINS["p"], "i": GAINS["i"], "d": GAINS["d"],
                          "i_clamp_max": GAINS["i_clamp"], "i_clamp_min": -GAINS["i_clamp"]})
        dynparam("set", PID_NAMESPACE, "p", str(NEW_P))
        self.reference.p = NEW_P
        command, state, expected = self.step(MEASURED[-1])
        self.assertAlmostEqual(state.p_term, NEW_P * (TARGET - MEASURED[-1]), delta=TOLERANCE)
        self.assertAlmostEqual(command.drive.speed, expected["output"], delta=TOLERANCE)
        self.check_state(state, expected)

    def test_3_dynparam_limits_the_node(self):
        dynparam("set", NODE, "max_speed", str(LIMIT))
        command, state, expected = self.step(0.0)
        self.assertGreater(expected["output"], LIMIT)
        self.assertAlmostEqual(state.output, expected["output"], delta=TOLERANCE)
        self.assertAlmostEqual(command.drive.speed, LIMIT, delta=TOLERANCE)

    def test_python_server_serves_the_generated_config(self):
        limits = Inbox(PYTHON_SERVER + "/max_speed", Float64)
        self.assertAlmostEqual(limits.wait_for(1).data, PYTHON_DEFAULT_LIMIT)
        shown = yaml.safe_load(dynparam("get", PYTHON_SERVER))
        self.assertEqual((shown["max_speed"], shown["enabled"]), (PYTHON_DEFAULT_LIMIT, True))
        dynparam("set", PYTHON_SERVER, "max_speed", str(NEW_PYTHON_LIMIT))
        self.assertAlmostEqual(limits.wait_for(2).data, NEW_PYTHON_LIMIT)

    def test_md5sums_are_upstreams(self):
        self.assertEqual(AckermannDriveStamped._md5sum, ACKERMANN_DRIVE_STAMPED_MD5)
        self.assertEqual(PidState._md5sum, PID_STATE_MD5)
        self.commands.wait_for(1)  # connected: the C++ node's md5sum is the same

    def test_roslint_target_lints(self):
        """roslint_limo_style_deps's own rule, run as make runs it from catkin_make's build
        space (the package's folder there mirrors its place in the source space). Its
        build.make directly: the workspace's top Makefile would first re-run CMake for every
        package that changed since the last build."""
        devel = next(path for path in os.environ["CMAKE_PREFIX_PATH"].split(os.pathsep)
                     if os.path.isdir(os.path.join(path, "lib", "limo_style_deps")))
        build = os.path.join(os.path.dirname(devel), "build")
        with open(os.path.join(devel, ".catkin")) as sources:
            source_spaces = sources.read().split(";")
        package = rospkg.RosPack().get_path("limo_style_deps")
        source = next(space for space in source_spaces if package.startswith(space + os.sep))
        target = os.path.join(os.path.relpath(package, source), "CMakeFiles",
                              "roslint_limo_style_deps.dir")
        self.assertTrue(os.path.isdir(os.path.join(build, target)),
                        f"no target roslint_limo_style_deps in {build}")
        run = subprocess.run(["make", "-f", os.path.join(target, "build.make"),
                              os.path.join(target, "build")], cwd=build,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=TIMEOUT)
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertIn(f"Done processing {os.path.join(package, 'src', 'speed_pid_node.cpp')}",
                      run.stdout)

if __name__ == "__main__":
    rostest.rosrun("limo_style_deps", "robot_package_deps", RobotPackageDeps)
