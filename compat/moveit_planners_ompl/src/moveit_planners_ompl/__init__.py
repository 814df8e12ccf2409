"""MoveIt's OMPL planning pipeline in Python (see planner, goals, planner_configs)."""
