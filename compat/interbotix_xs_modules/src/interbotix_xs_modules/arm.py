"""``InterbotixManipulatorXS`` and the arm's interface (upstream's ``arm.py``, noetic af96d28;
lines cited are that file's):
joint commands through the driver's ``commands/joint_group`` and ``joint_single`` with the
group's time-based profile (``Profile_Velocity`` = moving time in ms, ``Profile_Acceleration``
= acceleration time in ms); end-effector poses solved by Modern Robotics' ``IKinSpace``
(tolerances 0.001 rad and 0.001 m) from three initial guesses (all zero, then the waist at
-120 and +120 degrees), each solution wrapped into the joints' limits and checked against
them and against the joints' velocity limits over the moving time; Cartesian moves as
trajectories of waypoints solved from the last one."""
import math

import modern_robotics as mr
import numpy as np
import rospy
from interbotix_xs_msgs.msg import JointGroupCommand, JointSingleCommand, JointTrajectoryCommand
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

import interbotix_common_modules.angle_manipulation as ang
import interbotix_xs_modules.mr_descriptions as mrd
from interbotix_xs_modules.core import InterbotixRobotXSCore
from interbotix_xs_modules.gripper import InterbotixGripperXSInterface

IK_TOLERANCES = (0.001, 0.001)      # rad, m: upstream's IKinSpace eomg, ev (arm.py l. 196)
GUESS_WAISTS_DEGREES = (0.0, -120.0, 120.0)     # the initial guesses' waists (l. 48-50)


class InterbotixManipulatorXS:  # pylint: disable=too-few-public-methods
    """``bot.arm`` and, unless ``gripper_name`` is None, ``bot.gripper``; ``bot.dxl`` the core."""

    def __init__(self, robot_model, group_name="arm", gripper_name="gripper", robot_name=None,
                 moving_time=2.0, accel_time=0.3, gripper_pressure=0.5,
                 gripper_pressure_lower_limit=150, gripper_pressure_upper_limit=350,
                 init_node=True):
        self.dxl = InterbotixRobotXSCore(robot_model, robot_name, init_node)
        self.arm = InterbotixArmXSInterface(self.dxl, robot_model, group_name, moving_time,
                                            accel_time)
        if gripper_name is not None:
            self.gripper = InterbotixGripperXSInterface(self.dxl, gripper_name, gripper_pressure,
                                                        gripper_pressure_lower_limit,
                                                        gripper_pressure_upper_limit)


def robot_description(robot_model):
    """Modern Robotics' description of ``robot_model``; an arm without one is named."""
    try:
        return getattr(mrd, robot_model)
    except AttributeError:
        described = sorted(n for n in vars(mrd) if isinstance(getattr(mrd, n), type))
        raise ValueError(f"interbotix_xs_modules has no kinematics for robot_model "
                         f"'{robot_model}' (it has: {', '.join(described)})") from None


