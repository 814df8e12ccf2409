// MoveIt's MoveGroupInterface (moveit_ros_planning_interface, noetic-devel 7c0343f0), written here as a client of this
// workspace's move_group (compat/moveit_ros_move_group), as MoveIt's own is a client of its move_group: plans and
// moves through the `move_group` action (moveit_msgs/MoveGroupAction), executes through `execute_trajectory`, computes
// Cartesian paths through `compute_cartesian_path`, changes the scene through `apply_planning_scene` (attach and
// detach), pick and place through the `pickup` and `place` actions; stops by "stop" on `trajectory_execution_event`.
// Names are relative to the node handle of the Options (the node's namespace by default), as MoveIt's are. The robot
// model comes from `robot_description` (moveit_ros_planning's RobotModelLoader); the current state from
// `joint_states`.
//
// Provided: the members below, with MoveIt's signatures and meaning (goal fields as MoveIt fills them).
// Not provided (they answer at run time with ROS_ERROR naming what is missing, and false or nothing):
//   - the constraints database: setConstraintsDatabase, getKnownConstraints, setPathConstraints(const std::string&)
//     (MoveIt's warehouse_ros is not here; setPathConstraints(const moveit_msgs::Constraints&) is);
//   - getPlannerParams / setPlannerParams need the `get_planner_params` / `set_planner_params` services, which this
//     move_group does not serve;
//   - pick, place and planGraspsAndPick send their goals, and this move_group refuses them (MoveIt's pick and place
//     pipeline is not emulated).
// The planning_interface::MoveItErrorCode alias is MoveIt's deprecated one; moveit::core::MoveItErrorCode is the class.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <actionlib/client/simple_action_client.h>
#include <eigen_stl_containers/eigen_stl_vector_container.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <moveit/macros/class_forward.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit/utils/moveit_error_code.h>
#include <moveit_msgs/CollisionObject.h>
#include <moveit_msgs/Constraints.h>
#include <moveit_msgs/Grasp.h>
#include <moveit_msgs/MotionPlanRequest.h>
#include <moveit_msgs/MoveGroupAction.h>
#include <moveit_msgs/MoveItErrorCodes.h>
#include <moveit_msgs/PickupGoal.h>
#include <moveit_msgs/PlaceGoal.h>
#include <moveit_msgs/PlaceLocation.h>
#include <moveit_msgs/PlannerInterfaceDescription.h>
#include <moveit_msgs/RobotState.h>
#include <moveit_msgs/RobotTrajectory.h>
#include <moveit_msgs/TrajectoryConstraints.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/buffer.h>

namespace moveit
{
namespace planning_interface
{
using MoveItErrorCode [[deprecated("Use moveit::core::MoveItErrorCode")]] = moveit::core::MoveItErrorCode;

MOVEIT_CLASS_FORWARD(MoveGroupInterface);  // MoveGroupInterfacePtr, ConstPtr, WeakPtr ...

/** A client of move_group for one planning group. Blocking calls (move, execute, plan) wait for an action's result,
    which arrives through the node's callback queue: start a ros::AsyncSpinner first, as with MoveIt's. */
class MoveGroupInterface
{
public:
  // MoveIt's defaults (move_group_interface.h l. 105-121)
  static constexpr double DEFAULT_GOAL_JOINT_TOLERANCE = 1e-4;
  static constexpr double DEFAULT_GOAL_POSITION_TOLERANCE = 1e-4;
  static constexpr double DEFAULT_GOAL_ORIENTATION_TOLERANCE = 1e-3;
  static constexpr double DEFAULT_ALLOWED_PLANNING_TIME = 5.0;
  static constexpr int DEFAULT_NUM_PLANNING_ATTEMPTS = 1;

  /** "robot_description" */
  static const std::string ROBOT_DESCRIPTION;

  struct Options
  {
    Options(std::string group_name, std::string desc = ROBOT_DESCRIPTION,
            const ros::NodeHandle& node_handle = ros::NodeHandle())
      : group_name_(std::move(group_name)), robot_description_(std::move(desc)), node_handle_(node_handle)
    {
    }
    /** the planning group */
    std::string group_name_;
    /** the parameter holding the URDF (its SRDF in <name>_semantic) */
    std::string robot_description_;
    /** a model to use instead of loading one */
    moveit::core::RobotModelConstPtr robot_model_;
    /** move_group's actions and services are looked up relative to it */
    ros::NodeHandle node_handle_;
  };

