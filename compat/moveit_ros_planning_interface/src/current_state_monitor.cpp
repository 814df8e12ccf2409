#include "current_state_monitor.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace moveit
{
namespace planning_interface
{
namespace detail
{
namespace
{
const char JOINT_STATES_TOPIC[] = "joint_states";
// MoveIt's CurrentStateMonitor subscribes with a queue of 25 messages (current_state_monitor.cpp l. 187)
const uint32_t JOINT_STATES_QUEUE = 25;
}  // namespace

CurrentStateMonitor::CurrentStateMonitor(const moveit::core::RobotModelConstPtr& model,
                                         const ros::NodeHandle& node_handle)
  : model_(model), node_handle_(node_handle)
{
  node_handle_.setCallbackQueue(&queue_);
}

CurrentStateMonitor::~CurrentStateMonitor()
{
  if (spinner_)
    spinner_->stop();
  subscriber_.shutdown();
}

bool CurrentStateMonitor::isActive() const
{
  return static_cast<bool>(subscriber_);
}

void CurrentStateMonitor::startStateMonitor()
{
  if (isActive())
    return;
  subscriber_ = node_handle_.subscribe(JOINT_STATES_TOPIC, JOINT_STATES_QUEUE, &CurrentStateMonitor::jointStateCallback,
                                       this, ros::TransportHints().tcpNoDelay());
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
}

void CurrentStateMonitor::jointStateCallback(const sensor_msgs::JointStateConstPtr& message)
{
  if (message->name.size() != message->position.size())
  {
    ROS_ERROR_THROTTLE_NAMED(1, "current_state_monitor",
                             "joint_states: %zu names and %zu positions; the message is ignored",
                             message->name.size(), message->position.size());
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < message->name.size(); ++i)
    {
      const std::string& name = message->name[i];
      // joints the model lacks, and fixed or multi-DOF ones, are not read from joint_states (l. 345-350)
      if (!model_->hasJointModel(name) || model_->getJointModel(name)->getVariableCount() != 1 ||
          !std::isfinite(message->position[i]))
        continue;
      positions_[name] = message->position[i];
      // the newest stamp is kept (l. 351-353); an older one (a looped bag, for MoveIt, which then restarts its clock:
      // l. 355-361) does not take the joint back in time
      ros::Time& stamp = joint_time_[name];
      stamp = std::max(stamp, message->header.stamp);
    }
  }
  updated_.notify_all();
}

ros::Time CurrentStateMonitor::oldestUpdate() const
{
  ros::Time oldest;
  for (const moveit::core::JointModel* joint : model_->getActiveJointModels())
  {
    auto it = joint_time_.find(joint->getName());
    if (it == joint_time_.end())
      continue;  // never named: not waited for (l. 99-102)
    oldest = oldest.isZero() ? it->second : std::min(oldest, it->second);
  }
  return oldest;
}

bool CurrentStateMonitor::waitForCurrentState(const ros::Time& t, double wait_seconds) const
{
  std::unique_lock<std::mutex> lock(mutex_);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_seconds);
  while (oldestUpdate() < t || joint_time_.empty())
  {
    if (updated_.wait_until(lock, deadline) == std::cv_status::timeout)
    {
      if (oldestUpdate() >= t && !joint_time_.empty())
        break;
      ROS_INFO_STREAM_NAMED("current_state_monitor", "Didn't receive robot state (joint angles) with recent "
                                                     "timestamp within "
                                                         << wait_seconds << " seconds (topic '"
                                                         << subscriber_.getTopic() << "')");
      return false;
    }
  }
  return true;
}

bool CurrentStateMonitor::waitForCompleteState(const std::string& group, double wait_seconds) const
{
  const moveit::core::JointModelGroup* jmg = model_->getJointModelGroup(group);
  if (!jmg)
    return false;
  std::unique_lock<std::mutex> lock(mutex_);
  auto complete = [&] {
    for (const moveit::core::JointModel* joint : jmg->getActiveJointModels())
      if (joint_time_.find(joint->getName()) == joint_time_.end())
        return false;
    return true;
  };
  return updated_.wait_for(lock, std::chrono::duration<double>(wait_seconds), complete);
}

moveit::core::RobotStatePtr CurrentStateMonitor::getCurrentState() const
{
  auto state = std::make_shared<moveit::core::RobotState>(model_);
  state->setToDefaultValues();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state->setVariablePositions(positions_);
  }
  state->update();
  return state;
}
}  // namespace detail
}  // namespace planning_interface
}  // namespace moveit