class InterbotixArmXSInterface:  # pylint: disable=too-many-instance-attributes
    def __init__(self, core, robot_model, group_name, moving_time=2.0, accel_time=0.3):
        self.core = core
        self.group_info = self.core.srv_get_info("group", group_name)
        if self.group_info.profile_type != "time":
            rospy.logerr("Please set the group's 'profile type' to 'time'.")
        if self.group_info.mode != "position":
            rospy.logerr("Please set the group's 'operating mode' to 'position'.")
        self.robot_des = robot_description(robot_model)
        joints = self.group_info.num_joints
        self.initial_guesses = [[math.radians(waist)] + [0.0] * (joints - 1)
                                for waist in GUESS_WAISTS_DEGREES]
        self.moving_time = None
        self.accel_time = None
        self.group_name = group_name
        self.rev = 2 * math.pi
        self.joint_commands = [self.core.joint_states.position[self.core.js_index_map[name]]
                               for name in self.group_info.joint_names]
        self.T_sb = mr.FKinSpace(self.robot_des.M, self.robot_des.Slist, self.joint_commands)
        self.set_trajectory_time(moving_time, accel_time)
        self.info_index_map = {name: i for i, name in enumerate(self.group_info.joint_names)}
        print(f"Arm Group Name: {group_name}\nMoving Time: {moving_time:.2f} seconds\n"
              f"Acceleration Time: {accel_time:.2f} seconds\nDrive Mode: Time-Based-Profile")
        print("Initialized InterbotixArmXSInterface!\n")

    # --- sending -----------------------------------------------------------------------------
    def publish_positions(self, positions, moving_time=None, accel_time=None, blocking=True):
        self.set_trajectory_time(moving_time, accel_time)
        self.joint_commands = list(positions)
        self.core.pub_group.publish(JointGroupCommand(self.group_name, self.joint_commands))
        if blocking:
            rospy.sleep(self.moving_time)
        self.T_sb = mr.FKinSpace(self.robot_des.M, self.robot_des.Slist, self.joint_commands)

    def set_trajectory_time(self, moving_time=None, accel_time=None):
        """The group's profile registers in ms, written only when they change (l. 81-87)."""
        if moving_time is not None and moving_time != self.moving_time:
            self.moving_time = moving_time
            self.core.srv_set_reg(cmd_type="group", name=self.group_name, reg="Profile_Velocity",
                                  value=int(moving_time * 1000))
        if accel_time is not None and accel_time != self.accel_time:
            self.accel_time = accel_time
            self.core.srv_set_reg(cmd_type="group", name=self.group_name,
                                  reg="Profile_Acceleration", value=int(accel_time * 1000))

    # --- limits ------------------------------------------------------------------------------
    def _joint_within_limits(self, index, theta, current, warn):
        """Position limits on ``theta`` (cut to the mrad, as upstream's: l. 93) and the speed
        of going from ``current`` over the moving time."""
        theta = int(theta * 1000) / 1000.0
        lower = self.group_info.joint_lower_limits[index]
        upper = self.group_info.joint_upper_limits[index]
        if not lower <= theta <= upper:
            if warn:
                rospy.logwarn("Would exceed position limits on joint %s.", index)
                rospy.logwarn("Limits are [%f, %f], value was %f.", lower, upper, theta)
            return False
        speed = abs(theta - current) / float(self.moving_time)
        if speed > self.group_info.joint_velocity_limits[index]:
            if warn:
                rospy.logwarn("Would exceed velocity limits on joint %s.", index)
                rospy.logwarn("Limit is %f, value was %f.",
                              self.group_info.joint_velocity_limits[index], theta)
            return False
        return True

    def check_joint_limits(self, positions):
        return all(self._joint_within_limits(i, positions[i], self.joint_commands[i], warn=True)
                   for i in range(self.group_info.num_joints))

    def check_single_joint_limit(self, joint_name, position):
        index = self.info_index_map[joint_name]
        return self._joint_within_limits(index, position, self.joint_commands[index], warn=False)

    # --- joint space -------------------------------------------------------------------------
    def set_joint_positions(self, joint_positions, moving_time=None, accel_time=None,
                            blocking=True):
        if not self.check_joint_limits(joint_positions):
            return False
        self.publish_positions(joint_positions, moving_time, accel_time, blocking)
        return True

    def go_to_home_pose(self, moving_time=None, accel_time=None, blocking=True):
        self.publish_positions([0] * self.group_info.num_joints, moving_time, accel_time,
                               blocking)

    def go_to_sleep_pose(self, moving_time=None, accel_time=None, blocking=True):
        self.publish_positions(self.group_info.joint_sleep_positions, moving_time, accel_time,
                               blocking)

    def set_single_joint_position(self, joint_name, position, moving_time=None, accel_time=None,
                                  blocking=True):
        if not self.check_single_joint_limit(joint_name, position):
            return False
        self.set_trajectory_time(moving_time, accel_time)
        self.joint_commands[self.info_index_map[joint_name]] = position
        self.core.pub_single.publish(JointSingleCommand(joint_name, position))
        if blocking:
            rospy.sleep(self.moving_time)
        self.T_sb = mr.FKinSpace(self.robot_des.M, self.robot_des.Slist, self.joint_commands)
        return True

    # --- task space --------------------------------------------------------------------------
    def _wrapped(self, theta_list):
        """Each angle into (-2 pi, 2 pi), then by a turn towards its limits (upstream's)."""
        theta_list = list(theta_list)
        for i, theta in enumerate(theta_list):
            if theta <= -self.rev:
                theta = theta % -self.rev
            elif theta >= self.rev:
                theta = theta % self.rev
            if round(theta, 3) < round(self.group_info.joint_lower_limits[i], 3):
                theta += self.rev
            elif round(theta, 3) > round(self.group_info.joint_upper_limits[i], 3):
                theta -= self.rev
            theta_list[i] = theta
        return theta_list

    def set_ee_pose_matrix(self, T_sd, custom_guess=None, execute=True, moving_time=None,  # pylint: disable=invalid-name
                           accel_time=None, blocking=True):
        """Joint positions putting ee_gripper_link at ``T_sd`` in base_link, and whether they
        were found within the limits; executed when ``execute``."""
        guesses = self.initial_guesses if custom_guess is None else [custom_guess]
        theta_list = []
        for guess in guesses:
            theta_list, success = mr.IKinSpace(self.robot_des.Slist, self.robot_des.M, T_sd,
                                               guess, *IK_TOLERANCES)
            if success:
                theta_list = self._wrapped(theta_list)
                success = self.check_joint_limits(theta_list)
            if success:
                if execute:
                    self.publish_positions(theta_list, moving_time, accel_time, blocking)
                    self.T_sb = T_sd
                return theta_list, True
        rospy.logwarn("No valid pose could be found. Returned theta_list variable may be "
                      "nonsense.")
        return theta_list, False

    def set_ee_pose_components(self, x=0, y=0, z=0, roll=0, pitch=0, yaw=None,  # pylint: disable=too-many-arguments
                               custom_guess=None, execute=True, moving_time=None,
                               accel_time=None, blocking=True):
        """An arm of fewer than 6 joints (or a yaw of None) faces the point: yaw = atan2(y, x)
        (l. 239-241)."""
        if self.group_info.num_joints < 6 or yaw is None:
            yaw = math.atan2(y, x)
        T_sd = np.identity(4)  # pylint: disable=invalid-name
        T_sd[:3, :3] = ang.eulerAnglesToRotationMatrix([roll, pitch, yaw])
        T_sd[:3, 3] = [x, y, z]
        return self.set_ee_pose_matrix(T_sd, custom_guess, execute, moving_time, accel_time,
                                       blocking)

    def set_ee_cartesian_trajectory(self, x=0, y=0, z=0, roll=0, pitch=0, yaw=0,  # pylint: disable=too-many-arguments,too-many-locals
                                    moving_time=None, wp_moving_time=0.2, wp_accel_time=0.1,
                                    wp_period=0.05):
        """A straight move by (x, y, z, roll, pitch, yaw) in the frame of the gripper's
        heading (base_link turned by its yaw): waypoints every ``wp_period`` s over the moving
        time, each solved from the last; sent as one trajectory only if all are solved."""
        if self.group_info.num_joints < 6 and (y != 0 or yaw != 0):
            rospy.loginfo("Please leave the 'y' and 'yaw' fields at '0' when working with arms "
                          "that have less than 6dof.")
            return False
        rpy = ang.rotationMatrixToEulerAngles(self.T_sb[:3, :3])
        T_sy = np.identity(4)  # pylint: disable=invalid-name
        T_sy[:3, :3] = ang.eulerAnglesToRotationMatrix([0.0, 0.0, rpy[2]])
        T_yb = mr.TransInv(T_sy) @ self.T_sb  # pylint: disable=invalid-name
        rpy[2] = 0.0
        if moving_time is None:
            moving_time = self.moving_time
        accel_time = self.accel_time
        count = int(moving_time / wp_period)
        increment = 1.0 / float(count)
        trajectory = JointTrajectory()
        joint_positions = list(self.joint_commands)
        success, T_sd = True, self.T_sb  # pylint: disable=invalid-name
        for i in range(count + 1):
            trajectory.points.append(JointTrajectoryPoint(
                positions=joint_positions, time_from_start=rospy.Duration.from_sec(i * wp_period)))
            if i == count:
                break
            T_yb[:3, 3] += [increment * x, increment * y, increment * z]
            rpy[0] += increment * roll
            rpy[1] += increment * pitch
            rpy[2] += increment * yaw
            T_yb[:3, :3] = ang.eulerAnglesToRotationMatrix(rpy)
            T_sd = T_sy @ T_yb  # pylint: disable=invalid-name
            theta_list, success = self.set_ee_pose_matrix(T_sd, joint_positions, False,
                                                          blocking=False)
            if not success:
                rospy.loginfo("%.1f%% of trajectory successfully planned. Trajectory will not "
                              "be executed.", i / float(count) * 100)
                break
            joint_positions = theta_list
        if success:
            self.set_trajectory_time(wp_moving_time, wp_accel_time)
            trajectory.joint_names = self.group_info.joint_names
            with self.core.js_mutex:
                trajectory.points[0].positions = [
                    self.core.joint_states.position[self.core.js_index_map[name]]
                    for name in trajectory.joint_names]
            trajectory.header.stamp = rospy.Time.now()
            self.core.pub_traj.publish(JointTrajectoryCommand("group", self.group_name,
                                                              trajectory))
            rospy.sleep(moving_time + wp_moving_time)
            self.T_sb = T_sd
            self.joint_commands = joint_positions
            self.set_trajectory_time(moving_time, accel_time)
        return success

    def set_relative_ee_position_wrt_to_base_frame(self, *, dx=0, dy=0, dz=0, custom_guess=None,
                                                   execute=True, moving_time=None,
                                                   accel_time=None, blocking=True):
        return self.set_ee_pose_components(
            x=self.T_sb[0, 3] + dx, y=self.T_sb[1, 3] + dy, z=self.T_sb[2, 3] + dz,
            custom_guess=custom_guess, execute=execute, moving_time=moving_time,
            accel_time=accel_time, blocking=blocking)

    # --- what was commanded, what is -----------------------------------------------------------
    def get_joint_commands(self):
        return list(self.joint_commands)

    def get_single_joint_command(self, joint_name):
        return self.joint_commands[self.info_index_map[joint_name]]

    def get_ee_pose_command(self):
        return np.array(self.T_sb)

    def get_ee_pose(self):
        with self.core.js_mutex:
            states = [self.core.joint_states.position[self.core.js_index_map[name]]
                      for name in self.group_info.joint_names]
        return mr.FKinSpace(self.robot_des.M, self.robot_des.Slist, states)

    def capture_joint_positions(self):
        with self.core.js_mutex:
            self.joint_commands = [self.core.joint_states.position[self.core.js_index_map[name]]
                                   for name in self.group_info.joint_names]
        self.T_sb = mr.FKinSpace(self.robot_des.M, self.robot_des.Slist, self.joint_commands)
