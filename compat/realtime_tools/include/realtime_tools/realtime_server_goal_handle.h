// realtime_tools::RealtimeServerGoalHandle (realtime_tools noetic-devel 164f6d8,
// include/realtime_tools/realtime_server_goal_handle.h): an actionlib goal handle that a
// realtime loop ends or gives feedback on by request; runNonRealtime(), from a ROS timer,
// carries the requests out. The first of abort / cancel / succeed wins; abort and succeed
// act on an ACTIVE or PREEMPTING goal, cancel on a PREEMPTING one; feedback goes out while
// the goal is ACTIVE.
#ifndef REALTIME_TOOLS_REALTIME_SERVER_GOAL_HANDLE_H
#define REALTIME_TOOLS_REALTIME_SERVER_GOAL_HANDLE_H

#include <actionlib/server/action_server.h>

#include <memory>

namespace realtime_tools
{

template <class Action>
class RealtimeServerGoalHandle
{
private:
  ACTION_DEFINITION(Action);
  typedef actionlib::ServerGoalHandle<Action> GoalHandle;

  bool req_abort_ = false;
  bool req_cancel_ = false;
  bool req_succeed_ = false;
  ResultConstPtr req_result_;
  FeedbackConstPtr req_feedback_;

  bool requested() const
  {
    return req_abort_ || req_cancel_ || req_succeed_;
  }

public:
  GoalHandle gh_;
  // allocated here so that the realtime loop fills them without allocating
  ResultPtr preallocated_result_;
  FeedbackPtr preallocated_feedback_;

  // implicit, as upstream's
  RealtimeServerGoalHandle(GoalHandle& gh,  // NOLINT(runtime/explicit)
                           const ResultPtr& preallocated_result = ResultPtr(),
                           const FeedbackPtr& preallocated_feedback = FeedbackPtr())
    : gh_(gh), preallocated_result_(preallocated_result), preallocated_feedback_(preallocated_feedback)
  {
    if (!preallocated_result_)
      preallocated_result_.reset(new Result);
    if (!preallocated_feedback_)
      preallocated_feedback_.reset(new Feedback);
  }

  void setAborted(ResultConstPtr result = ResultConstPtr())
  {
    if (!requested())
    {
      req_result_ = result;
      req_abort_ = true;
    }
  }

  void setCanceled(ResultConstPtr result = ResultConstPtr())
  {
    if (!requested())
    {
      req_result_ = result;
      req_cancel_ = true;
    }
  }

  void setSucceeded(ResultConstPtr result = ResultConstPtr())
  {
    if (!requested())
    {
      req_result_ = result;
      req_succeed_ = true;
    }
  }

  void setFeedback(FeedbackConstPtr feedback = FeedbackConstPtr())
  {
    req_feedback_ = feedback;
  }

  bool valid()
  {
    return gh_.getGoal() != nullptr;
  }

  void runNonRealtime(const ros::TimerEvent& /*event*/)
  {
    if (!valid())
      return;
    using actionlib_msgs::GoalStatus;
    const uint8_t status = gh_.getGoalStatus().status;
    const bool running = status == GoalStatus::ACTIVE || status == GoalStatus::PREEMPTING;
    if (req_abort_ && running)
    {
      if (req_result_)
        gh_.setAborted(*req_result_);
      else
        gh_.setAborted();
    }
    else if (req_cancel_ && status == GoalStatus::PREEMPTING)
    {
      if (req_result_)
        gh_.setCanceled(*req_result_);
      else
        gh_.setCanceled();
    }
    else if (req_succeed_ && running)
    {
      if (req_result_)
        gh_.setSucceeded(*req_result_);
      else
        gh_.setSucceeded();
    }
    if (req_feedback_ && status == GoalStatus::ACTIVE)
      gh_.publishFeedback(*req_feedback_);
  }
};

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS_REALTIME_SERVER_GOAL_HANDLE_H
