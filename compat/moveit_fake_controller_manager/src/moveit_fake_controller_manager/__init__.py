"""MoveIt's fake controller manager (see manager)."""
