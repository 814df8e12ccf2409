// moveit_visual_tools::MoveItVisualTools as moveit_visual_tools noetic-devel 3.6.1 declares it
// (include/moveit_visual_tools/moveit_visual_tools.h): rviz_visual_tools' markers plus MoveIt's
// robot states and trajectories. Written anew (compat/, see compat/README.md) on this
// workspace's moveit_core (RobotModel, RobotState, conversions) and moveit_ros_planning
// (RobotModelLoader); names, signatures, defaults and topics are upstream's, the source lines
// are cited in src/moveit_visual_tools.cpp.
//
// Provided: the constructors MoveItVisualTools() (the robot_description model, markers in its
// model frame) and MoveItVisualTools(base_frame, marker_topic, robot_model); everything
// RvizVisualTools has (text, axes, arrows, trigger, prompt, deleteAllMarkers, ...);
// setRobotStateTopic, loadSharedRobotState, getSharedRobotState, getRootRobotState,
// getRobotModel, loadTrajectoryPub, loadRobotStatePub; publishTrajectoryLine (the end effector's
// forward kinematics through a trajectory: a sphere at each waypoint and a path of cylinders,
// for a link or for each end-effector tip of a group), publishTrajectoryPoints,
// publishTrajectoryPath (a moveit_msgs/DisplayTrajectory on /move_group/display_planned_path,
// which rviz's Trajectory display and MotionPlanning display show), publishTrajectoryPoint,
// publishIKSolutions, publishRobotState and hideRobot (moveit_msgs/DisplayRobotState on
// ~display_robot_state), enableRobotStateRootOffet, applyVirtualJointTransform,
// showJointLimits, publishWorkspaceParameters.
// Not provided: the constructor taking a planning_scene_monitor::PlanningSceneMonitorPtr and
// getPlanningSceneMonitor / setPlanningSceneMonitor (there is no C++ PlanningSceneMonitor here);
// what needs one (publishCollision*, removeAllCollisionObjects, cleanupCO, cleanupACO, attachCO,
// processCollisionObjectMsg, processAttachedCollisionObjectMsg, moveCollisionObject,
// triggerPlanningSceneUpdate, loadPlanningSceneMonitor, loadCollisionSceneFromFile) builds and
// says at run time, with ROS_ERROR, that it is not provided and returns false: add collision
// objects with moveit::planning_interface::PlanningSceneInterface instead. End-effector, grasp
// and contact-point markers (loadEEMarker, publishEEMarkers, publishGrasps,
// publishAnimatedGrasps, checkAndPublishCollision, publishContactPoints) need the links' collision
// geometry, which this moveit_core does not model: not declared. imarker_robot_state.h and
// imarker_end_effector.h stop with #error. publishTrajectoryPath and publishTrajectoryLine also
// take a robot_trajectory::RobotTrajectory (or its Ptr), as upstream's overloads do
// (moveit_visual_tools.cpp l. 1203-1231, 1326-1428 on noetic-devel).
#ifndef MOVEIT_VISUAL_TOOLS_MOVEIT_VISUAL_TOOLS_H
#define MOVEIT_VISUAL_TOOLS_MOVEIT_VISUAL_TOOLS_H

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <rviz_visual_tools/rviz_visual_tools.h>

#include <moveit/robot_model/robot_model.h>
#include <moveit/robot_model_loader/robot_model_loader.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit/robot_trajectory/robot_trajectory.h>

#include <moveit_msgs/AttachedCollisionObject.h>
#include <moveit_msgs/CollisionObject.h>
#include <moveit_msgs/DisplayRobotState.h>
#include <moveit_msgs/DisplayTrajectory.h>
#include <moveit_msgs/RobotTrajectory.h>
#include <moveit_msgs/WorkspaceParameters.h>
#include <trajectory_msgs/JointTrajectory.h>

namespace moveit_visual_tools
{
// Upstream's defaults (header l. 67-74)
static const std::string ROBOT_DESCRIPTION = "robot_description";
static const std::string DISPLAY_PLANNED_PATH_TOPIC = "/move_group/display_planned_path";
static const std::string DISPLAY_ROBOT_STATE_TOPIC = "display_robot_state";
static const std::string PLANNING_SCENE_TOPIC = "planning_scene";

class MoveItVisualTools : public rviz_visual_tools::RvizVisualTools
{
public:
  /** \brief The model of ROBOT_DESCRIPTION, markers in its model frame on RVIZ_MARKER_TOPIC */
  MoveItVisualTools();

