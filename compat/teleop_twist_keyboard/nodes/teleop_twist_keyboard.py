#!/usr/bin/env python3
"""Keyboard teleop on cmd_vel: see keyboard_teleop.node."""
from keyboard_teleop.node import main

main()
