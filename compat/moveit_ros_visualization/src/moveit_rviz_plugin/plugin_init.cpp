/* The displays' pluginlib exports, under MoveIt's class names. */
#include <pluginlib/class_list_macros.hpp>

#include "motion_planning_display.h"
#include "planning_scene_display.h"
#include "robot_state_display.h"
#include "trajectory_display.h"

PLUGINLIB_EXPORT_CLASS(moveit_rviz_plugin::PlanningSceneDisplay, rviz::Display)
PLUGINLIB_EXPORT_CLASS(moveit_rviz_plugin::TrajectoryDisplay, rviz::Display)
PLUGINLIB_EXPORT_CLASS(moveit_rviz_plugin::RobotStateDisplay, rviz::Display)
PLUGINLIB_EXPORT_CLASS(moveit_rviz_plugin::MotionPlanningDisplay, rviz::Display)