  /**
   * \param base_frame - the frame markers are given in, e.g. "world" or the robot's base link
   * \param marker_topic - the MarkerArray topic
   * \param robot_model - a model already loaded; null loads ROBOT_DESCRIPTION on first need
   */
  MoveItVisualTools(const std::string& base_frame,
                    const std::string& marker_topic = rviz_visual_tools::RVIZ_MARKER_TOPIC,
                    moveit::core::RobotModelConstPtr robot_model = moveit::core::RobotModelConstPtr());

  void setRobotStateTopic(const std::string& robot_state_topic)
  {
    robot_state_topic_ = robot_state_topic;
  }
  void setPlanningSceneTopic(const std::string& planning_scene_topic)
  {
    planning_scene_topic_ = planning_scene_topic;
  }

  /** \brief Load the model (if not given) and the shared states; false if the model cannot load */
  bool loadSharedRobotState();
  moveit::core::RobotStatePtr& getSharedRobotState();
  moveit::core::RobotStatePtr& getRootRobotState()
  {
    return root_robot_state_;
  }
  moveit::core::RobotModelConstPtr getRobotModel();

  /** \brief Advertise the DisplayTrajectory topic; blocking waits up to 0.5 s for a subscriber */
  void loadTrajectoryPub(const std::string& display_planned_path_topic = DISPLAY_PLANNED_PATH_TOPIC,
                         bool blocking = true);
  /** \brief Advertise the DisplayRobotState topic (robot_state_topic, or the one set) */
  void loadRobotStatePub(const std::string& robot_state_topic = "", bool blocking = true);

  void setManualSceneUpdating(bool enable_manual = true)
  {
    mannual_trigger_update_ = enable_manual;
  }

