// trajectory_processing::IterativeParabolicTimeParameterization (MoveIt noetic-devel moveit_core/trajectory_processing/
// include/moveit/trajectory_processing/iterative_time_parameterization.h), written anew on this workspace's
// RobotTrajectory: the algorithm move_group's AddTimeParameterization adapter runs (our Python move_group runs the same
// steps: moveit_core/time_parameterization.py). Each segment first takes the time its slowest variable needs at its
// speed limit times the velocity scaling factor; then, per variable, forward and backward passes lengthen a segment
// where a waypoint's parabolic acceleration exceeds the limit times the acceleration scaling factor by more than
// 0.01, by at most max_time_change_per_it a visit, while a pass changed something and at most max_iterations times;
// velocities and accelerations from the finite differences, zero at both ends (a first waypoint with velocities keeps
// them). A variable without a speed or acceleration limit gets 1 rad/s or 1 rad/s^2. The trajectory needs its group.
#pragma once

#include <vector>

#include <moveit/robot_trajectory/robot_trajectory.h>
#include <moveit/trajectory_processing/time_parameterization.h>

namespace trajectory_processing
{
class IterativeParabolicTimeParameterization : public TimeParameterization
{
public:
  IterativeParabolicTimeParameterization(unsigned int max_iterations = 100, double max_time_change_per_it = .01);

  bool computeTimeStamps(robot_trajectory::RobotTrajectory& trajectory, const double max_velocity_scaling_factor = 1.0,
                         const double max_acceleration_scaling_factor = 1.0) const override;

private:
  unsigned int max_iterations_;
  double max_time_change_per_it_;

  void applyVelocityConstraints(robot_trajectory::RobotTrajectory& rob_trajectory, std::vector<double>& time_diff,
                                const double max_velocity_scaling_factor) const;
  void applyAccelerationConstraints(robot_trajectory::RobotTrajectory& rob_trajectory, std::vector<double>& time_diff,
                                    const double max_acceleration_scaling_factor) const;
  // the segment's time grown by 1 % steps until the acceleration is within a_max (stopping once past cap, beyond
  // which the caller keeps cap anyway)
  double findT1(const double dq1, const double dq2, double dt1, const double dt2, const double a_max,
                const double cap) const;
  double findT2(const double dq1, const double dq2, const double dt1, double dt2, const double a_max,
                const double cap) const;
  static void updateTrajectory(robot_trajectory::RobotTrajectory& rob_trajectory, const std::vector<double>& time_diff);
};
}  // namespace trajectory_processing
