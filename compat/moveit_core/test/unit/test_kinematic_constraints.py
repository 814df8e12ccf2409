"""moveit_core.kinematic_constraints against MoveIt's definitions (kinematic_constraint.cpp,
noetic-devel): orientation errors are intrinsic XYZ Euler angles of R_target^T R_link
(checked against tf's 'rxyz' decomposition and against rotations built as Rx Ry Rz), with
the gimbal-lock rule; rotation vectors; joint bands with wrap for continuous joints; the
link point inside boxes, spheres, cylinders and convex meshes at their poses (checked
against the URDF's forward kinematics by urdf_tools); what cannot be configured left out,
and what is not provided refused."""
import math

import numpy as np
import pytest
from geometry_msgs.msg import Point, Pose, Quaternion
from moveit_msgs.msg import (Constraints, JointConstraint, OrientationConstraint,
                             PositionConstraint, VisibilityConstraint)
from shape_msgs.msg import Mesh, MeshTriangle, SolidPrimitive
from tf.transformations import (euler_from_matrix, euler_matrix, quaternion_from_matrix,
                                random_rotation_matrix, rotation_matrix)

from moveit_core import robot_model
from moveit_core.kinematic_constraints import (ConstraintError, ConstraintSet, intrinsic_xyz,
                                               orientation_error)
from moveit_core.planning_scene import PlanningScene
from urdf_tools.kinematics import link_transform

# a continuous joint turning an arm whose tip sits 0.5 m out and 0.2 m up
URDF = """<robot name="spinner">
  <link name="base"/><link name="arm"/><link name="tip"/>
  <joint name="spin" type="continuous"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/></joint>
  <joint name="lift" type="revolute"><parent link="arm"/><child link="tip"/>
    <origin xyz="0.5 0 0.2"/><axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/></joint>
</robot>"""
SRDF = '<robot name="spinner"><group name="all"><joint name="spin"/><joint name="lift"/>' \
       '</group></robot>'
RANDOM_ROTATIONS = 200


@pytest.fixture
def scene():
    return PlanningScene(robot_model.load(URDF, SRDF, {}))


def quaternion(matrix3):
    full = np.eye(4)
    full[:3, :3] = matrix3
    return Quaternion(*quaternion_from_matrix(full))


def orientation(link, rotation, tolerances, parameterization=0):
    constraint = OrientationConstraint(link_name=link, orientation=quaternion(rotation),
                                       absolute_x_axis_tolerance=tolerances[0],
                                       absolute_y_axis_tolerance=tolerances[1],
                                       absolute_z_axis_tolerance=tolerances[2],
                                       parameterization=parameterization, weight=1.0)
    constraint.header.frame_id = "base"
    return constraint


def position(link, primitive, pose_matrix=np.eye(4), offset=(0.0, 0.0, 0.0)):
    constraint = PositionConstraint(link_name=link, weight=1.0)
    constraint.header.frame_id = "base"
    constraint.target_point_offset.x, constraint.target_point_offset.y, \
        constraint.target_point_offset.z = offset
    constraint.constraint_region.primitives = [primitive]
    pose = Pose(orientation=quaternion(pose_matrix[:3, :3]))
    pose.position.x, pose.position.y, pose.position.z = pose_matrix[:3, 3]
    constraint.constraint_region.primitive_poses = [pose]
    return constraint


def test_intrinsic_xyz_is_tfs_rxyz_and_rebuilds_the_rotation():
    rng = np.random.default_rng(3)
    for _ in range(RANDOM_ROTATIONS):
        rotation = random_rotation_matrix(rng.random(3))
        angles, regular = intrinsic_xyz(rotation[:3, :3])
        assert regular
        assert np.allclose(angles, euler_from_matrix(rotation, "rxyz"), atol=1e-9)
        rebuilt = euler_matrix(*angles, "rxyz")
        assert np.allclose(rebuilt, rotation, atol=1e-9)


def test_at_gimbal_lock_the_yaw_hidden_in_the_roll_is_read_as_yaw():
    """R = Rx(0.3) Ry(pi/2) Rz(0.2): the decomposition gives roll 0.5, yaw 0; a z tolerance
    below 0.5 reads it as a yaw (kc:698-705), a larger one keeps it a roll."""
    rotation = euler_matrix(0.3, math.pi / 2, 0.2, "rxyz")[:3, :3]
    assert np.allclose(orientation_error(rotation, 0, 0.1), [0.0, math.pi / 2, 0.5])
    assert np.allclose(orientation_error(rotation, 0, 1.0), [0.5, math.pi / 2, 0.0])


