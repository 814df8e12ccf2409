// control_toolbox::Pid, each step as control_toolbox noetic-devel de05a5c src/pid.cpp takes
// it (cited by line); sim_bridge's ros_control/pid.py cites the same lines.
#include <control_toolbox/pid.h>

#include <tinyxml.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace control_toolbox
{

namespace
{
// pid.cpp l. 49: where initPid(..., node) and initXml put the dynamic_reconfigure server
const char* const DEFAULT_NAMESPACE = "pid";
// l. 146: the state publisher's queue
const int STATE_QUEUE_SIZE = 1;

bool usable(double value)
{
  return !std::isnan(value) && !std::isinf(value);
}
}  // namespace

Pid::Pid(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  setGains(p, i, d, i_max, i_min, antiwindup);  // l. 51-57
  reset();
}

Pid::Pid(const Pid& source)
{
  gains_buffer_ = source.gains_buffer_;  // l. 59-67
  reset();
}

Pid::~Pid()
{
}

Pid& Pid::operator=(const Pid& source)
{
  if (this != &source)
  {
    gains_buffer_ = source.gains_buffer_;  // pid.h: the gains, and a fresh state
    reset();
  }
  return *this;
}

void Pid::initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  setGains(p, i, d, i_max, i_min, antiwindup);  // l. 93-98
  reset();
}

void Pid::initPid(double p, double i, double d, double i_max, double i_min, const ros::NodeHandle& /*node*/)
{
  initPid(p, i, d, i_max, i_min);  // l. 73-81
  ros::NodeHandle nh(DEFAULT_NAMESPACE);
  initDynamicReconfig(nh);
}

void Pid::initPid(double p, double i, double d, double i_max, double i_min, bool antiwindup,
                  const ros::NodeHandle& /*node*/)
{
  initPid(p, i, d, i_max, i_min, antiwindup);  // l. 83-91
  ros::NodeHandle nh(DEFAULT_NAMESPACE);
  initDynamicReconfig(nh);
}

bool Pid::initParam(const std::string& prefix, const bool quiet)
{
  ros::NodeHandle nh(prefix);  // l. 100-104
  return init(nh, quiet);
}

bool Pid::init(const ros::NodeHandle& node, const bool quiet)
{
  ros::NodeHandle nh(node);
  Gains gains;
  if (!nh.getParam("p", gains.p_gain_))  // l. 113-119: only p is required
  {
    if (!quiet)
      ROS_ERROR("No p gain specified for pid.  Namespace: %s", nh.getNamespace().c_str());
    return false;
  }
  nh.param("i", gains.i_gain_, 0.0);  // l. 121-122
  nh.param("d", gains.d_gain_, 0.0);

  double i_clamp;  // l. 125-128: one symmetric bound ...
  nh.param("i_clamp", i_clamp, 0.0);
  gains.i_max_ = std::abs(i_clamp);
  gains.i_min_ = -std::abs(i_clamp);
  if (nh.hasParam("i_clamp_min"))  // l. 129-133: ... or either side, its sign forced
  {
    nh.param("i_clamp_min", gains.i_min_, gains.i_min_);
    gains.i_min_ = -std::abs(gains.i_min_);
  }
  if (nh.hasParam("i_clamp_max"))  // l. 134-138
  {
    nh.param("i_clamp_max", gains.i_max_, gains.i_max_);
    gains.i_max_ = std::abs(gains.i_max_);
  }
  nh.param("antiwindup", gains.antiwindup_, false);  // l. 139

  nh.param("publish_state", publish_state_, false);  // l. 141-147
  if (publish_state_)
  {
    state_publisher_.reset(new realtime_tools::RealtimePublisher<control_msgs::PidState>());
    state_publisher_->init(nh, "state", STATE_QUEUE_SIZE);
  }

  setGains(gains);  // l. 149-152
  reset();
  initDynamicReconfig(nh);
  return true;
}

