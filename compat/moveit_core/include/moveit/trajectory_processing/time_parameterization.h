// trajectory_processing::TimeParameterization (MoveIt noetic-devel moveit_core/trajectory_processing/include/moveit/
// trajectory_processing/time_parameterization.h): the base class of the time parameterizations, here
// IterativeParabolicTimeParameterization (iterative_time_parameterization.h).
#pragma once

#include <moveit/macros/class_forward.h>
#include <moveit/robot_trajectory/robot_trajectory.h>

namespace trajectory_processing
{
MOVEIT_CLASS_FORWARD(TimeParameterization);

class TimeParameterization
{
public:
  virtual ~TimeParameterization() = default;
  // the waypoints' durations, velocities and accelerations within the group's limits times the factors
  virtual bool computeTimeStamps(robot_trajectory::RobotTrajectory& trajectory,
                                 const double max_velocity_scaling_factor = 1.0,
                                 const double max_acceleration_scaling_factor = 1.0) const = 0;
};
}  // namespace trajectory_processing
