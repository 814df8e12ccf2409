"""Driving any robot here from the keyboard, with teleop_twist_keyboard's keys."""
