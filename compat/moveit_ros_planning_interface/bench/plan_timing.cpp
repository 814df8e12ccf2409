// make bench's C++ MoveIt client (tools/bench/moveit_cost.py): MoveGroupInterface::plan to the group's named
// targets in turn, each timed from the call to its answer, beside the planning time move_group reports. One JSON
// line per plan on stdout. tools/bench/plan_timing.py does the same through moveit_commander, so that the two
// clients are compared on the same move_group, goals and start.
// move_group waits for a joint_states message newer than each request before planning (move_action_capability.cpp:67
// on noetic-devel): the bench publishes them at 1 kHz meanwhile, so that the wait is under a millisecond for both.
//
// Private parameters: ~group (the planning group), ~targets (named targets, planned to in turn), ~count (plans).
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

#include <moveit/move_group_interface/move_group_interface.h>
#include <ros/ros.h>

namespace
{
constexpr int DEFAULT_COUNT = 40;
constexpr double MS_PER_S = 1000.0;
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "plan_timing_cpp");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  ros::NodeHandle parameters("~");
  std::string group;
  std::vector<std::string> targets;
  int count = DEFAULT_COUNT;
  parameters.param<std::string>("group", group, "interbotix_arm");
  parameters.param("count", count, DEFAULT_COUNT);
  if (!parameters.getParam("targets", targets) || targets.empty())
  {
    ROS_FATAL("plan_timing: ~targets (a list of the group's named targets) is not set");
    return 1;
  }
  moveit::planning_interface::MoveGroupInterface move_group(group);
  for (int i = 0; i < count && ros::ok(); ++i)
  {
    move_group.setNamedTarget(targets[i % targets.size()]);
    moveit::planning_interface::MoveGroupInterface::Plan plan;
    const auto began = std::chrono::steady_clock::now();
    const bool planned = static_cast<bool>(move_group.plan(plan));
    const std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - began;
    std::cout << "{\"wall_ms\": " << wall.count() << ", \"planning_ms\": " << plan.planning_time_ * MS_PER_S
              << ", \"planned\": " << (planned ? "true" : "false") << "}" << std::endl;
  }
  return 0;
}
