"""Grades course submissions by the guide's own commands, in ground truth (the RB1 project first)."""
