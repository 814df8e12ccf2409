/* The animation follows TrajectoryVisualization::update (trajectory_visualization.cpp
 * l. 402-525 on noetic-devel): a new path waits until the one shown ends (unless
 * "Interrupt Display"), waypoints advance by the path's durations over the factor, the robot
 * hides at the end unless looping or trailing. */
#include "trajectory_visualization.h"

#include <algorithm>
#include <sstream>

#include <rviz/display.h>
#include <rviz/display_context.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/editable_enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/int_property.h>
#include <rviz/properties/ros_topic_property.h>

#include "message_checks.h"

namespace moveit_rviz_plugin
{
namespace
{
const char DEFAULT_DISPLAY_TIME[] = "3x";  // trajectory_visualization.cpp l. 357-358
const float DEFAULT_DISPLAY_TIME_VALUE = -3.0f;
}  // namespace

TrajectoryVisualization::TrajectoryVisualization(rviz::Property* widget, rviz::Display* display) : display_(display)
{
  trajectory_topic_property_ =
      new rviz::RosTopicProperty("Trajectory Topic", "move_group/display_planned_path",
                                 ros::message_traits::datatype<moveit_msgs::DisplayTrajectory>(),
                                 "The topic on which the moveit_msgs::DisplayTrajectory messages are received", widget,
                                 SLOT(changedTrajectoryTopic()), this);
  display_path_visual_enabled_property_ =
      new rviz::BoolProperty("Show Robot Visual", true,
                             "Indicates whether the geometry of the robot as defined for visualisation purposes "
                             "should be displayed",
                             widget, SLOT(changedDisplayPathVisualEnabled()), this);
  display_path_collision_enabled_property_ =
      new rviz::BoolProperty("Show Robot Collision", false,
                             "Indicates whether the geometry of the robot as defined for collision detection "
                             "purposes should be displayed",
                             widget, SLOT(changedDisplayPathCollisionEnabled()), this);
  robot_path_alpha_property_ = new rviz::FloatProperty("Robot Alpha", 0.5f, "Specifies the alpha for the robot links",
                                                       widget, SLOT(changedRobotPathAlpha()), this);
  robot_path_alpha_property_->setMin(0.0);
  robot_path_alpha_property_->setMax(1.0);
  state_display_time_property_ = new rviz::EditableEnumProperty(
      "State Display Time", DEFAULT_DISPLAY_TIME,
      "Replay speed of trajectory. Either as factor of its time parameterization or as constant time (s) per waypoint.",
      widget);
  for (const char* option : { "3x", "1x", "0.5x", "0.05s", "0.1s", "0.5s" })
    state_display_time_property_->addOptionStd(option);
  use_sim_time_property_ = new rviz::BoolProperty(
      "Use Sim Time", false, "Indicates whether simulation time or wall-time is used for state display timing.", widget);
  loop_display_property_ =
      new rviz::BoolProperty("Loop Animation", false, "Indicates whether the last received path is to be animated in a loop",
                             widget);
  trail_display_property_ =
      new rviz::BoolProperty("Show Trail", false, "Show a path trail", widget, SLOT(changedShowTrail()), this);
  trail_step_size_property_ = new rviz::IntProperty(
      "Trail Step Size", 1, "Specifies the step size of the samples shown in the trajectory trail.", widget,
      SLOT(changedTrailStepSize()), this);
  trail_step_size_property_->setMin(1);
  interrupt_display_property_ = new rviz::BoolProperty(
      "Interrupt Display", false, "Immediately show newly planned trajectory, interrupting the currently displayed one.",
      widget);
  robot_color_property_ = new rviz::ColorProperty("Robot Color", QColor(150, 50, 150), "The color of the animated robot",
                                                  widget, SLOT(changedRobotColor()), this);
  enable_robot_color_property_ = new rviz::BoolProperty(
      "Color Enabled", false, "Specifies whether robot coloring is enabled", widget, SLOT(enabledRobotColor()), this);
}

TrajectoryVisualization::~TrajectoryVisualization()
{
  trail_.clear();
  path_robot_.reset();
}

void TrajectoryVisualization::onInitialize(Ogre::SceneNode* node, rviz::DisplayContext* context,
                                           const ros::NodeHandle& handle)
{
  node_ = node;
  context_ = context;
  handle_ = handle;
  path_robot_.reset(new RobotStateVisual(node_, context_, "Planned Path", nullptr));
  path_robot_->setVisible(false);
}

void TrajectoryVisualization::onRobotModelLoaded(const RobotKinematics& kinematics)
{
  kinematics_ = &kinematics;
  trail_.clear();
  path_robot_->load(kinematics);
  applyLook(*path_robot_);
  path_robot_->setVisible(false);
}

void TrajectoryVisualization::applyLook(RobotStateVisual& visual)
{
  visual.setVisualVisible(display_path_visual_enabled_property_->getBool());
  visual.setCollisionVisible(display_path_collision_enabled_property_->getBool());
  visual.setAlpha(robot_path_alpha_property_->getFloat());
  if (enable_robot_color_property_->getBool())
  {
    const QColor color = robot_color_property_->getColor();
    visual.setColor(Ogre::ColourValue(color.redF(), color.greenF(), color.blueF()));
  }
  else
    visual.unsetColor();
}

void TrajectoryVisualization::onEnable()
{
  changedTrajectoryTopic();
}

void TrajectoryVisualization::onDisable()
{
  subscriber_.shutdown();
  animating_ = false;
  displaying_.clear();
  trail_.clear();
  if (path_robot_)
    path_robot_->setVisible(false);
}

void TrajectoryVisualization::reset()
{
  onDisable();
  if (display_->isEnabled())
    onEnable();
}

void TrajectoryVisualization::changedTrajectoryTopic()
{
  subscriber_.shutdown();
  const std::string topic = trajectory_topic_property_->getStdString();
  if (topic.empty() || !display_->isEnabled())
    return;
  try
  {
    subscriber_ = handle_.subscribe(topic, 2, &TrajectoryVisualization::incomingDisplayTrajectory, this);
    display_->deleteStatusStd("Trajectory Topic");
  }
  catch (const ros::Exception& error)
  {
    display_->setStatusStd(rviz::StatusProperty::Error, "Trajectory Topic", error.what());
  }
}

void TrajectoryVisualization::incomingDisplayTrajectory(const moveit_msgs::DisplayTrajectory::ConstPtr& message)
{
  showTrajectory(*message);
}

void TrajectoryVisualization::showTrajectory(const moveit_msgs::DisplayTrajectory& message)
{
  // the start state over the current state, then each trajectory's points over the last one
  JointPositions state = current_;
  const sensor_msgs::JointState& start = message.trajectory_start.joint_state;
  if (!nonFiniteJoint(start).empty())
  {
    display_->setStatusStd(rviz::StatusProperty::Error, "Trajectory",
                           "the start state's joint '" + nonFiniteJoint(start) +
                               "' is not a finite number: path not shown");
    return;
  }
  for (size_t i = 0; i < start.name.size() && i < start.position.size(); ++i)
    state[start.name[i]] = start.position[i];
  std::vector<Waypoint> waypoints;
  std::string problem;
  for (const auto& part : message.trajectory)
  {
    const trajectory_msgs::JointTrajectory& joints = part.joint_trajectory;
    double previous_time = 0.0;
    for (const auto& point : joints.points)
    {
      if (!finite(point.positions))
      {
        problem = "a waypoint's positions are not all finite numbers";
        break;
      }
      if (point.positions.size() != joints.joint_names.size())
      {
        problem = "a waypoint has " + std::to_string(point.positions.size()) + " positions for " +
                  std::to_string(joints.joint_names.size()) + " joints";
        break;
      }
      for (size_t j = 0; j < joints.joint_names.size(); ++j)
        state[joints.joint_names[j]] = point.positions[j];
      const double time = point.time_from_start.toSec();
      waypoints.push_back({ state, std::max(0.0, time - previous_time) });
      previous_time = time;
    }
  }
  if (!problem.empty())
  {
    display_->setStatusStd(rviz::StatusProperty::Error, "Trajectory", problem + ": path not shown");
    return;
  }
  display_->setStatusStd(rviz::StatusProperty::Ok, "Trajectory",
                         "path of " + std::to_string(waypoints.size()) + " waypoints received");
  if (waypoints.empty())
    return;
  std::lock_guard<std::mutex> lock(incoming_lock_);
  to_display_ = std::move(waypoints);
  displaying_attached_ = message.trajectory_start.attached_collision_objects;
  if (interrupt_display_property_->getBool())
    interrupt_ = true;
}

float TrajectoryVisualization::stateDisplayTime()
{
  // trajectory_visualization.cpp l. 355-404: "<factor>x" or "<seconds>s"; anything else
  // (or a value not above 0) resets the property to "3x"
  std::string text = state_display_time_property_->getStdString();
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  if (text.empty() || (text.back() != 'x' && text.back() != 's'))
  {
    state_display_time_property_->setStdString(DEFAULT_DISPLAY_TIME);
    return DEFAULT_DISPLAY_TIME_VALUE;
  }
  const float sign = text.back() == 'x' ? -1.0f : 1.0f;
  text.pop_back();
  std::istringstream stream(text);
  float value = 0.0f;
  if (!(stream >> value) || value <= 0.0f)
  {
    state_display_time_property_->setStdString(DEFAULT_DISPLAY_TIME);
    return DEFAULT_DISPLAY_TIME_VALUE;
  }
  return sign * value;
}

void TrajectoryVisualization::showWaypoint(size_t index)
{
  current_waypoint_ = static_cast<long>(index);
  path_robot_->update(displaying_[index].positions, displaying_attached_);
  const int step = trail_step_size_property_->getInt();
  for (size_t i = 0; i < trail_.size(); ++i)
    trail_[i]->setVisible(static_cast<long>(std::min(displaying_.size() - 1, i * step)) <= current_waypoint_);
}

void TrajectoryVisualization::update(float wall_dt, float ros_dt)
{
  if (!kinematics_ || !path_robot_)
    return;
  {
    std::lock_guard<std::mutex> lock(incoming_lock_);
    if (interrupt_)
    {
      animating_ = false;
      interrupt_ = false;
    }
    if (!animating_)
    {
      if (!to_display_.empty())
      {
        displaying_ = std::move(to_display_);
        to_display_.clear();
        animating_ = true;
        buildTrail();
      }
      else if (!displaying_.empty() && loop_display_property_->getBool())
        animating_ = true;
      if (animating_)
        current_waypoint_ = -1;
    }
  }
  if (animating_)
  {
    const long previous = current_waypoint_;
    const long count = static_cast<long>(displaying_.size());
    waypoint_time_ += use_sim_time_property_->getBool() ? ros_dt : wall_dt;
    float display_time = stateDisplayTime();
    if (current_waypoint_ < 0)
    {
      current_waypoint_ = 0;
      waypoint_time_ = 0.0f;
    }
    else if (display_time < 0.0f)
    {
      const float factor = -display_time;
      while (current_waypoint_ + 1 < count &&
             (display_time = displaying_[current_waypoint_ + 1].from_previous / factor) < waypoint_time_)
      {
        waypoint_time_ -= display_time;
        ++current_waypoint_;
      }
      if (current_waypoint_ + 1 >= count)
        current_waypoint_ = count;  // past the last waypoint: the animation ends
    }
    else if (waypoint_time_ > display_time)
    {
      waypoint_time_ = 0.0f;
      ++current_waypoint_;
    }
    if (current_waypoint_ != previous)
    {
      if (current_waypoint_ < count)
        showWaypoint(current_waypoint_);
      else
      {
        animating_ = false;
        showWaypoint(count - 1);
      }
    }
  }
  path_robot_->setVisible(display_->isEnabled() && !displaying_.empty() &&
                          (animating_ || trail_display_property_->getBool()));
}

void TrajectoryVisualization::buildTrail()
{
  trail_.clear();
  if (!trail_display_property_->getBool() || displaying_.empty() || !kinematics_)
    return;
  const size_t step = static_cast<size_t>(trail_step_size_property_->getInt());
  for (size_t i = 0; i * step < displaying_.size() + step - 1; ++i)
  {
    const size_t index = std::min(displaying_.size() - 1, i * step);
    std::unique_ptr<RobotStateVisual> visual(
        new RobotStateVisual(node_, context_, "Trail Robot " + std::to_string(i), nullptr));
    visual->load(*kinematics_);
    applyLook(*visual);
    visual->update(displaying_[index].positions, displaying_attached_);
    visual->setVisible(display_->isEnabled() && static_cast<long>(index) <= current_waypoint_);
    trail_.push_back(std::move(visual));
  }
}

void TrajectoryVisualization::changedRobotPathAlpha()
{
  if (path_robot_)
    applyLook(*path_robot_);
  for (auto& visual : trail_)
    applyLook(*visual);
}

void TrajectoryVisualization::changedDisplayPathVisualEnabled()
{
  changedRobotPathAlpha();
}

void TrajectoryVisualization::changedDisplayPathCollisionEnabled()
{
  changedRobotPathAlpha();
}

void TrajectoryVisualization::changedShowTrail()
{
  buildTrail();
}

void TrajectoryVisualization::changedTrailStepSize()
{
  buildTrail();
}

void TrajectoryVisualization::changedRobotColor()
{
  changedRobotPathAlpha();
}

void TrajectoryVisualization::enabledRobotColor()
{
  changedRobotPathAlpha();
}
}  // namespace moveit_rviz_plugin
