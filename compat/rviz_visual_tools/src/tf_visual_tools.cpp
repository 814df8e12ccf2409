// TFVisualTools as rviz_visual_tools noetic-devel 3.9.1's src/tf_visual_tools.cpp behaves (lines cited): the
// transforms a user hands in are kept and the whole set is sent on /tf at each tick of a timer.
#include <rviz_visual_tools/tf_visual_tools.h>

#include <cmath>

namespace rviz_visual_tools
{
namespace
{
const char LOGNAME[] = "tf_visual_tools";
}  // namespace

TFVisualTools::TFVisualTools(double loop_hz)
{
  // one timer at the given rate (l. 49-55)
  non_realtime_loop_ = nh_.createTimer(ros::Duration(1.0 / loop_hz), &TFVisualTools::publishAllTransforms, this);
  ROS_INFO_STREAM_NAMED(LOGNAME, "TFVisualTools Ready.");
}

bool TFVisualTools::publishTransform(const Eigen::Isometry3d& transform, const std::string& from_frame,
                                     const std::string& to_frame)
{
  ROS_DEBUG_STREAM_NAMED(LOGNAME, "Publishing transform from " << from_frame << " to " << to_frame);
  geometry_msgs::TransformStamped msg;
  msg.header.stamp = ros::Time::now();
  msg.header.frame_id = from_frame;
  msg.child_frame_id = to_frame;
  msg.transform.translation.x = transform.translation().x();
  msg.transform.translation.y = transform.translation().y();
  msg.transform.translation.z = transform.translation().z();
  // the rotation's quaternion scaled to unit length (l. 66-77)
  const Eigen::Quaterniond q(transform.rotation());
  const double norm = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z() + q.w() * q.w());
  msg.transform.rotation.x = q.x() / norm;
  msg.transform.rotation.y = q.y() / norm;
  msg.transform.rotation.z = q.z() / norm;
  msg.transform.rotation.w = q.w() / norm;

  // the same parent and child again: its transform replaced in place, its stamp kept (l. 82-95)
  for (geometry_msgs::TransformStamped& kept : transforms_)
  {
    if (kept.child_frame_id == to_frame && kept.header.frame_id == from_frame)
    {
      kept.transform = msg.transform;
      return true;
    }
  }
  transforms_.push_back(msg);
  return true;
}

void TFVisualTools::clearAllTransforms()
{
  transforms_.clear();
}

void TFVisualTools::publishAllTransforms(const ros::TimerEvent& /*e*/)
{
  ROS_DEBUG_STREAM_NAMED(LOGNAME, "Publishing transforms");
  // all restamped now and sent as one message (l. 103-114)
  for (geometry_msgs::TransformStamped& kept : transforms_)
    kept.header.stamp = ros::Time::now();
  tf_pub_.sendTransform(transforms_);
}

}  // namespace rviz_visual_tools
