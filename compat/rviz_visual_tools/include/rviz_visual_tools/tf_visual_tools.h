// rviz_visual_tools::TFVisualTools with the names and signatures of rviz_visual_tools noetic-devel 3.9.1
// (include/rviz_visual_tools/tf_visual_tools.h): transforms kept and re-broadcast on /tf by a timer, so that a
// debugging frame stays visible in rviz.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <boost/shared_ptr.hpp>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

namespace rviz_visual_tools
{
class TFVisualTools
{
public:
  // loop_hz: how often every kept transform is broadcast again (upstream's default, 2 Hz)
  explicit TFVisualTools(double loop_hz = 2);

  // Keeps the transform of `to_frame` in `from_frame` (replacing the pair's earlier one); broadcast from the next
  // timer tick on. Always true, as upstream's.
  bool publishTransform(const Eigen::Isometry3d& transform, const std::string& from_frame, const std::string& to_frame);

  // Forgets every kept transform: the timer broadcasts none of them any more
  void clearAllTransforms();

  // The timer's callback: every kept transform, stamped now
  void publishAllTransforms(const ros::TimerEvent& e);

private:
  ros::NodeHandle nh_;
  tf2_ros::TransformBroadcaster tf_pub_;
  ros::Timer non_realtime_loop_;
  std::vector<geometry_msgs::TransformStamped> transforms_;
};

typedef boost::shared_ptr<TFVisualTools> TFVisualToolsPtr;
typedef boost::shared_ptr<const TFVisualTools> TFVisualToolsConstPtr;

}  // namespace rviz_visual_tools
