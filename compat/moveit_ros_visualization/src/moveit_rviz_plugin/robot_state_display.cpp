/* The RobotState display: a DisplayRobotState drawn as MoveIt's RobotStateDisplay draws it
 * (the state over the model's defaults, `hide` hides it, highlight_links colour links). */
#include "robot_state_display.h"

#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/ros_topic_property.h>
#include <rviz/properties/string_property.h>

#include "message_checks.h"
#include "robot_frame_placement.h"

namespace moveit_rviz_plugin
{
RobotStateDisplay::RobotStateDisplay()
{
  robot_state_topic_property_ =
      new rviz::RosTopicProperty("Robot State Topic", "display_robot_state",
                                 ros::message_traits::datatype<moveit_msgs::DisplayRobotState>(),
                                 "The topic on which the moveit_msgs::DisplayRobotState messages are received", this,
                                 SLOT(changedRobotStateTopic()), this);
  root_link_name_property_ =
      new rviz::StringProperty("Robot Root Link", "", "Shows the name of the root link for the robot model", this);
  root_link_name_property_->setReadOnly(true);
  robot_alpha_property_ = new rviz::FloatProperty("Robot Alpha", 1.0f, "Specifies the alpha for the robot links", this,
                                                  SLOT(changedLook()), this);
  robot_alpha_property_->setMin(0.0);
  robot_alpha_property_->setMax(1.0);
  attached_body_color_property_ = new rviz::ColorProperty(
      "Attached Body Color", QColor(150, 50, 150), "The color for the attached bodies", this, SLOT(changedLook()), this);
  enable_link_highlight_ = new rviz::BoolProperty("Show Highlights", true, "Specifies whether link highlighting is enabled",
                                                  this, SLOT(changedLook()), this);
  enable_visual_visible_ = new rviz::BoolProperty(
      "Visual Enabled", true, "Whether to display the visual representation of the robot.", this, SLOT(changedLook()), this);
  enable_collision_visible_ =
      new rviz::BoolProperty("Collision Enabled", false, "Whether to display the collision representation of the robot.",
                             this, SLOT(changedLook()), this);
  show_all_links_ = new rviz::BoolProperty("Show All Links", true, "Toggle all links visibility on or off.", this,
                                           SLOT(changedLook()), this);
}

RobotStateDisplay::~RobotStateDisplay()
{
  robot_.reset();
}

void RobotStateDisplay::onInitialize()
{
  Display::onInitialize();
  robot_.reset(new RobotStateVisual(scene_node_, context_, "Robot Visual", this));
  robot_->setVisible(false);
}

void RobotStateDisplay::onRobotModelLoaded()
{
  root_link_name_property_->setStdString(kinematics_.rootLink());
  robot_->load(kinematics_);
  changedLook();
  changed_ = true;
}

void RobotStateDisplay::onEnable()
{
  Display::onEnable();
  if (!robotModelLoaded())
    loadRobotModel();
  changedRobotStateTopic();
  changed_ = true;
}

void RobotStateDisplay::onDisable()
{
  subscriber_.shutdown();
  if (robot_)
    robot_->setVisible(false);
  Display::onDisable();
}

void RobotStateDisplay::reset()
{
  Display::reset();
  forgetRobotModel();
  if (isEnabled())
    loadRobotModel();
}


void RobotStateDisplay::changedRobotStateTopic()
{
  subscriber_.shutdown();
  if (!isEnabled() || robot_state_topic_property_->getStdString().empty())
    return;
  try
  {
    subscriber_ = update_nh_.subscribe(robot_state_topic_property_->getStdString(), 10,
                                       &RobotStateDisplay::incomingRobotState, this);
    deleteStatusStd("Robot State Topic");
  }
  catch (const ros::Exception& error)
  {
    setStatusStd(rviz::StatusProperty::Error, "Robot State Topic", error.what());
  }
}

void RobotStateDisplay::changedLook()
{
  if (!robot_)
    return;
  robot_->setVisualVisible(enable_visual_visible_->getBool());
  robot_->setCollisionVisible(enable_collision_visible_->getBool());
  robot_->setAlpha(robot_alpha_property_->getFloat());
  const QColor color = attached_body_color_property_->getColor();
  robot_->setAttachedBodyColor(Ogre::ColourValue(color.redF(), color.greenF(), color.blueF()));
  robot_->setHighlights(enable_link_highlight_->getBool() ? highlights_ : std::map<std::string, Ogre::ColourValue>());
  changed_ = true;
}

void RobotStateDisplay::incomingRobotState(const moveit_msgs::DisplayRobotState::ConstPtr& message)
{
  const sensor_msgs::JointState& joints = message->state.joint_state;
  if (joints.name.size() != joints.position.size())
  {
    setStatusStd(rviz::StatusProperty::Error, "Robot State",
                 std::to_string(joints.name.size()) + " joint names for " + std::to_string(joints.position.size()) +
                     " positions: state ignored");
    return;
  }
  const std::string bad_joint = nonFiniteJoint(joints);
  if (!bad_joint.empty())
  {
    setStatusStd(rviz::StatusProperty::Error, "Robot State",
                 "joint '" + bad_joint + "' is not a finite number: state ignored");
    return;
  }
  if (!message->state.is_diff)
    positions_.clear();
  for (size_t i = 0; i < joints.name.size(); ++i)
    positions_[joints.name[i]] = joints.position[i];
  attached_ = message->state.attached_collision_objects;
  highlights_.clear();
  for (const auto& highlight : message->highlight_links)
    highlights_[highlight.id] = Ogre::ColourValue(highlight.color.r, highlight.color.g, highlight.color.b);
  hidden_ = message->hide;
  setStatusStd(rviz::StatusProperty::Ok, "Robot State", "received");
  changedLook();
}

void RobotStateDisplay::update(float wall_dt, float ros_dt)
{
  Display::update(wall_dt, ros_dt);
  if (!ensureRobotModel(wall_dt))
    return;
  placeAtFrame(scene_node_, planningFrame(), context_, this);
  if (changed_)
  {
    changed_ = false;
    robot_->update(positions_, attached_);
    robot_->setVisible(isEnabled() && !hidden_ && show_all_links_->getBool());
  }
}
}  // namespace moveit_rviz_plugin