bool Pid::initXml(TiXmlElement* config)
{
  ros::NodeHandle nh(DEFAULT_NAMESPACE);  // l. 157-178
  auto attribute = [config](const char* name) {
    return config->Attribute(name) ? atof(config->Attribute(name)) : 0.0;
  };
  const double i_clamp = attribute("iClamp");
  setGains(attribute("p"), attribute("i"), attribute("d"), std::abs(i_clamp), -std::abs(i_clamp),
           attribute("antiwindup") != 0.0);
  reset();
  initDynamicReconfig(nh);
  return true;
}

void Pid::initDynamicReconfig(ros::NodeHandle& node)
{
  ROS_DEBUG_STREAM_NAMED("pid", "Initializing dynamic reconfigure in namespace " << node.getNamespace());
  // l. 180-195: the server starts from the Pid's gains, then calls back on every change
  param_reconfig_server_.reset(new DynamicReconfigServer(param_reconfig_mutex_, node));
  dynamic_reconfig_initialized_ = true;
  updateDynamicReconfig();
  param_reconfig_callback_ = std::bind(&Pid::dynamicReconfigCallback, this, std::placeholders::_1,
                                       std::placeholders::_2);
  param_reconfig_server_->setCallback(param_reconfig_callback_);
}

void Pid::reset()
{
  // l. 197-201: after reset(0, 0) the last error counts as a valid 0, so the first
  // derivative after a reset is (error - 0) / dt
  reset(0.0, 0.0);
  valid_p_error_last_ = true;
}

void Pid::reset(double d_error, double i_error)
{
  p_error_last_ = 0.0;  // l. 203-211
  p_error_ = 0.0;
  i_error_ = i_error;
  d_error_ = d_error;
  cmd_ = 0.0;
  valid_p_error_last_ = false;
}

void Pid::getGains(double& p, double& i, double& d, double& i_max, double& i_min)
{
  bool antiwindup;
  getGains(p, i, d, i_max, i_min, antiwindup);
}

void Pid::getGains(double& p, double& i, double& d, double& i_max, double& i_min, bool& antiwindup)
{
  const Gains gains = *gains_buffer_.readFromRT();  // l. 219-229
  p = gains.p_gain_;
  i = gains.i_gain_;
  d = gains.d_gain_;
  i_max = gains.i_max_;
  i_min = gains.i_min_;
  antiwindup = gains.antiwindup_;
}

Pid::Gains Pid::getGains()
{
  return *gains_buffer_.readFromRT();
}

void Pid::setGains(double p, double i, double d, double i_max, double i_min, bool antiwindup)
{
  setGains(Gains(p, i, d, i_max, i_min, antiwindup));
}

void Pid::setGains(const Gains& gains)
{
  gains_buffer_.writeFromNonRT(gains);  // l. 243-249: and the server shows them
  updateDynamicReconfig(gains);
}

void Pid::updateDynamicReconfig()
{
  if (!dynamic_reconfig_initialized_)
    return;
  control_toolbox::ParametersConfig config;  // l. 251-264
  getGains(config.p, config.i, config.d, config.i_clamp_max, config.i_clamp_min, config.antiwindup);
  updateDynamicReconfig(config);
}

void Pid::updateDynamicReconfig(Gains gains_config)
{
  if (!dynamic_reconfig_initialized_)
    return;
  control_toolbox::ParametersConfig config;  // l. 266-283
  config.p = gains_config.p_gain_;
  config.i = gains_config.i_gain_;
  config.d = gains_config.d_gain_;
  config.i_clamp_max = gains_config.i_max_;
  config.i_clamp_min = gains_config.i_min_;
  config.antiwindup = gains_config.antiwindup_;
  updateDynamicReconfig(config);
}

void Pid::updateDynamicReconfig(control_toolbox::ParametersConfig config)
{
  if (!dynamic_reconfig_initialized_)
    return;
  // l. 285-295: the server's own (recursive) mutex, which the reconfigure callback holds too
  boost::recursive_mutex::scoped_lock lock(param_reconfig_mutex_);
  param_reconfig_server_->updateConfig(config);
}

void Pid::dynamicReconfigCallback(control_toolbox::ParametersConfig& config, uint32_t /*level*/)
{
  ROS_DEBUG_STREAM_NAMED("pid", "Dynamics reconfigure callback recieved.");
  setGains(config.p, config.i, config.d, config.i_clamp_max, config.i_clamp_min, config.antiwindup);  // l. 297-303
}