  MOVEIT_STRUCT_FORWARD(Plan);

  /** A motion plan as messages */
  struct Plan
  {
    /** the whole state planning started from */
    moveit_msgs::RobotState start_state_;
    /** the trajectory (its joints may be fewer than the start state's) */
    moveit_msgs::RobotTrajectory trajectory_;
    /** seconds move_group took to plan */
    double planning_time_;
  };

  /** Connects to move_group for \e opt.group_name_: waits for its actions up to \e wait_for_servers (zero: for ever)
      and throws std::runtime_error when one is not there by then, or when the model or the group is unknown. Without
      \e tf_buffer one shared buffer and listener are made. */
  MoveGroupInterface(const Options& opt,
                     const std::shared_ptr<tf2_ros::Buffer>& tf_buffer = std::shared_ptr<tf2_ros::Buffer>(),
                     const ros::WallDuration& wait_for_servers = ros::WallDuration());
  [[deprecated]] MoveGroupInterface(const Options& opt, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                    const ros::Duration& wait_for_servers);
  /** As above with Options(group). Throws std::runtime_error when ROS is not initialised. */
  MoveGroupInterface(const std::string& group,
                     const std::shared_ptr<tf2_ros::Buffer>& tf_buffer = std::shared_ptr<tf2_ros::Buffer>(),
                     const ros::WallDuration& wait_for_servers = ros::WallDuration());
  [[deprecated]] MoveGroupInterface(const std::string& group, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                    const ros::Duration& wait_for_servers);

  ~MoveGroupInterface();
  MoveGroupInterface(const MoveGroupInterface&) = delete;
  MoveGroupInterface& operator=(const MoveGroupInterface&) = delete;
  MoveGroupInterface(MoveGroupInterface&& other) noexcept;
  MoveGroupInterface& operator=(MoveGroupInterface&& other) noexcept;

  // --- the group and the model ---------------------------------------------------------------------------------------
  const std::string& getName() const;
  /** the group's states in the SRDF (remembered values are not listed, as MoveIt's) */
  const std::vector<std::string>& getNamedTargets() const;
  moveit::core::RobotModelConstPtr getRobotModel() const;
  const ros::NodeHandle& getNodeHandle() const;
  /** the model frame (the SRDF's virtual joint's parent frame, else the URDF's root link) */
  const std::string& getPlanningFrame() const;
  const std::vector<std::string>& getJointModelGroupNames() const;
  const std::vector<std::string>& getLinkNames() const;
  /** remembered values first, else the SRDF's group state of that name; empty when neither */
  std::map<std::string, double> getNamedTargetValues(const std::string& name) const;
  const std::vector<std::string>& getJoints() const;
  [[deprecated("use getVariableNames")]] const std::vector<std::string>& getJointNames() const
  {
    return getVariableNames();
  }
  const std::vector<std::string>& getVariableNames() const;
  const std::vector<std::string>& getActiveJoints() const;
  unsigned int getVariableCount() const;

  // --- planner settings ----------------------------------------------------------------------------------------------
  /** through `query_planner_interface` */
  bool getInterfaceDescriptions(std::vector<moveit_msgs::PlannerInterfaceDescription>& desc) const;
  bool getInterfaceDescription(moveit_msgs::PlannerInterfaceDescription& desc) const;
  /** not served by this move_group: empty, with an error naming the service */
  std::map<std::string, std::string> getPlannerParams(const std::string& planner_id,
                                                      const std::string& group = "") const;
  void setPlannerParams(const std::string& planner_id, const std::string& group,
                        const std::map<std::string, std::string>& params, bool bReplace = false);
  /** move_group/default_planning_pipeline */
  std::string getDefaultPlanningPipelineId() const;
  /** changing the pipeline clears the planner id */
  void setPlanningPipelineId(const std::string& pipeline_id);
  const std::string& getPlanningPipelineId() const;
  /** move_group/[planning_pipelines/<pipeline>/][<group>/]default_planner_config */
  std::string getDefaultPlannerId(const std::string& group = "") const;
  void setPlannerId(const std::string& planner_id);
  const std::string& getPlannerId() const;
  /** ignored unless positive */
  void setPlanningTime(double seconds);
  void setNumPlanningAttempts(unsigned int num_planning_attempts);
  /** in (0, 1]; above 1 is 1; 0 or below is robot_description_planning/default_velocity_scaling_factor (0.1) */
  void setMaxVelocityScalingFactor(double max_velocity_scaling_factor);
  void setMaxAccelerationScalingFactor(double max_acceleration_scaling_factor);
  void limitMaxCartesianLinkSpeed(const double max_speed, const std::string& link_name = "");
  void clearMaxCartesianLinkSpeed();
  double getPlanningTime() const;

