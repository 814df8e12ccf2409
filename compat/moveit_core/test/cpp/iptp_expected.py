"""Expected timing for test_robot_trajectory_cpp: the path timed by the Python move_group's
IterativeParabolicTimeParameterization (moveit_core.time_parameterization.time_path, checked against upstream's
loops compiled apart), independent of the C++ class under test.

argv: path file (first line: velocity scaling, acceleration scaling; second: each joint's speed limit, 0 for none;
third: each joint's acceleration limit, 0 for none; then one waypoint a line). Prints the waypoints' times, then
each waypoint's velocities, then each waypoint's accelerations, one line each."""
import sys

from moveit_core.time_parameterization import time_path


def numbers(line):
    return [float(x) for x in line.split()]


def main():
    with open(sys.argv[1], encoding="utf-8") as stream:
        lines = [line for line in stream if line.strip()]
    velocity_scaling, acceleration_scaling = numbers(lines[0])
    speed = [v or None for v in numbers(lines[1])]
    acceleration = [a or None for a in numbers(lines[2])]
    timed = time_path([numbers(line) for line in lines[3:]], speed, acceleration, velocity_scaling,
                      acceleration_scaling)
    print(" ".join(repr(float(t)) for t in timed.times))
    for rows in (timed.velocities, timed.accelerations):
        for row in rows:
            print(" ".join(repr(float(x)) for x in row))


if __name__ == "__main__":
    main()
