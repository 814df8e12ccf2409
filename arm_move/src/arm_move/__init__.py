"""Motion planning and pick-and-place for a PincherX-100-class arm, without MoveIt."""
