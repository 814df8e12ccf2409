// rviz_visual_tools::RemoteControl, written anew with upstream's semantics (rviz_visual_tools
// noetic-devel 3.9.1 src/remote_control.cpp, lines cited below).
#include <rviz_visual_tools/remote_control.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace rviz_visual_tools
{
namespace
{
// The panel's topic and queue (remote_control.cpp l. 55-58)
const char* const DASHBOARD_TOPIC = "/rviz_visual_tools_gui";
const std::size_t DASHBOARD_QUEUE_SIZE = 10;
// How often a wait looks at the buttons and spins the callback queue (l. 159)
const double WAIT_POLL_PERIOD = 0.25;
// The Joy buttons' meanings (l. 67-86)
const std::size_t BUTTON_NEXT = 1;
const std::size_t BUTTON_CONTINUE = 2;
const std::size_t BUTTON_FULL_CONTINUE = 3;
const std::size_t BUTTON_STOP = 4;

const char* const CONSOLE_CYAN = "\033[96m";
const char* const CONSOLE_RESET = "\033[0m";

bool pressed(const sensor_msgs::Joy& msg, std::size_t button)
{
  return msg.buttons.size() > button && msg.buttons[button] != 0;
}
}  // namespace

RemoteControl::RemoteControl(const ros::NodeHandle& nh) : nh_(nh)
{
  rviz_dashboard_sub_ = nh_.subscribe<sensor_msgs::Joy>(DASHBOARD_TOPIC, DASHBOARD_QUEUE_SIZE,
                                                        &RemoteControl::rvizDashboardCallback, this);
  ROS_INFO_STREAM_NAMED(name_, "RemoteControl Ready.");
}

void RemoteControl::rvizDashboardCallback(const sensor_msgs::Joy::ConstPtr& msg)
{
  // The first pressed button in this order decides, as upstream's if-else chain does; upstream
  // indexes buttons[] unchecked, a shorter message here counts as no button pressed.
  if (pressed(*msg, BUTTON_NEXT))
  {
    setReadyForNextStep();
  }
  else if (pressed(*msg, BUTTON_CONTINUE))
  {
    setAutonomous();
  }
  else if (pressed(*msg, BUTTON_FULL_CONTINUE))
  {
    setFullAutonomous();
  }
  else if (pressed(*msg, BUTTON_STOP))
  {
    setStop();
  }
  else
  {
    ROS_ERROR_STREAM_NAMED(name_, "Unknown input button");
  }
}

bool RemoteControl::setReadyForNextStep()
{
  // A "next" only counts while something waits (l. 89-98)
  stop_ = false;
  if (is_waiting_)
  {
    next_step_ready_ = true;
  }
  return true;
}

void RemoteControl::setAutonomous(bool autonomous)
{
  autonomous_ = autonomous;
  stop_ = false;
}

void RemoteControl::setFullAutonomous(bool autonomous)
{
  full_autonomous_ = autonomous;
  autonomous_ = autonomous;
  stop_ = false;
}

void RemoteControl::setStop(bool stop)
{
  stop_ = stop;
  if (stop)
  {
    autonomous_ = false;
    full_autonomous_ = false;
  }
}

bool RemoteControl::getStop()
{
  return stop_;
}

bool RemoteControl::getAutonomous()
{
  return autonomous_;
}

bool RemoteControl::getFullAutonomous()
{
  return full_autonomous_;
}

bool RemoteControl::waitForNextStep(const std::string& caption)
{
  return waitUntil(caption, [this] { return next_step_ready_ || autonomous_; });
}

bool RemoteControl::waitForNextFullStep(const std::string& caption)
{
  return waitUntil(caption, [this] { return next_step_ready_ || full_autonomous_; });
}

bool RemoteControl::waitUntil(const std::string& caption, const std::function<bool()>& released)
{
  // Nothing to wait for (l. 140-144)
  if (released() || !ros::ok())
  {
    return true;
  }

  std::cout << std::endl
            << CONSOLE_CYAN << "Waiting to continue: " << caption << CONSOLE_RESET << std::flush;
  // Waiting before the waiting state is shown (upstream shows it first, l. 150-155): a "next"
  // sent as soon as it shows is not dropped
  is_waiting_ = true;
  if (displayWaitingState_)
  {
    displayWaitingState_(true);
  }

  while (!released() && ros::ok())
  {
    ros::Duration(WAIT_POLL_PERIOD).sleep();
    ros::spinOnce();
  }
  if (!ros::ok())
  {
    // Shut down while waiting: upstream leaves the program here (l. 162-165)
    std::exit(EXIT_SUCCESS);
  }

  next_step_ready_ = false;
  is_waiting_ = false;
  std::cout << CONSOLE_CYAN << "... continuing" << CONSOLE_RESET << std::endl;
  if (displayWaitingState_)
  {
    displayWaitingState_(false);
  }
  return true;
}

}  // namespace rviz_visual_tools
