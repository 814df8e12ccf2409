// RobotState <-> message conversions (MoveIt noetic-devel moveit_core/robot_state/src/conversions.cpp): joint_state
// and multi_dof_joint_state in, the state's variables out (multi-DOF joints as transforms); attached bodies are not
// provided here.
#include <moveit/robot_state/conversions.h>

#include <sstream>

#include <ros/console.h>

namespace moveit
{
namespace core
{
namespace
{
const char LOGNAME[] = "robot_state";

bool multiDofJointsToRobotState(const sensor_msgs::MultiDOFJointState& mjs, RobotState& state)
{
  if (mjs.joint_names.size() != mjs.transforms.size())
  {
    ROS_ERROR_NAMED(LOGNAME, "multi_dof_joint_state has %zu names and %zu transforms", mjs.joint_names.size(),
                    mjs.transforms.size());
    return false;
  }
  for (std::size_t i = 0; i < mjs.joint_names.size(); ++i)
  {
    const JointModel* joint = state.getRobotModel()->getJointModel(mjs.joint_names[i]);
    if (!joint)
      return false;
    const geometry_msgs::Transform& t = mjs.transforms[i];
    Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
    transform.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
    transform.linear() =
        Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized().toRotationMatrix();
    state.setJointPositions(joint, transform);
  }
  return true;
}
}  // namespace

bool jointStateToRobotState(const sensor_msgs::JointState& joint_state, RobotState& state)
{
  if (joint_state.name.size() != joint_state.position.size())
  {
    ROS_ERROR_NAMED(LOGNAME, "joint_state has %zu names and %zu positions", joint_state.name.size(),
                    joint_state.position.size());
    return false;
  }
  state.setVariableValues(joint_state);
  state.update();
  return true;
}

bool robotStateMsgToRobotState(const moveit_msgs::RobotState& robot_state, RobotState& state,
                               bool copy_attached_bodies)
{
  bool ok = true;
  if (!robot_state.joint_state.name.empty())
    ok = jointStateToRobotState(robot_state.joint_state, state) && ok;
  if (!robot_state.multi_dof_joint_state.joint_names.empty())
    ok = multiDofJointsToRobotState(robot_state.multi_dof_joint_state, state) && ok;
  if (copy_attached_bodies && !robot_state.attached_collision_objects.empty())
    ROS_WARN_NAMED(LOGNAME, "%zu attached collision objects in the message are not attached: RobotState's attached "
                            "bodies are not provided here",
                   robot_state.attached_collision_objects.size());
  state.update();
  return ok;
}

void robotStateToRobotStateMsg(const RobotState& state, moveit_msgs::RobotState& robot_state,
                               bool /*copy_attached_bodies*/)
{
  robot_state.is_diff = false;
  robotStateToJointStateMsg(state, robot_state.joint_state);
  robot_state.multi_dof_joint_state = sensor_msgs::MultiDOFJointState();
  robot_state.attached_collision_objects.clear();
  const RobotModel& model = *state.getRobotModel();
  robot_state.multi_dof_joint_state.header.frame_id = model.getModelFrame();
  for (const JointModel* joint : model.getMultiDOFJointModels())
  {
    Eigen::Isometry3d t;
    joint->computeTransform(state.getJointPositions(joint), t);
    geometry_msgs::Transform msg;
    msg.translation.x = t.translation().x();
    msg.translation.y = t.translation().y();
    msg.translation.z = t.translation().z();
    const Eigen::Quaterniond q(t.linear());
    msg.rotation.x = q.x();
    msg.rotation.y = q.y();
    msg.rotation.z = q.z();
    msg.rotation.w = q.w();
    robot_state.multi_dof_joint_state.joint_names.push_back(joint->getName());
    robot_state.multi_dof_joint_state.transforms.push_back(msg);
  }
}

void robotStateToJointStateMsg(const RobotState& state, sensor_msgs::JointState& joint_state)
{
  joint_state = sensor_msgs::JointState();
  for (const JointModel* joint : state.getRobotModel()->getSingleDOFJointModels())
  {
    const int index = joint->getFirstVariableIndex();
    joint_state.name.push_back(joint->getName());
    joint_state.position.push_back(state.getVariablePosition(index));
    if (state.hasVelocities())
      joint_state.velocity.push_back(state.getVariableVelocity(index));
  }
  if (joint_state.velocity.size() != joint_state.position.size())
    joint_state.velocity.clear();
}

bool jointTrajPointToRobotState(const trajectory_msgs::JointTrajectory& trajectory, std::size_t point_id,
                                RobotState& state)
{
  if (trajectory.points.empty() || point_id >= trajectory.points.size())
  {
    ROS_ERROR_NAMED(LOGNAME, "Trajectory has no point %zu", point_id);
    return false;
  }
  const trajectory_msgs::JointTrajectoryPoint& point = trajectory.points[point_id];
  state.setVariablePositions(trajectory.joint_names, point.positions);
  if (!point.velocities.empty())
    state.setVariableVelocities(trajectory.joint_names, point.velocities);
  if (!point.effort.empty())
    state.setVariableEffort(trajectory.joint_names, point.effort);
  return true;
}

void robotStateToStream(const RobotState& state, std::ostream& out, bool include_header, const std::string& separator)
{
  const std::vector<std::string>& names = state.getVariableNames();
  if (include_header)
  {
    for (std::size_t i = 0; i < names.size(); ++i)
      out << names[i] << (i + 1 < names.size() ? separator : "");
    out << std::endl;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
    out << state.getVariablePosition(i) << (i + 1 < names.size() ? separator : "");
  out << std::endl;
}

void robotStateToStream(const RobotState& state, std::ostream& out,
                        const std::vector<std::string>& joint_groups_ordering, bool include_header,
                        const std::string& separator)
{
  std::vector<std::string> names;
  std::vector<double> values;
  for (const std::string& group_name : joint_groups_ordering)
  {
    const JointModelGroup* jmg = state.getRobotModel()->getJointModelGroup(group_name);
    if (!jmg)
      continue;
    std::vector<double> group_values;
    state.copyJointGroupPositions(jmg, group_values);
    names.insert(names.end(), jmg->getVariableNames().begin(), jmg->getVariableNames().end());
    values.insert(values.end(), group_values.begin(), group_values.end());
  }
  if (include_header)
  {
    for (std::size_t i = 0; i < names.size(); ++i)
      out << names[i] << (i + 1 < names.size() ? separator : "");
    out << std::endl;
  }
  for (std::size_t i = 0; i < values.size(); ++i)
    out << values[i] << (i + 1 < values.size() ? separator : "");
  out << std::endl;
}

void streamToRobotState(RobotState& state, const std::string& line, const std::string& separator)
{
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= line.size())
  {
    const std::size_t end = line.find(separator, start);
    const std::string field = line.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!field.empty())
      values.push_back(std::stod(field));
    if (end == std::string::npos)
      break;
    start = end + separator.size();
  }
  if (values.size() != state.getVariableCount())
  {
    ROS_ERROR_NAMED(LOGNAME, "streamToRobotState: %zu values for %zu variables", values.size(),
                    state.getVariableCount());
    return;
  }
  state.setVariablePositions(values);
}
}  // namespace core
}  // namespace moveit