def test_orientation_constraints_decide_with_absolute_tolerances(scene):
    # spin about z, then lift about the turned y
    target = (rotation_matrix(1.0, [0, 0, 1]) @ rotation_matrix(0.4, [0, 1, 0]))[:3, :3]
    state = {"spin": 1.0, "lift": 0.4}
    link = link_transform(scene.model.urdf, "base", "tip", state)[:3, :3]
    assert np.allclose(link, target, atol=1e-9)
    # turned 0.08 about the tip's own x: inside 0.1, outside 0.05 on x only
    turned = target @ euler_matrix(0.08, 0.0, 0.0, "rxyz")[:3, :3]
    inside = ConstraintSet(scene, Constraints(orientation_constraints=[
        orientation("tip", turned, (0.1, 0.01, 0.01))]))
    outside = ConstraintSet(scene, Constraints(orientation_constraints=[
        orientation("tip", turned, (0.05, 1.0, 1.0))]))
    assert inside.decide(state) is None
    assert "turned" in outside.decide(state)
    vector = ConstraintSet(scene, Constraints(orientation_constraints=[
        orientation("tip", turned, (0.081, 1e-6, 1e-6), OrientationConstraint.ROTATION_VECTOR)]))
    assert vector.decide(state) is None


def test_joint_bands_wrap_for_continuous_joints(scene):
    band = ConstraintSet(scene, Constraints(joint_constraints=[
        JointConstraint(joint_name="spin", position=3.1, tolerance_above=0.1,
                        tolerance_below=0.1, weight=1.0),
        JointConstraint(joint_name="lift", position=0.2, tolerance_above=0.1,
                        tolerance_below=0.0, weight=1.0)]))
    # -3.1 is 0.083 rad past pi from 3.1 the short way
    assert band.decide({"spin": -3.1, "lift": 0.25}) is None
    assert band.decide({"spin": 3.1 + 4 * math.pi, "lift": 0.3}) is None   # edge holds
    assert "lift" in band.decide({"spin": 3.1, "lift": 0.19})
    assert "spin" in band.decide({"spin": 2.9, "lift": 0.2})


def test_the_link_point_must_lie_in_one_of_the_regions_shapes(scene):
    state = {"spin": 0.5, "lift": -0.3}
    tip = link_transform(scene.model.urdf, "base", "tip", state)
    offset = np.array([0.1, 0.0, 0.0])
    point = (tip @ np.append(offset, 1.0))[:3]
    turned = np.eye(4)
    turned[:3, :3] = euler_matrix(0.0, 0.0, 0.7)[:3, :3]
    turned[:3, 3] = point + turned[:3, :3] @ [0.045, 0.0, 0.0]   # 4.5 cm along its own x
    box = SolidPrimitive(type=SolidPrimitive.BOX, dimensions=[0.1, 0.01, 0.01])
    assert ConstraintSet(scene, Constraints(position_constraints=[
        position("tip", box, turned, offset)])).decide(state) is None
    # without the offset the tip's origin is 10 cm away
    assert "outside" in ConstraintSet(scene, Constraints(position_constraints=[
        position("tip", box, turned)])).decide(state)
    at = np.eye(4)
    at[:3, 3] = point + [0.0, 0.0, 0.019]
    sphere = SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.02])
    cylinder = SolidPrimitive(type=SolidPrimitive.CYLINDER, dimensions=[0.04, 0.001])
    for shape, holds in ((sphere, True), (cylinder, True)):
        decided = ConstraintSet(scene, Constraints(position_constraints=[
            position("tip", shape, at, offset)])).decide(state)
        assert (decided is None) == holds
    at[:3, 3] = point + [0.0, 0.0, 0.021]
    assert ConstraintSet(scene, Constraints(position_constraints=[
        position("tip", sphere, at, offset)])).decide(state) is not None


def test_a_convex_mesh_region_holds_its_inside(scene):
    state = {"spin": 0.0, "lift": 0.0}
    tip = link_transform(scene.model.urdf, "base", "tip", state)[:3, 3]
    corners = [Point(x=x, y=y, z=z) for x in (-0.1, 0.1) for y in (-0.1, 0.1)
               for z in (-0.1, 0.1)]
    mesh = Mesh(vertices=corners, triangles=[MeshTriangle(vertex_indices=[0, 1, 2])])
    constraint = PositionConstraint(link_name="tip", weight=1.0)
    constraint.header.frame_id = "base"
    constraint.constraint_region.meshes = [mesh]
    for shift, holds in ((0.05, True), (0.15, False)):
        pose = Pose()
        pose.orientation.w = 1.0
        pose.position.x, pose.position.y, pose.position.z = tip + [shift, 0.0, 0.0]
        constraint.constraint_region.mesh_poses = [pose]
        assert (ConstraintSet(scene, Constraints(position_constraints=[constraint]))
                .decide(state) is None) == holds


def test_what_cannot_be_configured_is_left_out_and_visibility_is_refused(scene):
    loose = ConstraintSet(scene, Constraints(
        joint_constraints=[JointConstraint(joint_name="no_such_joint", position=1.0)],
        orientation_constraints=[orientation("no_such_link", np.eye(3), (0.1, 0.1, 0.1))]))
    assert loose.empty
    assert loose.decide({"spin": 0.0, "lift": 0.0}) is None
    with pytest.raises(ConstraintError, match="visibility"):
        ConstraintSet(scene, Constraints(visibility_constraints=[VisibilityConstraint()]))
    unknown = orientation("tip", np.eye(3), (0.1, 0.1, 0.1))
    unknown.header.frame_id = "no_such_frame"
    with pytest.raises(ConstraintError, match="no_such_frame"):
        ConstraintSet(scene, Constraints(orientation_constraints=[unknown]))
