// rviz_visual_tools::RemoteControl as rviz_visual_tools noetic-devel 3.9.1 declares it
// (include/rviz_visual_tools/remote_control.h): a break point in a program, released by a
// sensor_msgs/Joy on /rviz_visual_tools_gui, which upstream's RvizVisualToolsGui panel sends
// and `rostopic pub` can send as well. Written anew (compat/, see compat/README.md).
//
// Buttons (src/remote_control.cpp l. 65-87, the first pressed one counts):
//   buttons[1] next: releases a waitForNextStep that is waiting (a press while nothing waits is
//              forgotten, l. 89-98);
//   buttons[2] continue: autonomous, waitForNextStep no longer stops;
//   buttons[3] full continue: waitForNextFullStep no longer stops either;
//   buttons[4] stop: leaves the autonomous modes.
// Provided: everything upstream's header declares. Not provided: the rviz panel itself
// (publish the Joy by hand: `rostopic pub -1 /rviz_visual_tools_gui sensor_msgs/Joy
// '{buttons: [0, 1, 0, 0, 0, 0]}'`).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/Joy.h>

namespace rviz_visual_tools
{
/** \brief Called with true when a wait begins and false when it ends (e.g. to show a marker) */
typedef std::function<void(bool)> DisplayWaitingState;

class RemoteControl
{
public:
  /** \brief Subscribes /rviz_visual_tools_gui through nh (the topic is absolute, as upstream's) */
  explicit RemoteControl(const ros::NodeHandle& nh);

  /** \brief A Joy message from the panel: see the button table above */
  void rvizDashboardCallback(const sensor_msgs::Joy::ConstPtr& msg);

  /** \brief As the "next" button: releases a waiting waitForNextStep */
  bool setReadyForNextStep();

  /** \brief As the "continue" / "full continue" buttons */
  void setAutonomous(bool autonomous = true);
  void setFullAutonomous(bool autonomous = true);

  bool getAutonomous();
  bool getFullAutonomous();

  /** \brief As the "stop" button: leaves both autonomous modes */
  void setStop(bool stop = true);
  bool getStop();

  /**
   * \brief Block until "next" (or an autonomous mode) releases the program, spinning the global
   *        callback queue meanwhile. If ROS shuts down while waiting the process exits with 0, as
   *        upstream's does (remote_control.cpp l. 162-165).
   * \return true
   */
  bool waitForNextStep(const std::string& caption = "go to next step");
  bool waitForNextFullStep(const std::string& caption = "go to next full step");

  /** \brief True while a waitForNextStep / waitForNextFullStep is blocking */
  bool isWaiting()
  {
    return is_waiting_;
  }

  void setDisplayWaitingState(DisplayWaitingState displayWaitingState)
  {
    displayWaitingState_ = displayWaitingState;
  }

private:
  /** \brief The shared body of both waits: released when `released()` becomes true */
  bool waitUntil(const std::string& caption, const std::function<bool()>& released);

  ros::NodeHandle nh_;
  std::string name_ = "remote_control";
  ros::Subscriber rviz_dashboard_sub_;

  // Written by the subscriber's callback (possibly an AsyncSpinner's thread), read by the
  // waiting thread: atomics rather than upstream's plain bools.
  std::atomic<bool> is_waiting_{ false };
  std::atomic<bool> next_step_ready_{ false };
  std::atomic<bool> autonomous_{ false };
  std::atomic<bool> full_autonomous_{ false };
  std::atomic<bool> stop_{ false };

  DisplayWaitingState displayWaitingState_;
};

typedef std::shared_ptr<RemoteControl> RemoteControlPtr;
typedef std::shared_ptr<const RemoteControl> RemoteControlConstPtr;

}  // namespace rviz_visual_tools
