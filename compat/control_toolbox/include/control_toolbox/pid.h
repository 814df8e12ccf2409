// control_toolbox::Pid as ros-controls/control_toolbox noetic-devel de05a5c declares it
// (include/control_toolbox/pid.h) and computes it (src/pid.cpp), written anew. The same
// formulas run in sim_bridge's Python emulation (sim_bridge/src/sim_bridge/ros_control/pid.py),
// which ros_control's controllers use there.
//
//   command = p * error + clamp(i * integral(error dt), i_min, i_max) + d * error_dot
//
// error is target - state (pid.cpp l. 337). With antiwindup the integral itself is clamped to
// [i_min / i, i_max / i] and its term is not (l. 349-363). Gains live in a RealtimeBuffer so
// that dynamic_reconfigure (the ParametersConfig server, in the namespace init() was given)
// changes them without blocking computeCommand. With ~publish_state, every command is
// published on <namespace>/state as control_msgs/PidState (l. 141-147, 371-391).
#ifndef CONTROL_TOOLBOX_PID_H
#define CONTROL_TOOLBOX_PID_H

#include <control_msgs/PidState.h>
#include <control_toolbox/ParametersConfig.h>
#include <dynamic_reconfigure/server.h>
#include <realtime_tools/realtime_buffer.h>
#include <realtime_tools/realtime_publisher.h>
#include <ros/ros.h>

#include <boost/shared_ptr.hpp>
#include <boost/thread/recursive_mutex.hpp>

#include <string>

class TiXmlElement;

namespace control_toolbox
{

class Pid
{
public:
  struct Gains
  {
    Gains(double p, double i, double d, double i_max, double i_min)
      : p_gain_(p), i_gain_(i), d_gain_(d), i_max_(i_max), i_min_(i_min), antiwindup_(false)
    {
    }
    Gains(double p, double i, double d, double i_max, double i_min, bool antiwindup)
      : p_gain_(p), i_gain_(i), d_gain_(d), i_max_(i_max), i_min_(i_min), antiwindup_(antiwindup)
    {
    }
    Gains() : p_gain_(0.0), i_gain_(0.0), d_gain_(0.0), i_max_(0.0), i_min_(0.0), antiwindup_(false)
    {
    }
    double p_gain_;
    double i_gain_;
    double d_gain_;
    double i_max_;     // upper bound of the integral term
    double i_min_;     // lower bound of the integral term
    bool antiwindup_;  // clamp the integral instead of its term
  };

  Pid(double p = 0.0, double i = 0.0, double d = 0.0, double i_max = 0.0, double i_min = -0.0,
      bool antiwindup = false);
  // a copy has the source's gains and a fresh state, and no dynamic_reconfigure server
  Pid(const Pid& source);
  ~Pid();

  void initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  // the node handle is ignored, as upstream's: the server goes to the namespace "pid"
  void initPid(double p, double i, double d, double i_max, double i_min, const ros::NodeHandle& node);
  void initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup,
               const ros::NodeHandle& node);
  bool initParam(const std::string& prefix, const bool quiet = false);
  // gains from the parameters p (required), i, d, i_clamp, i_clamp_min, i_clamp_max,
  // antiwindup, publish_state under node's namespace; false without p
  bool init(const ros::NodeHandle& node, const bool quiet = false);
  // gains from the attributes p, i, d, iClamp, antiwindup
  bool initXml(TiXmlElement* config);
  void initDynamicReconfig(ros::NodeHandle& node);

  void reset();
  void reset(double d_error, double i_error);

  void getGains(double& p, double& i, double& d, double& i_max, double& i_min);
  void getGains(double& p, double& i, double& d, double& i_max, double& i_min, bool& antiwindup);
  Gains getGains();
  void setGains(double p, double i, double d, double i_max, double i_min, bool antiwindup = false);
  void setGains(const Gains& gains);

  void updateDynamicReconfig();
  void updateDynamicReconfig(Gains gains_config);
  void updateDynamicReconfig(control_toolbox::ParametersConfig config);
  void dynamicReconfigCallback(control_toolbox::ParametersConfig& config, uint32_t level);

  // error = target - state; the derivative from the change of error over dt
  double computeCommand(double error, ros::Duration dt);
  // with the error's derivative given (a velocity error, say)
  double computeCommand(double error, double error_dot, ros::Duration dt);
  // the old convention, error = state - target: -computeCommand
  ROS_DEPRECATED double updatePid(double p_error, ros::Duration dt);
  ROS_DEPRECATED double updatePid(double error, double error_dot, ros::Duration dt);

  void setCurrentCmd(double cmd);
  double getCurrentCmd();
  void getCurrentPIDErrors(double* pe, double* ie, double* de);
  void printValues();

  Pid& operator=(const Pid& source);

private:
  typedef dynamic_reconfigure::Server<control_toolbox::ParametersConfig> DynamicReconfigServer;

  realtime_tools::RealtimeBuffer<Gains> gains_buffer_;
  boost::shared_ptr<realtime_tools::RealtimePublisher<control_msgs::PidState> > state_publisher_;
  bool publish_state_ = false;
  bool valid_p_error_last_ = false;
  double p_error_last_ = 0.0;
  double p_error_ = 0.0;
  double i_error_ = 0.0;
  double d_error_ = 0.0;
  double cmd_ = 0.0;

  bool dynamic_reconfig_initialized_ = false;
  boost::shared_ptr<DynamicReconfigServer> param_reconfig_server_;
  DynamicReconfigServer::CallbackType param_reconfig_callback_;
  boost::recursive_mutex param_reconfig_mutex_;
};

}  // namespace control_toolbox

#endif  // CONTROL_TOOLBOX_PID_H