  // --- tolerances and workspace --------------------------------------------------------------------------------------
  double getGoalJointTolerance() const;
  double getGoalPositionTolerance() const;
  double getGoalOrientationTolerance() const;
  /** the joint, position and orientation tolerances at once */
  void setGoalTolerance(double tolerance);
  void setGoalJointTolerance(double tolerance);
  void setGoalPositionTolerance(double tolerance);
  void setGoalOrientationTolerance(double tolerance);
  /** the box (planning frame) the planner samples a floating or planar base in */
  void setWorkspace(double minx, double miny, double minz, double maxx, double maxy, double maxz);

  // --- start state ---------------------------------------------------------------------------------------------------
  void setStartState(const moveit_msgs::RobotState& start_state);
  void setStartState(const moveit::core::RobotState& start_state);
  /** an empty diff: move_group starts from the state it has */
  void setStartStateToCurrentState();
  void setSupportSurfaceName(const std::string& name);

  // --- joint-space targets (each makes the joint target the active one) ----------------------------------------------
  /** the group's variables in getVariableNames() order; false on a wrong count or when out of bounds (the values are
      set all the same) */
  bool setJointValueTarget(const std::vector<double>& group_variable_values);
  /** variables of the group by name (one not in the group: false, nothing set) */
  bool setJointValueTarget(const std::map<std::string, double>& variable_values);
  bool setJointValueTarget(const std::vector<std::string>& variable_names, const std::vector<double>& variable_values);
  bool setJointValueTarget(const moveit::core::RobotState& robot_state);
  bool setJointValueTarget(const std::string& joint_name, const std::vector<double>& values);
  bool setJointValueTarget(const std::string& joint_name, double value);
  bool setJointValueTarget(const sensor_msgs::JointState& state);
  /** the group's joint values that put \e end_effector_link at the pose, by IK from the start state (the model's
      kinematics solver); false when IK fails (the partial result is kept) */
  bool setJointValueTarget(const geometry_msgs::Pose& eef_pose, const std::string& end_effector_link = "");
  bool setJointValueTarget(const geometry_msgs::PoseStamped& eef_pose, const std::string& end_effector_link = "");
  bool setJointValueTarget(const Eigen::Isometry3d& eef_pose, const std::string& end_effector_link = "");
  /** as setJointValueTarget(pose) with the solver's approximate solution accepted */
  bool setApproximateJointValueTarget(const geometry_msgs::Pose& eef_pose, const std::string& end_effector_link = "");
  bool setApproximateJointValueTarget(const geometry_msgs::PoseStamped& eef_pose,
                                      const std::string& end_effector_link = "");
  bool setApproximateJointValueTarget(const Eigen::Isometry3d& eef_pose, const std::string& end_effector_link = "");
  /** random values within the bounds */
  void setRandomTarget();
  /** remembered values of that name, else the SRDF's group state */
  bool setNamedTarget(const std::string& name);
  void getJointValueTarget(std::vector<double>& group_variable_values) const;
  [[deprecated]] const moveit::core::RobotState& getJointValueTarget() const;

