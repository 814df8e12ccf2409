"""RB1 project, task 4: the /rotate_robot service."""