  // Not provided (no PlanningSceneMonitor here): each says so with ROS_ERROR and returns false
  bool loadPlanningSceneMonitor();
  bool processCollisionObjectMsg(const moveit_msgs::CollisionObject& msg,
                                 const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool processAttachedCollisionObjectMsg(const moveit_msgs::AttachedCollisionObject& msg);
  bool moveCollisionObject(const Eigen::Isometry3d& pose, const std::string& name,
                           const rviz_visual_tools::colors& color);
  bool moveCollisionObject(const geometry_msgs::Pose& pose, const std::string& name,
                           const rviz_visual_tools::colors& color);
  bool triggerPlanningSceneUpdate();
  bool removeAllCollisionObjects();
  bool cleanupCO(const std::string& name);
  bool cleanupACO(const std::string& name);
  bool attachCO(const std::string& name, const std::string& ee_parent_link);
  bool publishCollisionFloor(double z = 0.0, const std::string& plane_name = "Floor",
                             const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionBlock(const geometry_msgs::Pose& block_pose, const std::string& block_name = "block",
                             double block_size = 0.1,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCuboid(const Eigen::Vector3d& point1, const Eigen::Vector3d& point2, const std::string& name,
                              const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCuboid(const geometry_msgs::Point& point1, const geometry_msgs::Point& point2,
                              const std::string& name,
                              const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCuboid(const Eigen::Isometry3d& pose, double width, double depth, double height,
                              const std::string& name, const rviz_visual_tools::colors& color);
  bool publishCollisionCuboid(const geometry_msgs::Pose& pose, double width, double depth, double height,
                              const std::string& name, const rviz_visual_tools::colors& color);
  bool publishCollisionCuboid(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size, const std::string& name,
                              const rviz_visual_tools::colors& color)
  {
    return publishCollisionCuboid(pose, size.x(), size.y(), size.z(), name, color);
  }
  bool publishCollisionCuboid(const geometry_msgs::Pose& pose, const geometry_msgs::Vector3& size,
                              const std::string& name, const rviz_visual_tools::colors& color)
  {
    return publishCollisionCuboid(pose, size.x, size.y, size.z, name, color);
  }
  bool publishCollisionCylinder(const geometry_msgs::Point& a, const geometry_msgs::Point& b,
                                const std::string& object_name, double radius,
                                const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCylinder(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const std::string& object_name,
                                double radius, const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCylinder(const Eigen::Isometry3d& object_pose, const std::string& object_name, double radius,
                                double height, const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionCylinder(const geometry_msgs::Pose& object_pose, const std::string& object_name,
                                double radius, double height,
                                const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionMesh(const geometry_msgs::Pose& object_pose, const std::string& object_name,
                            const std::string& mesh_path,
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionMesh(const Eigen::Isometry3d& object_pose, const std::string& object_name,
                            const std::string& mesh_path,
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionMesh(const Eigen::Isometry3d& object_pose, const std::string& object_name,
                            const shape_msgs::Mesh& mesh_msg,
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionMesh(const geometry_msgs::Pose& object_pose, const std::string& object_name,
                            const shape_msgs::Mesh& mesh_msg,
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionWall(double x, double y, double angle = 0.0, double width = 2.0, double height = 1.5,
                            const std::string& name = "wall",
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionWall(double x, double y, double z, double angle = 0.0, double width = 2.0,
                            double height = 1.5, const std::string& name = "wall",
                            const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool publishCollisionTable(double x, double y, double z, double angle, double width, double height, double depth,
                             const std::string& name,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::GREEN);
  bool loadCollisionSceneFromFile(const std::string& path);
  bool loadCollisionSceneFromFile(const std::string& path, const Eigen::Isometry3d& offset);

  /** \brief The workspace's box, a translucent cuboid "Planning_Workspace" id 1 */
  bool publishWorkspaceParameters(const moveit_msgs::WorkspaceParameters& params);

  /** \brief Show the solutions in turn as a trajectory, display_time seconds each (blocks) */
  bool publishIKSolutions(const std::vector<trajectory_msgs::JointTrajectoryPoint>& ik_solutions,
                          const moveit::core::JointModelGroup* arm_jmg, double display_time = 0.4);

  /** \brief A one-point trajectory of the group shown for display_time seconds (blocks) */
  bool publishTrajectoryPoint(const trajectory_msgs::JointTrajectoryPoint& trajectory_pt,
                              const std::string& planning_group, double display_time = 0.1);

  /**
   * \brief A moveit_msgs/DisplayTrajectory for rviz to animate (not batched: no trigger() needed)
   * \param blocking - wait for the animation's duration
   */
  bool publishTrajectoryPath(const std::vector<moveit::core::RobotStatePtr>& trajectory,
                             const moveit::core::JointModelGroup* jmg, double speed = 0.01, bool blocking = false);
  bool publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                             const moveit::core::RobotStateConstPtr& robot_state, bool blocking = false);
  bool publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                             const moveit::core::RobotState& robot_state, bool blocking = false);
  bool publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                             const moveit_msgs::RobotState& robot_state, bool blocking = false);
  void publishTrajectoryPath(const moveit_msgs::DisplayTrajectory& display_trajectory_msg);
  /** \brief The trajectory's message from its first waypoint; a trajectory without times is shown
   *         at 2 s per waypoint (upstream's "1 hz") */
  bool publishTrajectoryPath(const robot_trajectory::RobotTrajectoryPtr& trajectory, bool blocking = false);
  bool publishTrajectoryPath(const robot_trajectory::RobotTrajectory& trajectory, bool blocking = false);

  /**
   * \brief The path of a link through a trajectory: a sphere (namespace "Sphere") at each
   *        waypoint's forward kinematics and a cylinder (namespace "Path") between consecutive
   *        ones, in the model frame
   * \param ee_parent_link - the link traced (of any model of the same robot: matched by name)
   * \param arm_jmg - the group whose variables the trajectory gives; without ee_parent_link each
   *        of its end-effector tips is traced
   */
  bool publishTrajectoryLine(const moveit_msgs::RobotTrajectory& trajectory_msg,
                             const moveit::core::LinkModel* ee_parent_link,
                             const moveit::core::JointModelGroup* arm_jmg,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);
  bool publishTrajectoryLine(const moveit_msgs::RobotTrajectory& trajectory_msg,
                             const moveit::core::JointModelGroup* arm_jmg,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);
  /** \brief The same line from a RobotTrajectory's waypoints (their own forward kinematics) */
  bool publishTrajectoryLine(const robot_trajectory::RobotTrajectoryPtr& robot_trajectory,
                             const moveit::core::LinkModel* ee_parent_link,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);
  bool publishTrajectoryLine(const robot_trajectory::RobotTrajectory& robot_trajectory,
                             const moveit::core::LinkModel* ee_parent_link,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);
  bool publishTrajectoryLine(const robot_trajectory::RobotTrajectoryPtr& robot_trajectory,
                             const moveit::core::JointModelGroup* arm_jmg,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);
  bool publishTrajectoryLine(const robot_trajectory::RobotTrajectory& robot_trajectory,
                             const moveit::core::JointModelGroup* arm_jmg,
                             const rviz_visual_tools::colors& color = rviz_visual_tools::LIME_GREEN);

  /** \brief A sphere at the link's position in each state */
  bool publishTrajectoryPoints(const std::vector<moveit::core::RobotStatePtr>& robot_state_trajectory,
                               const moveit::core::LinkModel* ee_parent_link,
                               const rviz_visual_tools::colors& color = rviz_visual_tools::YELLOW);

  /** \brief Published robot states get their virtual joint ("virtual_joint", floating) set to offset */
  void enableRobotStateRootOffet(const Eigen::Isometry3d& offset);
  void disableRobotStateRootOffet();

  /**
   * \brief A moveit_msgs/DisplayRobotState for rviz's RobotState display (not batched)
   * \param color - DEFAULT keeps the URDF's colours; another colours every link (or highlight_links)
   */
  bool publishRobotState(const trajectory_msgs::JointTrajectoryPoint& trajectory_pt,
                         const moveit::core::JointModelGroup* jmg,
                         const rviz_visual_tools::colors& color = rviz_visual_tools::DEFAULT);
  bool publishRobotState(const std::vector<double>& joint_positions, const moveit::core::JointModelGroup* jmg,
                         const rviz_visual_tools::colors& color = rviz_visual_tools::DEFAULT);
  bool publishRobotState(const moveit::core::RobotState& robot_state,
                         const rviz_visual_tools::colors& color = rviz_visual_tools::DEFAULT,
                         const std::vector<std::string>& highlight_links = {});
  bool publishRobotState(const moveit::core::RobotStatePtr& robot_state,
                         const rviz_visual_tools::colors& color = rviz_visual_tools::DEFAULT,
                         const std::vector<std::string>& highlight_links = {});
  void publishRobotState(const moveit_msgs::DisplayRobotState& display_robot_state_msg);

  /** \brief A DisplayRobotState with hide set */
  bool hideRobot();

  /** \brief Set the floating "virtual_joint" to offset; false if the model has none */
  static bool applyVirtualJointTransform(moveit::core::RobotState& robot_state, const Eigen::Isometry3d& offset);

  /** \brief Print each single-variable active joint's position within its bounds */
  void showJointLimits(const moveit::core::RobotStatePtr& robot_state);

private:
  /** \brief The tip link's pose at each point of the message, the points' positions set by
   *         name on the shared state; false (and ROS_ERROR) for a point that cannot be set */
  bool linkPoses(const moveit_msgs::RobotTrajectory& trajectory_msg, const moveit::core::LinkModel* link,
                 EigenSTL::vector_Isometry3d& poses);
  static bool checkForVirtualJoint(const moveit::core::RobotState& robot_state);
  /** \brief The ROS_ERROR of what needs a PlanningSceneMonitor; returns false */
  bool notProvided(const std::string& method) const;

protected:
  bool mannual_trigger_update_ = false;

  std::string robot_state_topic_;
  std::string planning_scene_topic_;

  ros::Publisher pub_display_path_;
  ros::Publisher pub_robot_state_;

  robot_model_loader::RobotModelLoaderPtr rm_loader_;

  // One DisplayRobotState per colour, its highlights made once
  std::map<rviz_visual_tools::colors, moveit_msgs::DisplayRobotState> display_robot_msgs_;

  moveit::core::RobotModelConstPtr robot_model_;
  moveit::core::RobotStatePtr shared_robot_state_;
  moveit::core::RobotStatePtr hidden_robot_state_;
  moveit::core::RobotStatePtr root_robot_state_;

  bool robot_state_root_offset_enabled_ = false;
  Eigen::Isometry3d robot_state_root_offset_;

public:
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

typedef std::shared_ptr<MoveItVisualTools> MoveItVisualToolsPtr;
typedef std::shared_ptr<const MoveItVisualTools> MoveItVisualToolsConstPtr;

}  // namespace moveit_visual_tools

#endif  // MOVEIT_VISUAL_TOOLS_MOVEIT_VISUAL_TOOLS_H