  // --- Cartesian targets (the end effector link's; make the pose target the active one) ------------------------------
  /** position only (the orientation of an existing target is kept in the message and not constrained) */
  bool setPositionTarget(double x, double y, double z, const std::string& end_effector_link = "");
  bool setRPYTarget(double roll, double pitch, double yaw, const std::string& end_effector_link = "");
  bool setOrientationTarget(double x, double y, double z, double w, const std::string& end_effector_link = "");
  bool setPoseTarget(const Eigen::Isometry3d& end_effector_pose, const std::string& end_effector_link = "");
  bool setPoseTarget(const geometry_msgs::Pose& target, const std::string& end_effector_link = "");
  bool setPoseTarget(const geometry_msgs::PoseStamped& target, const std::string& end_effector_link = "");
  /** several poses: the plan reaches one of them */
  bool setPoseTargets(const EigenSTL::vector_Isometry3d& end_effector_pose, const std::string& end_effector_link = "");
  bool setPoseTargets(const std::vector<geometry_msgs::Pose>& target, const std::string& end_effector_link = "");
  bool setPoseTargets(const std::vector<geometry_msgs::PoseStamped>& target, const std::string& end_effector_link = "");
  /** the frame of poses given without one (the planning frame by default) */
  void setPoseReferenceFrame(const std::string& pose_reference_frame);
  /** false when the group has no end effector link yet or \e end_effector_link is empty */
  bool setEndEffectorLink(const std::string& end_effector_link);
  bool setEndEffector(const std::string& eef_name);
  void clearPoseTarget(const std::string& end_effector_link = "");
  void clearPoseTargets();
  const geometry_msgs::PoseStamped& getPoseTarget(const std::string& end_effector_link = "") const;
  const std::vector<geometry_msgs::PoseStamped>& getPoseTargets(const std::string& end_effector_link = "") const;
  /** the group's tip for a chain (the last link), else what setEndEffectorLink set */
  const std::string& getEndEffectorLink() const;
  const std::string& getEndEffector() const;
  const std::string& getPoseReferenceFrame() const;

  // --- planning and execution ----------------------------------------------------------------------------------------
  /** plan and execute, returning once the goal is sent */
  moveit::core::MoveItErrorCode asyncMove();
  actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>& getMoveGroupClient() const;
  /** plan and execute, waiting for the result */
  moveit::core::MoveItErrorCode move();
  /** plan only; the plan in \e plan */
  moveit::core::MoveItErrorCode plan(Plan& plan);
  moveit::core::MoveItErrorCode asyncExecute(const Plan& plan);
  moveit::core::MoveItErrorCode asyncExecute(const moveit_msgs::RobotTrajectory& trajectory);
  moveit::core::MoveItErrorCode execute(const Plan& plan);
  moveit::core::MoveItErrorCode execute(const moveit_msgs::RobotTrajectory& trajectory);
  /** the end effector link along straight lines through \e waypoints (pose reference frame), steps of at most
      \e eef_step metres; the fraction of the path achieved, -1 on error (\e error_code says which) */
  double computeCartesianPath(const std::vector<geometry_msgs::Pose>& waypoints, double eef_step, double jump_threshold,
                              moveit_msgs::RobotTrajectory& trajectory, bool avoid_collisions = true,
                              moveit_msgs::MoveItErrorCodes* error_code = nullptr);
  double computeCartesianPath(const std::vector<geometry_msgs::Pose>& waypoints, double eef_step, double jump_threshold,
                              moveit_msgs::RobotTrajectory& trajectory,
                              const moveit_msgs::Constraints& path_constraints, bool avoid_collisions = true,
                              moveit_msgs::MoveItErrorCodes* error_code = nullptr);
  /** stops the trajectory being executed */
  void stop();
  void allowReplanning(bool flag);
  void setReplanAttempts(int32_t attempts);
  void setReplanDelay(double delay);
  void allowLooking(bool flag);
  void setLookAroundAttempts(int32_t attempts);
  /** the request plan() and move() send */
  void constructMotionPlanRequest(moveit_msgs::MotionPlanRequest& request);

