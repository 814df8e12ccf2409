"""MoveIt's simple controller manager (see manager)."""
