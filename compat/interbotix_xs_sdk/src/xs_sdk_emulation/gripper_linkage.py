"""The X-series gripper's linkage: a servo horn of radius r turns, an arm of length L slides
each finger. Upstream's formulas (``xs_sdk_sim``'s ``robot_convert_angular_position_to_linear``,
l. 230-236, and ``robot_convert_linear_position_to_radian``, l. 219-224): a finger's distance from the horn's centre
at horn angle a is r sin a + sqrt(L^2 - (r^2 - r^2 sin^2 a)); the angle for a distance d
between the fingers is pi/2 - acos((r^2 + (d/2)^2 - L^2) / (r d))."""
import math


def finger_distance(angle: float, horn_radius: float, arm_length: float) -> float:
    """One finger's distance (m) from the horn's centre at the horn's ``angle`` (rad)."""
    a1 = horn_radius * math.sin(angle)
    c = math.sqrt(horn_radius ** 2 - a1 ** 2)
    return a1 + math.sqrt(arm_length ** 2 - c ** 2)


def horn_angle(between_fingers: float, horn_radius: float, arm_length: float) -> float:
    """The horn's angle (rad) that puts the fingers ``between_fingers`` (m) apart."""
    half = between_fingers / 2.0
    return math.pi / 2.0 - math.acos((horn_radius ** 2 + half ** 2 - arm_length ** 2)
                                     / (2.0 * horn_radius * half))
