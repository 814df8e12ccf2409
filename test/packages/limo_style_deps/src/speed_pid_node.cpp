// A LIMO-style speed loop: each measured speed (std_msgs/Float64 on measured_speed) steps a
// control_toolbox::Pid towards the target (target_speed) over the loop's fixed period, and
// the command goes out as ackermann_msgs/AckermannDriveStamped on ackermann_cmd through a
// realtime_tools::RealtimePublisher, limited by this node's SpeedLimit settings
// (dynamic_reconfigure). The Pid's gains are read from ~pid and tuned on ~pid with dynparam.
#include <ackermann_msgs/AckermannDriveStamped.h>
#include <control_toolbox/pid.h>
#include <dynamic_reconfigure/server.h>
#include <limo_style_deps/SpeedLimitConfig.h>
#include <realtime_tools/realtime_publisher.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>

#include <algorithm>

namespace limo_style_deps
{

class SpeedPidNode
{
public:
  explicit SpeedPidNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : command_publisher_(node, "ackermann_cmd", 1), limit_server_(private_node)
  {
    private_node.param("control_period", control_period_, 0.1);
    private_node.param("steering_angle", steering_angle_, 0.0);
    ROS_INFO("speed_pid_node: control_period %.3f s, steering_angle %.3f rad", control_period_,
             steering_angle_);
    if (!pid_.init(ros::NodeHandle(private_node, "pid")))
      ROS_FATAL("speed_pid_node: set ~pid/p (and optionally i, d, i_clamp) to run");
    limit_server_.setCallback([this](SpeedLimitConfig& config, uint32_t level) { onLimits(config, level); });
    target_subscriber_ = node.subscribe("target_speed", 1, &SpeedPidNode::onTarget, this);
    measured_subscriber_ = node.subscribe("measured_speed", 1, &SpeedPidNode::onMeasured, this);
  }

private:
  void onLimits(const SpeedLimitConfig& config, uint32_t /*level*/)
  {
    limits_ = config;
  }

  void onTarget(const std_msgs::Float64& target)
  {
    target_ = target.data;
  }

  void onMeasured(const std_msgs::Float64& measured)
  {
    double command = pid_.computeCommand(target_ - measured.data, ros::Duration(control_period_));
    command = limits_.enabled ? std::max(-limits_.max_speed, std::min(command, limits_.max_speed)) : 0.0;
    if (command_publisher_.trylock())
    {
      command_publisher_.msg_.header.stamp = ros::Time::now();
      command_publisher_.msg_.drive.speed = command;
      command_publisher_.msg_.drive.steering_angle = steering_angle_;
      command_publisher_.unlockAndPublish();
    }
  }

  control_toolbox::Pid pid_;
  realtime_tools::RealtimePublisher<ackermann_msgs::AckermannDriveStamped> command_publisher_;
  dynamic_reconfigure::Server<SpeedLimitConfig> limit_server_;
  SpeedLimitConfig limits_;
  ros::Subscriber target_subscriber_;
  ros::Subscriber measured_subscriber_;
  double control_period_ = 0.0;
  double steering_angle_ = 0.0;
  double target_ = 0.0;
};

}  // namespace limo_style_deps

int main(int argc, char** argv)
{
  ros::init(argc, argv, "speed_pid_node");
  limo_style_deps::SpeedPidNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
