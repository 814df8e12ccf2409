// trajectory_processing::IterativeParabolicTimeParameterization: the workspace's implementation of MoveIt
// noetic-devel's algorithm (moveit_core/trajectory_processing/src/iterative_time_parameterization.cpp, "iptp" below),
// step for step as compat/moveit_core's Python time_parameterization.py runs it for move_group.
#include <moveit/trajectory_processing/iterative_time_parameterization.h>

#include <algorithm>
#include <cmath>

#include <ros/console.h>

namespace trajectory_processing
{
namespace
{
const std::string LOGNAME = "trajectory_processing.iterative_time_parameterization";
constexpr double DEFAULT_VEL_MAX = 1.0;      // rad/s (m/s) of a variable without a speed limit (iptp:43)
constexpr double DEFAULT_ACCEL_MAX = 1.0;    // rad/s^2 of one without an acceleration limit (iptp:44)
constexpr double ROUNDING_THRESHOLD = 0.01;  // an acceleration this far beyond its limit is tolerated (iptp:45)
constexpr double MULT_FACTOR = 1.01;         // findT1/findT2's step (iptp:151, 170)

// a scaling factor as the adapter reads it: (0, 1] as given, else 1 (iptp:111-122, 325-336)
double scalingFactor(double factor, const char* name)
{
  if (factor > 0.0 && factor <= 1.0)
    return factor;
  if (factor == 0.0)
    ROS_DEBUG_NAMED(LOGNAME, "A %s of 0.0 was specified, defaulting to 1.0 instead.", name);
  else
    ROS_WARN_NAMED(LOGNAME, "Invalid %s %f specified, defaulting to 1.0 instead.", name, factor);
  return 1.0;
}

double parabolicAcceleration(double dq1, double dq2, double dt1, double dt2)
{
  return 2.0 * (dq2 / dt2 - dq1 / dt1) / (dt1 + dt2);
}
}  // namespace

IterativeParabolicTimeParameterization::IterativeParabolicTimeParameterization(unsigned int max_iterations,
                                                                               double max_time_change_per_it)
  : max_iterations_(max_iterations), max_time_change_per_it_(max_time_change_per_it)
{
}

void IterativeParabolicTimeParameterization::applyVelocityConstraints(robot_trajectory::RobotTrajectory& rob_trajectory,
                                                                      std::vector<double>& time_diff,
                                                                      const double max_velocity_scaling_factor) const
{
  // iptp:101-143: each segment as long as its slowest variable needs
  const moveit::core::JointModelGroup* group = rob_trajectory.getGroup();
  const std::vector<std::string>& vars = group->getVariableNames();
  const std::vector<int>& idx = group->getVariableIndexList();
  const moveit::core::RobotModel& model = group->getParentModel();
  const double factor = scalingFactor(max_velocity_scaling_factor, "max_velocity_scaling_factor");
  for (std::size_t i = 0; i + 1 < rob_trajectory.getWayPointCount(); ++i)
  {
    const moveit::core::RobotState& current = rob_trajectory.getWayPoint(i);
    const moveit::core::RobotState& next = rob_trajectory.getWayPoint(i + 1);
    for (std::size_t j = 0; j < vars.size(); ++j)
    {
      double v_max = DEFAULT_VEL_MAX;
      const moveit::core::VariableBounds& bounds = model.getVariableBounds(vars[j]);
      if (bounds.velocity_bounded_)
        v_max = std::min(std::fabs(bounds.max_velocity_ * factor), std::fabs(bounds.min_velocity_ * factor));
      const double t_min =
          std::abs(next.getVariablePosition(idx[j]) - current.getVariablePosition(idx[j])) / v_max;
      time_diff[i] = std::max(time_diff[i], t_min);
    }
  }
}

double IterativeParabolicTimeParameterization::findT1(const double dq1, const double dq2, double dt1,
                                                      const double dt2, const double a_max, const double cap) const
{
  // iptp:148-165: the acceleration is evaluated before each step, so the loop ends one step past the first time
  // that satisfies it, as upstream's
  double a = parabolicAcceleration(dq1, dq2, dt1, dt2);
  while (std::abs(a) > a_max && dt1 <= cap)
  {
    a = parabolicAcceleration(dq1, dq2, dt1, dt2);
    dt1 *= MULT_FACTOR;
  }
  return dt1;
}

double IterativeParabolicTimeParameterization::findT2(const double dq1, const double dq2, const double dt1,
                                                      double dt2, const double a_max, const double cap) const
{
  // iptp:167-184, as findT1 for the second segment
  double a = parabolicAcceleration(dq1, dq2, dt1, dt2);
  while (std::abs(a) > a_max && dt2 <= cap)
  {
    a = parabolicAcceleration(dq1, dq2, dt1, dt2);
    dt2 *= MULT_FACTOR;
  }
  return dt2;
}

void IterativeParabolicTimeParameterization::applyAccelerationConstraints(
    robot_trajectory::RobotTrajectory& rob_trajectory, std::vector<double>& time_diff,
    const double max_acceleration_scaling_factor) const
{
  // iptp:298-456: per variable a forward then a backward pass (the direction alternating across variables), while
  // a pass changed something and at most max_iterations_ times
  const moveit::core::JointModelGroup* group = rob_trajectory.getGroup();
  const std::vector<std::string>& vars = group->getVariableNames();
  const std::vector<int>& idx = group->getVariableIndexList();
  const moveit::core::RobotModel& model = group->getParentModel();
  const int num_points = static_cast<int>(rob_trajectory.getWayPointCount());
  const double factor = scalingFactor(max_acceleration_scaling_factor, "max_acceleration_scaling_factor");
  bool backwards = false;
  unsigned int iteration = 0;
  int num_updates = 0;
  do
  {
    num_updates = 0;
    ++iteration;
    for (std::size_t j = 0; j < vars.size(); ++j)
    {
      double a_max = DEFAULT_ACCEL_MAX;
      const moveit::core::VariableBounds& bounds = model.getVariableBounds(vars[j]);
      if (bounds.acceleration_bounded_)
        a_max = std::min(std::fabs(bounds.max_acceleration_ * factor), std::fabs(bounds.min_acceleration_ * factor));
      for (int pass = 0; pass < 2; ++pass)
      {
        for (int i = 0; i < num_points - 1; ++i)
        {
          const int index = backwards ? (num_points - 1) - i : i;
          const moveit::core::RobotState& current = rob_trajectory.getWayPoint(index);
          const double q2 = current.getVariablePosition(idx[j]);
          double q1, q3, dt1, dt2;
          if (index == 0)  // the first point mirrors its successor
          {
            q1 = q3 = rob_trajectory.getWayPoint(1).getVariablePosition(idx[j]);
            dt1 = dt2 = time_diff[0];
          }
          else if (index < num_points - 1)
          {
            q1 = rob_trajectory.getWayPoint(index - 1).getVariablePosition(idx[j]);
            q3 = rob_trajectory.getWayPoint(index + 1).getVariablePosition(idx[j]);
            dt1 = time_diff[index - 1];
            dt2 = time_diff[index];
          }
          else  // the last point mirrors its predecessor
          {
            q1 = q3 = rob_trajectory.getWayPoint(index - 1).getVariablePosition(idx[j]);
            dt1 = dt2 = time_diff[index - 1];
          }
          if (dt1 == 0.0 || dt2 == 0.0)
            continue;  // a = 0 (iptp:400-405)
          // a first waypoint with velocities starts from them (iptp:408-417)
          const double v1 = index == 0 && current.hasVelocities() ? current.getVariableVelocity(idx[j]) :
                                                                     (q2 - q1) / dt1;
          const double a = 2.0 * ((q3 - q2) / dt2 - v1) / (dt1 + dt2);
          if (std::fabs(a) <= a_max + ROUNDING_THRESHOLD)
            continue;
          // iptp:424-433: at most max_time_change_per_it_ more a visit
          if (!backwards)
          {
            const double cap = dt2 + max_time_change_per_it_;
            time_diff[index] = std::min(cap, findT2(q2 - q1, q3 - q2, dt1, dt2, a_max, cap));
          }
          else
          {
            const double cap = dt1 + max_time_change_per_it_;
            time_diff[index - 1] = std::min(cap, findT1(q2 - q1, q3 - q2, dt1, dt2, a_max, cap));
          }
          ++num_updates;
        }
        backwards = !backwards;
      }
    }
  } while (num_updates > 0 && iteration < max_iterations_);
}

void IterativeParabolicTimeParameterization::updateTrajectory(robot_trajectory::RobotTrajectory& rob_trajectory,
                                                              const std::vector<double>& time_diff)
{
  // iptp:188-295: durations; each waypoint's velocity the mean of the segments either side and its acceleration
  // their difference, the ends mirrored (zero velocity there), a first waypoint with velocities keeping them
  if (time_diff.empty())
    return;
  const int num_points = static_cast<int>(rob_trajectory.getWayPointCount());
  rob_trajectory.setWayPointDurationFromPrevious(0, 0.0);
  for (int i = 1; i < num_points; ++i)
    rob_trajectory.setWayPointDurationFromPrevious(i, time_diff[i - 1]);
  if (num_points <= 1)
    return;
  const moveit::core::JointModelGroup* group = rob_trajectory.getGroup();
  const std::vector<int>& idx = group->getVariableIndexList();
  for (int i = 0; i < num_points; ++i)
  {
    moveit::core::RobotState& current = *rob_trajectory.getWayPointPtr(i);
    std::vector<double>& accelerations = rob_trajectory.wayPointAccelerations(i);
    for (int variable : idx)
    {
      // asked per variable, as upstream asks (iptp:277-284): once the first variable's velocity is written the first
      // waypoint has velocities, so its other variables start from theirs (zero: velocity 0, acceleration 0)
      const bool start_velocity = i == 0 && current.hasVelocities();
      const double q2 = current.getVariablePosition(variable);
      double q1, q3, dt1, dt2;
      if (i == 0)
      {
        q1 = q3 = rob_trajectory.getWayPoint(1).getVariablePosition(variable);
        dt1 = dt2 = time_diff[0];
      }
      else if (i < num_points - 1)
      {
        q1 = rob_trajectory.getWayPoint(i - 1).getVariablePosition(variable);
        q3 = rob_trajectory.getWayPoint(i + 1).getVariablePosition(variable);
        dt1 = time_diff[i - 1];
        dt2 = time_diff[i];
      }
      else
      {
        q1 = q3 = rob_trajectory.getWayPoint(i - 1).getVariablePosition(variable);
        dt1 = dt2 = time_diff[i - 1];
      }
      double v1 = 0.0;
      double v2 = 0.0;
      double a = 0.0;
      if (dt1 != 0.0 && dt2 != 0.0)
      {
        v1 = start_velocity ? current.getVariableVelocity(variable) : (q2 - q1) / dt1;
        v2 = start_velocity ? v1 : (q3 - q2) / dt2;
        a = 2.0 * (v2 - v1) / (dt1 + dt2);
      }
      current.setVariableVelocity(variable, (v2 + v1) / 2.0);
      accelerations[variable] = a;
    }
  }
}

bool IterativeParabolicTimeParameterization::computeTimeStamps(robot_trajectory::RobotTrajectory& trajectory,
                                                               const double max_velocity_scaling_factor,
                                                               const double max_acceleration_scaling_factor) const
{
  // iptp:458-485
  if (trajectory.empty())
    return true;
  if (!trajectory.getGroup())
  {
    ROS_ERROR_NAMED(LOGNAME, "It looks like the planner did not set the group the plan was computed for");
    return false;
  }
  // the parabolas are wrong across a wrapped angle: unwind first (iptp:473-474)
  trajectory.unwind();
  std::vector<double> time_diff(trajectory.getWayPointCount() - 1, 0.0);
  applyVelocityConstraints(trajectory, time_diff, max_velocity_scaling_factor);
  applyAccelerationConstraints(trajectory, time_diff, max_acceleration_scaling_factor);
  updateTrajectory(trajectory, time_diff);
  return true;
}
}  // namespace trajectory_processing
