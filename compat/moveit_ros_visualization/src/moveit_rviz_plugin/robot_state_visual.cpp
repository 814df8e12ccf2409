/* rviz::Robot posed through a LinkUpdater that reads our forward kinematics, as MoveIt's
 * RobotStateVisualization poses it through its PlanningLinkUpdater. */
#include "robot_state_visual.h"

#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <rviz/display_context.h>
#include <rviz/robot/link_updater.h>
#include <rviz/robot/robot_link.h>

namespace moveit_rviz_plugin
{
namespace
{
Ogre::Vector3 position(const KDL::Frame& frame)
{
  return Ogre::Vector3(frame.p.x(), frame.p.y(), frame.p.z());
}

Ogre::Quaternion orientation(const KDL::Frame& frame)
{
  double x, y, z, w;
  frame.M.GetQuaternion(x, y, z, w);
  return Ogre::Quaternion(w, x, y, z);
}

class PosesLinkUpdater : public rviz::LinkUpdater
{
public:
  explicit PosesLinkUpdater(const LinkPoses& poses) : poses_(poses) {}

  // the link's frame for both: rviz::RobotLink adds the visual's and collision's origins
  bool getLinkTransforms(const std::string& link_name, Ogre::Vector3& visual_position,
                         Ogre::Quaternion& visual_orientation, Ogre::Vector3& collision_position,
                         Ogre::Quaternion& collision_orientation) const override
  {
    auto found = poses_.find(link_name);
    if (found == poses_.end())
      return false;
    visual_position = collision_position = position(found->second);
    visual_orientation = collision_orientation = orientation(found->second);
    return true;
  }

private:
  const LinkPoses& poses_;
};
}  // namespace

RobotStateVisual::RobotStateVisual(Ogre::SceneNode* parent, rviz::DisplayContext* context, const std::string& name,
                                   rviz::Property* links_parent)
  : context_(context)
  , node_(parent->createChildSceneNode())
  , robot_(new rviz::Robot(node_, context, name, links_parent))
  , attached_color_(150 / 255.0f, 50 / 255.0f, 150 / 255.0f)
{
}

RobotStateVisual::~RobotStateVisual()
{
  attached_.clear();
  robot_.reset();
  context_->getSceneManager()->destroySceneNode(node_);
}

void RobotStateVisual::load(const RobotKinematics& kinematics)
{
  kinematics_ = &kinematics;
  attached_.clear();
  robot_->load(kinematics.urdf(), true, true);
  applyColors();
}

void RobotStateVisual::clear()
{
  attached_.clear();
  robot_->clear();
  kinematics_ = nullptr;
}

void RobotStateVisual::update(const JointPositions& positions,
                              const std::vector<moveit_msgs::AttachedCollisionObject>& attached)
{
  if (kinematics_)
    update(kinematics_->linkPoses(positions), attached);
}

void RobotStateVisual::update(const LinkPoses& poses, const std::vector<moveit_msgs::AttachedCollisionObject>& attached)
{
  if (!kinematics_)
    return;
  robot_->update(PosesLinkUpdater(poses));
  std::map<std::string, std::unique_ptr<CollisionObjectVisual>> drawn;
  for (const auto& body : attached)
  {
    auto link = poses.find(body.link_name);
    if (link == poses.end())
      continue;
    auto visual = std::move(attached_[body.object.id]);
    if (!visual)
      visual.reset(new CollisionObjectVisual(context_->getSceneManager(), node_));
    visual->setShapes(body.object);
    // MoveIt keeps an attached body's shapes in its link's frame
    visual->node()->setPosition(position(link->second));
    visual->node()->setOrientation(orientation(link->second));
    Ogre::ColourValue color = attached_color_;
    color.a = alpha_;
    visual->setColor(color);
    visual->setVisible(visible_);
    drawn[body.object.id] = std::move(visual);
  }
  attached_ = std::move(drawn);
}

void RobotStateVisual::setPose(const Ogre::Vector3& position, const Ogre::Quaternion& orientation)
{
  node_->setPosition(position);
  node_->setOrientation(orientation);
}

void RobotStateVisual::setVisible(bool visible)
{
  visible_ = visible;
  robot_->setVisible(visible);
  for (auto& body : attached_)
    body.second->setVisible(visible);
}

void RobotStateVisual::setVisualVisible(bool visible)
{
  robot_->setVisualVisible(visible);
}

void RobotStateVisual::setCollisionVisible(bool visible)
{
  robot_->setCollisionVisible(visible);
}

void RobotStateVisual::setAlpha(float alpha)
{
  alpha_ = alpha;
  robot_->setAlpha(alpha);
  for (auto& body : attached_)
  {
    Ogre::ColourValue color = attached_color_;
    color.a = alpha;
    body.second->setColor(color);
  }
}

void RobotStateVisual::setColor(const Ogre::ColourValue& color)
{
  has_color_ = true;
  color_ = color;
  applyColors();
}

void RobotStateVisual::unsetColor()
{
  has_color_ = false;
  applyColors();
}

void RobotStateVisual::setAttachedBodyColor(const Ogre::ColourValue& color)
{
  attached_color_ = color;
  setAlpha(alpha_);
}

void RobotStateVisual::setHighlights(const std::map<std::string, Ogre::ColourValue>& highlights)
{
  highlights_ = highlights;
  applyColors();
}

void RobotStateVisual::applyColors()
{
  for (const auto& entry : robot_->getLinks())
  {
    rviz::RobotLink* link = entry.second;
    auto highlight = highlights_.find(entry.first);
    if (highlight != highlights_.end())
      link->setColor(highlight->second.r, highlight->second.g, highlight->second.b);
    else if (has_color_)
      link->setColor(color_.r, color_.g, color_.b);
    else
      link->unsetColor();
  }
}
}  // namespace moveit_rviz_plugin
