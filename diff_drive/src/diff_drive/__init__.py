"""The flipping differential-drive robot's node logic (see flip)."""
