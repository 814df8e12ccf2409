"""moveit_commander's exception."""


class MoveItCommanderException(Exception):
    """Raised for a request the commander cannot make (an unknown name, a target outside
    the bounds, a failed IK for a pose given as a joint target)."""
