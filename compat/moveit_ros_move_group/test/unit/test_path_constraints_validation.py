"""check_plan_request on path constraints: a NaN or infinite value there is refused with
START_STATE_VIOLATES_PATH_CONSTRAINTS (where MoveIt ends: no state satisfies a comparison
with NaN, not even one FixStartStatePathConstraints plans to), naming the field and joint;
finite ones pass. No master."""
import math

import pytest
from moveit_msgs.msg import (Constraints, JointConstraint, MotionPlanRequest,
                             MoveItErrorCodes as Codes, OrientationConstraint)

from moveit_ros_move_group.validation import Refused, check_plan_request


def constrained(**joint):
    request = MotionPlanRequest(group_name="manipulator")
    request.path_constraints = Constraints(
        joint_constraints=[JointConstraint(joint_name="elbow_joint", position=0.5,
                                           tolerance_above=0.1, tolerance_below=0.1,
                                           weight=1.0)],
        orientation_constraints=[OrientationConstraint(link_name="tool0", weight=1.0,
                                                       absolute_x_axis_tolerance=0.1)])
    for field, value in joint.items():
        setattr(request.path_constraints.joint_constraints[0], field, value)
    return request


@pytest.mark.parametrize("field", ["position", "tolerance_above", "tolerance_below"])
@pytest.mark.parametrize("value", [math.nan, math.inf])
def test_a_non_finite_path_constraint_is_refused_naming_it(field, value):
    with pytest.raises(Refused) as refused:
        check_plan_request(constrained(**{field: value}))
    assert refused.value.code == Codes.START_STATE_VIOLATES_PATH_CONSTRAINTS
    assert f"request.path_constraints.joint_constraints[0].{field} is {value}" in \
        refused.value.message
    assert "elbow_joint" in refused.value.message


def test_an_orientation_tolerance_of_nan_is_refused_too():
    request = constrained()
    request.path_constraints.orientation_constraints[0].absolute_y_axis_tolerance = math.nan
    with pytest.raises(Refused, match="orientation_constraints\\[0\\].absolute_y_axis"):
        check_plan_request(request)


def test_finite_path_constraints_pass():
    check_plan_request(constrained())
