// Internal to moveit_ros_planning_interface: a publisher's first message is lost when it is published before the
// subscriber has connected, so one-shot messages (a scene diff, a "stop") wait for the connection first.
#pragma once

#include <ros/ros.h>

namespace moveit
{
namespace planning_interface
{
namespace detail
{
// How long a one-shot message waits for move_group's subscription: connecting takes milliseconds on one machine; a
// move_group that is not running is not waited for longer than this
constexpr double SUBSCRIBER_WAIT_SECONDS = 2.0;
// How often the connection is looked at meanwhile
constexpr double SUBSCRIBER_POLL_SECONDS = 0.005;

inline bool waitForSubscriber(const ros::Publisher& publisher, double seconds = SUBSCRIBER_WAIT_SECONDS)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (publisher.getNumSubscribers() == 0 && ros::ok() && ros::WallTime::now() < end)
    ros::WallDuration(SUBSCRIBER_POLL_SECONDS).sleep();
  return publisher.getNumSubscribers() > 0;
}
}  // namespace detail
}  // namespace planning_interface
}  // namespace moveit