double Pid::computeCommand(double error, ros::Duration dt)
{
  if (dt == ros::Duration(0.0) || !usable(error))  // l. 308-309
    return 0.0;
  double error_dot = d_error_;  // l. 311-321: the last derivative when dt < 0
  if (dt.toSec() > 0.0)
  {
    if (valid_p_error_last_)
      error_dot = (error - p_error_last_) / dt.toSec();
    p_error_last_ = error;
    valid_p_error_last_ = true;
  }
  return computeCommand(error, error_dot, dt);
}

double Pid::computeCommand(double error, double error_dot, ros::Duration dt)
{
  const Gains gains = *gains_buffer_.readFromRT();  // l. 334
  p_error_ = error;  // l. 337-338: kept before the checks below, as upstream's
  d_error_ = error_dot;
  if (dt == ros::Duration(0.0) || !usable(error) || !usable(error_dot))  // l. 340-341
    return 0.0;

  const double p_term = gains.p_gain_ * p_error_;  // l. 344
  i_error_ += dt.toSec() * p_error_;  // l. 347
  if (gains.antiwindup_ && gains.i_gain_ != 0)  // l. 349-354: the integral clamped
  {
    const double low = std::min(gains.i_min_ / gains.i_gain_, gains.i_max_ / gains.i_gain_);
    const double high = std::max(gains.i_min_ / gains.i_gain_, gains.i_max_ / gains.i_gain_);
    i_error_ = std::min(std::max(i_error_, low), high);
  }
  double i_term = gains.i_gain_ * i_error_;  // l. 357
  if (!gains.antiwindup_)  // l. 359-363: the term clamped
    i_term = std::min(std::max(i_term, gains.i_min_), gains.i_max_);
  const double d_term = gains.d_gain_ * d_error_;  // l. 366
  cmd_ = p_term + i_term + d_term;  // l. 369

  if (publish_state_ && state_publisher_ && state_publisher_->trylock())  // l. 372-391
  {
    control_msgs::PidState& state = state_publisher_->msg_;
    state.header.stamp = ros::Time::now();
    state.timestep = dt;
    state.error = error;
    state.error_dot = error_dot;
    state.p_error = p_error_;
    state.i_error = i_error_;
    state.d_error = d_error_;
    state.p_term = p_term;
    state.i_term = i_term;
    state.d_term = d_term;
    state.i_max = gains.i_max_;
    state.i_min = gains.i_min_;
    state.output = cmd_;
    state_publisher_->unlockAndPublish();
  }
  return cmd_;
}

double Pid::updatePid(double error, ros::Duration dt)
{
  return -computeCommand(error, dt);  // l. 326-329
}

double Pid::updatePid(double error, double error_dot, ros::Duration dt)
{
  return -computeCommand(error, error_dot, dt);  // l. 396-399
}

void Pid::setCurrentCmd(double cmd)
{
  cmd_ = cmd;
}

double Pid::getCurrentCmd()
{
  return cmd_;
}

void Pid::getCurrentPIDErrors(double* pe, double* ie, double* de)
{
  *pe = p_error_;  // l. 411-419
  *ie = i_error_;
  *de = d_error_;
}

void Pid::printValues()
{
  const Gains gains = getGains();
  ROS_INFO_STREAM_NAMED("pid", "Current Values of PID Class:\n"
                                   << "  P Gain: " << gains.p_gain_ << "\n"
                                   << "  I Gain: " << gains.i_gain_ << "\n"
                                   << "  D Gain: " << gains.d_gain_ << "\n"
                                   << "  I_Max:  " << gains.i_max_ << "\n"
                                   << "  I_Min:  " << gains.i_min_ << "\n"
                                   << "  Antiwindup:  " << gains.antiwindup_ << "\n"
                                   << "  P_Error_Last: " << p_error_last_ << "\n"
                                   << "  P_Error:      " << p_error_ << "\n"
                                   << "  I_Error:       " << i_error_ << "\n"
                                   << "  D_Error:      " << d_error_ << "\n"
                                   << "  Command:      " << cmd_);
}

}  // namespace control_toolbox