  // --- pick and place (move_group here refuses them) -----------------------------------------------------------------
  moveit_msgs::PickupGoal constructPickupGoal(const std::string& object, std::vector<moveit_msgs::Grasp> grasps,
                                              bool plan_only) const;
  moveit_msgs::PlaceGoal constructPlaceGoal(const std::string& object,
                                            std::vector<moveit_msgs::PlaceLocation> locations, bool plan_only) const;
  std::vector<moveit_msgs::PlaceLocation>
  posesToPlaceLocations(const std::vector<geometry_msgs::PoseStamped>& poses) const;
  moveit::core::MoveItErrorCode pick(const std::string& object, bool plan_only = false)
  {
    return pick(constructPickupGoal(object, std::vector<moveit_msgs::Grasp>(), plan_only));
  }
  moveit::core::MoveItErrorCode pick(const std::string& object, const moveit_msgs::Grasp& grasp, bool plan_only = false)
  {
    return pick(constructPickupGoal(object, { grasp }, plan_only));
  }
  moveit::core::MoveItErrorCode pick(const std::string& object, std::vector<moveit_msgs::Grasp> grasps,
                                     bool plan_only = false)
  {
    return pick(constructPickupGoal(object, std::move(grasps), plan_only));
  }
  moveit::core::MoveItErrorCode pick(const moveit_msgs::PickupGoal& goal);
  moveit::core::MoveItErrorCode planGraspsAndPick(const std::string& object = "", bool plan_only = false);
  moveit::core::MoveItErrorCode planGraspsAndPick(const moveit_msgs::CollisionObject& object, bool plan_only = false);
  moveit::core::MoveItErrorCode place(const std::string& object, bool plan_only = false)
  {
    return place(constructPlaceGoal(object, std::vector<moveit_msgs::PlaceLocation>(), plan_only));
  }
  moveit::core::MoveItErrorCode place(const std::string& object, std::vector<moveit_msgs::PlaceLocation> locations,
                                      bool plan_only = false)
  {
    return place(constructPlaceGoal(object, std::move(locations), plan_only));
  }
  moveit::core::MoveItErrorCode place(const std::string& object, const std::vector<geometry_msgs::PoseStamped>& poses,
                                      bool plan_only = false)
  {
    return place(constructPlaceGoal(object, posesToPlaceLocations(poses), plan_only));
  }
  moveit::core::MoveItErrorCode place(const std::string& object, const geometry_msgs::PoseStamped& pose,
                                      bool plan_only = false)
  {
    return place(constructPlaceGoal(object, posesToPlaceLocations({ pose }), plan_only));
  }
  moveit::core::MoveItErrorCode place(const moveit_msgs::PlaceGoal& goal);

  // --- attached objects (through the planning scene, synchronously) --------------------------------------------------
  /** attaches the world object \e object to \e link (the end effector link, else the group's first link), touching
      \e link (or \e touch_links); false when move_group could not attach it (no such object or link) */
  bool attachObject(const std::string& object, const std::string& link = "");
  bool attachObject(const std::string& object, const std::string& link, const std::vector<std::string>& touch_links);
  /** detaches \e name: an object, or every object on that link of the group; every object on the group's links when
      empty. The object returns to the world where it is now. */
  bool detachObject(const std::string& name = "");

  // --- the current state (from joint_states) -------------------------------------------------------------------------
  /** starts listening to joint_states and waits up to \e wait seconds for every joint of the group */
  bool startStateMonitor(double wait = 1.0);
  /** the group's variables now; empty when no recent state came within a second */
  std::vector<double> getCurrentJointValues() const;
  /** the robot's state, once a joint_states message newer than the call has named every joint (up to \e wait s);
      null when none did */
  moveit::core::RobotStatePtr getCurrentState(double wait = 1) const;
  /** the link's pose now in the planning frame */
  geometry_msgs::PoseStamped getCurrentPose(const std::string& end_effector_link = "") const;
  /** roll, pitch, yaw of the link now (static axes X, Y, Z) */
  std::vector<double> getCurrentRPY(const std::string& end_effector_link = "") const;
  std::vector<double> getRandomJointValues() const;
  geometry_msgs::PoseStamped getRandomPose(const std::string& end_effector_link = "") const;

  // --- remembered joint values (in this client only) -----------------------------------------------------------------
  void rememberJointValues(const std::string& name);
  void rememberJointValues(const std::string& name, const std::vector<double>& values);
  const std::map<std::string, std::vector<double> >& getRememberedJointValues() const
  {
    return remembered_joint_values_;
  }
  void forgetJointValues(const std::string& name);

  // --- constraints ---------------------------------------------------------------------------------------------------
  /** not provided (MoveIt's warehouse): an error saying so */
  void setConstraintsDatabase(const std::string& host, unsigned int port);
  std::vector<std::string> getKnownConstraints() const;
  moveit_msgs::Constraints getPathConstraints() const;
  /** by name from the constraints database: not provided, false */
  bool setPathConstraints(const std::string& constraint);
  void setPathConstraints(const moveit_msgs::Constraints& constraint);
  void clearPathConstraints();
  moveit_msgs::TrajectoryConstraints getTrajectoryConstraints() const;
  void setTrajectoryConstraints(const moveit_msgs::TrajectoryConstraints& constraint);
  void clearTrajectoryConstraints();

protected:
  const moveit::core::RobotState& getTargetRobotState() const;

private:
  std::map<std::string, std::vector<double> > remembered_joint_values_;
  class MoveGroupInterfaceImpl;
  MoveGroupInterfaceImpl* impl_;
};
}  // namespace planning_interface
}  // namespace moveit
