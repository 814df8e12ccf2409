// rostest node: MoveGroupInterface on the px100's fake move_group. What MoveIt's MoveGroupInterface answers
// (move_group_interface.cpp, noetic-devel 7c0343f0) for wrong arguments, the MotionPlanRequest it builds, and that
// plan, move and attach reach move_group and come back with what /joint_states then says.
#include <algorithm>
#include <mutex>
#include <utility>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <moveit/move_group_interface/move_group_interface.h>
#include <moveit/planning_scene_interface/planning_scene_interface.h>
#include <ros/console.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <shape_msgs/SolidPrimitive.h>

using moveit::planning_interface::MoveGroupInterface;
using moveit::planning_interface::PlanningSceneInterface;
using Codes = moveit_msgs::MoveItErrorCodes;

namespace
{
const std::string GROUP = "interbotix_arm";
const std::vector<std::string> ARM = { "waist", "shoulder", "elbow", "wrist_angle" };
const std::string TIP = "px100/ee_gripper_link";
// how close a reached joint goal must be (rad): the fake controllers reach the last point exactly
const double JOINT_TOLERANCE = 0.01;
const double JOINT_STATES_WAIT = 5.0;  // s
// the stopped motion: 1.5 rad of waist at a tenth of its 2.35 rad/s takes over 6 s, long enough to stop it midway
const double WAIST_TRAVEL = 1.5;         // rad
const double SLOW = 0.1;
const double MOVED = 0.05;               // rad: the waist has left its start (or stopped this short of the goal)
const double MOTION_START_WAIT = 10.0;   // s (wall): planning and the start of execution
const double STOP_WAIT = 10.0;           // s: the move's result after the stop
const double POLL = 0.05;                // s (wall)
const double SCENE_WAIT = 5.0;           // s (wall): a diff on the planning_scene topic applied
// a position the px100 (reach under 0.4 m) cannot have: move_group aborts the goal
const double OUT_OF_REACH_X = 5.0;  // m

// Keeps what this process logs through rosconsole, level and text
class LogRecorder : public ros::console::LogAppender
{
public:
  void log(ros::console::Level level, const char* str, const char*, const char*, int) override
  {
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.emplace_back(level, str);
  }
  std::vector<std::pair<ros::console::Level, std::string>> take()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::move(lines_);
  }

private:
  std::mutex mutex_;
  std::vector<std::pair<ros::console::Level, std::string>> lines_;
};

// the lines starting with `prefix`, by level
std::vector<ros::console::Level> levelsOf(const std::vector<std::pair<ros::console::Level, std::string>>& lines,
                                          const std::string& prefix)
{
  std::vector<ros::console::Level> levels;
  for (const auto& line : lines)
    if (line.second.compare(0, prefix.size(), prefix) == 0)
      levels.push_back(line.first);
  return levels;
}
}  // namespace

class MoveGroupInterfaceTest : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    group_ = new MoveGroupInterface(GROUP);
  }
  static void TearDownTestSuite()
  {
    delete group_;
    group_ = nullptr;
  }
  static MoveGroupInterface* group_;
};
MoveGroupInterface* MoveGroupInterfaceTest::group_ = nullptr;

TEST_F(MoveGroupInterfaceTest, KnowsTheGroup)
{
  EXPECT_EQ(group_->getName(), GROUP);
  EXPECT_EQ(group_->getVariableNames(), ARM);
  EXPECT_EQ(group_->getVariableCount(), ARM.size());
  EXPECT_EQ(group_->getEndEffectorLink(), TIP);  // the last link of a chain
  EXPECT_EQ(group_->getPlanningFrame(), group_->getRobotModel()->getModelFrame());
  std::vector<std::string> named = group_->getNamedTargets();
  std::sort(named.begin(), named.end());
  EXPECT_EQ(named, (std::vector<std::string>{ "Home", "Sleep" }));
  EXPECT_EQ(group_->getNamedTargetValues("Home").size(), ARM.size());
  EXPECT_TRUE(group_->getNamedTargetValues("no_such_state").empty());
}

TEST(MoveGroupInterfaceConstruction, AnUnknownGroupThrows)
{
  try
  {
    MoveGroupInterface unknown("no_such_group");
    FAIL() << "constructed for a group the model lacks";
  }
  catch (const std::runtime_error& error)
  {
    EXPECT_NE(std::string(error.what()).find("no_such_group"), std::string::npos) << error.what();
  }
}

TEST_F(MoveGroupInterfaceTest, RefusesWrongJointTargets)
{
  ASSERT_TRUE(group_->setJointValueTarget(std::vector<double>(ARM.size(), 0.0)));
  EXPECT_FALSE(group_->setJointValueTarget(std::vector<double>{ 0.1, 0.2 }));  // a wrong count
  EXPECT_FALSE(group_->setJointValueTarget(std::map<std::string, double>{ { "no_such_joint", 0.1 } }));
  EXPECT_FALSE(group_->setJointValueTarget("no_such_joint", 0.1));
  EXPECT_FALSE(group_->setJointValueTarget(std::vector<std::string>{ "waist" }, std::vector<double>{ 0.1, 0.2 }));
  EXPECT_FALSE(group_->setNamedTarget("no_such_state"));
  // nothing above changed the target
  std::vector<double> target;
  group_->getJointValueTarget(target);
  EXPECT_EQ(target, std::vector<double>(ARM.size(), 0.0));
  // out of bounds: false, and set all the same (MoveIt's documented behaviour)
  const std::vector<double> outside = { 10.0, 0.0, 0.0, 0.0 };
  EXPECT_FALSE(group_->setJointValueTarget(outside));
  group_->getJointValueTarget(target);
  EXPECT_EQ(target, outside);
  EXPECT_FALSE(group_->setPoseTargets(std::vector<geometry_msgs::Pose>{}));
  EXPECT_FALSE(group_->setEndEffectorLink(""));
  EXPECT_FALSE(group_->setPathConstraints(std::string("from_the_database")));  // no warehouse here
}

TEST_F(MoveGroupInterfaceTest, BuildsTheRequestAsMoveIt)
{
  group_->setNamedTarget("Home");
  group_->setPlannerId("RRTkConfigDefault");
  group_->setPlanningTime(-1.0);  // ignored
  group_->setNumPlanningAttempts(3);
  group_->setMaxVelocityScalingFactor(2.0);       // above 1: 1
  group_->setMaxAccelerationScalingFactor(0.0);  // 0: the config's default, else 0.1
  group_->setGoalJointTolerance(0.002);
  moveit_msgs::MotionPlanRequest request;
  group_->constructMotionPlanRequest(request);
  EXPECT_EQ(request.group_name, GROUP);
  EXPECT_EQ(request.planner_id, "RRTkConfigDefault");
  EXPECT_DOUBLE_EQ(request.allowed_planning_time, MoveGroupInterface::DEFAULT_ALLOWED_PLANNING_TIME);
  EXPECT_EQ(request.num_planning_attempts, 3);
  EXPECT_DOUBLE_EQ(request.max_velocity_scaling_factor, 1.0);
  EXPECT_DOUBLE_EQ(request.max_acceleration_scaling_factor, 0.1);
  EXPECT_TRUE(request.start_state.is_diff);
  ASSERT_EQ(request.goal_constraints.size(), 1u);
  const std::map<std::string, double> home = group_->getNamedTargetValues("Home");
  ASSERT_EQ(request.goal_constraints[0].joint_constraints.size(), ARM.size());
  for (const moveit_msgs::JointConstraint& c : request.goal_constraints[0].joint_constraints)
  {
    EXPECT_DOUBLE_EQ(c.position, home.at(c.joint_name)) << c.joint_name;
    EXPECT_DOUBLE_EQ(c.tolerance_above, 0.002);
    EXPECT_DOUBLE_EQ(c.tolerance_below, 0.002);
  }

  geometry_msgs::Pose pose;
  pose.position.x = 0.2;
  pose.position.z = 0.1;
  pose.orientation.w = 1.0;
  group_->setGoalPositionTolerance(0.005);
  group_->setGoalOrientationTolerance(0.05);
  ASSERT_TRUE(group_->setPoseTarget(pose));
  // a request is filled, not cleared, by constructMotionPlanRequest (goals merge into what it holds, as MoveIt's):
  // a new one each time
  request = moveit_msgs::MotionPlanRequest();
  group_->constructMotionPlanRequest(request);
  ASSERT_EQ(request.goal_constraints.size(), 1u);
  const moveit_msgs::Constraints& c = request.goal_constraints[0];
  EXPECT_TRUE(c.joint_constraints.empty());
  ASSERT_EQ(c.position_constraints.size(), 1u);
  ASSERT_EQ(c.orientation_constraints.size(), 1u);
  EXPECT_EQ(c.position_constraints[0].link_name, TIP);
  EXPECT_EQ(c.position_constraints[0].header.frame_id, group_->getPlanningFrame());
  EXPECT_DOUBLE_EQ(c.orientation_constraints[0].absolute_x_axis_tolerance, 0.05);

  ASSERT_TRUE(group_->setPositionTarget(0.2, 0.0, 0.1));
  request = moveit_msgs::MotionPlanRequest();
  group_->constructMotionPlanRequest(request);
  EXPECT_EQ(request.goal_constraints[0].position_constraints.size(), 1u);
  EXPECT_TRUE(request.goal_constraints[0].orientation_constraints.empty());
  ASSERT_TRUE(group_->setRPYTarget(0.0, 0.3, 0.0));
  request = moveit_msgs::MotionPlanRequest();
  group_->constructMotionPlanRequest(request);
  EXPECT_TRUE(request.goal_constraints[0].position_constraints.empty());
  EXPECT_EQ(request.goal_constraints[0].orientation_constraints.size(), 1u);
  group_->clearPoseTargets();
  group_->setGoalTolerance(MoveGroupInterface::DEFAULT_GOAL_JOINT_TOLERANCE);
  group_->setPlannerId("");
}

TEST_F(MoveGroupInterfaceTest, PlansAndMovesThroughMoveGroup)
{
  // the interface's current values are those joint_states gives
  const sensor_msgs::JointStateConstPtr before =
      ros::topic::waitForMessage<sensor_msgs::JointState>("joint_states", ros::Duration(JOINT_STATES_WAIT));
  ASSERT_TRUE(before);
  const std::vector<double> current = group_->getCurrentJointValues();
  ASSERT_EQ(current.size(), ARM.size());

  const std::vector<double> goal = { 0.4, -0.2, 0.3, 0.2 };
  ASSERT_TRUE(group_->setJointValueTarget(goal));
  MoveGroupInterface::Plan plan;
  const moveit::core::MoveItErrorCode planned = group_->plan(plan);
  ASSERT_TRUE(static_cast<bool>(planned)) << planned;
  ASSERT_GE(plan.trajectory_.joint_trajectory.points.size(), 2u);
  const std::vector<double>& last = plan.trajectory_.joint_trajectory.points.back().positions;
  for (std::size_t i = 0; i < ARM.size(); ++i)
    EXPECT_NEAR(last[i], goal[i], JOINT_TOLERANCE) << ARM[i];
  EXPECT_GT(plan.planning_time_, 0.0);

  ASSERT_TRUE(static_cast<bool>(group_->execute(plan)));
  const sensor_msgs::JointStateConstPtr after =
      ros::topic::waitForMessage<sensor_msgs::JointState>("joint_states", ros::Duration(JOINT_STATES_WAIT));
  ASSERT_TRUE(after);
  for (std::size_t i = 0; i < ARM.size(); ++i)
  {
    const auto it = std::find(after->name.begin(), after->name.end(), ARM[i]);
    ASSERT_NE(it, after->name.end());
    EXPECT_NEAR(after->position[it - after->name.begin()], goal[i], JOINT_TOLERANCE) << ARM[i];
  }
  const std::vector<double> reported = group_->getCurrentJointValues();
  for (std::size_t i = 0; i < ARM.size(); ++i)
    EXPECT_NEAR(reported[i], goal[i], JOINT_TOLERANCE) << ARM[i];

  // the named target through move()
  ASSERT_TRUE(group_->setNamedTarget("Home"));
  ASSERT_EQ(group_->move(), Codes::SUCCESS);
  const std::map<std::string, double> home = group_->getNamedTargetValues("Home");
  const std::vector<double> at_home = group_->getCurrentJointValues();
  for (std::size_t i = 0; i < ARM.size(); ++i)
    EXPECT_NEAR(at_home[i], home.at(ARM[i]), JOINT_TOLERANCE) << ARM[i];

  // remembered values come before the SRDF's, in this client only
  group_->rememberJointValues("Home", goal);
  EXPECT_EQ(group_->getNamedTargetValues("Home").at("waist"), goal[0]);
  group_->forgetJointValues("Home");
  EXPECT_EQ(group_->getNamedTargetValues("Home").at("waist"), home.at("waist"));
}

TEST_F(MoveGroupInterfaceTest, PlansFromAGivenStartState)
{
  moveit::core::RobotStatePtr start = group_->getCurrentState();
  ASSERT_TRUE(start);
  const std::vector<double> from = { -0.5, 0.1, 0.2, -0.3 };
  start->setJointGroupPositions(GROUP, from);
  group_->setStartState(*start);
  ASSERT_TRUE(group_->setJointValueTarget(std::vector<double>{ 0.5, 0.0, 0.0, 0.0 }));
  MoveGroupInterface::Plan plan;
  const moveit::core::MoveItErrorCode code = group_->plan(plan);
  group_->setStartStateToCurrentState();
  ASSERT_TRUE(static_cast<bool>(code)) << code;
  // the plan starts where it was told to, not where the arm is
  const trajectory_msgs::JointTrajectory& path = plan.trajectory_.joint_trajectory;
  ASSERT_FALSE(path.points.empty());
  for (std::size_t i = 0; i < ARM.size(); ++i)
  {
    const auto it = std::find(path.joint_names.begin(), path.joint_names.end(), ARM[i]);
    ASSERT_NE(it, path.joint_names.end());
    EXPECT_NEAR(path.points.front().positions[it - path.joint_names.begin()], from[i], 1e-6) << ARM[i];
  }
}

TEST_F(MoveGroupInterfaceTest, StopsAMoveUnderWay)
{
  // a slow motion of the waist, sent without waiting; stopped once joint_states show it moving
  ASSERT_TRUE(group_->setNamedTarget("Home"));
  ASSERT_EQ(group_->move(), Codes::SUCCESS);
  const double start = group_->getCurrentJointValues().at(0);
  std::vector<double> goal = group_->getCurrentJointValues();
  goal[0] = start + WAIST_TRAVEL;
  group_->setMaxVelocityScalingFactor(SLOW);
  ASSERT_TRUE(group_->setJointValueTarget(goal));
  ASSERT_EQ(group_->asyncMove(), Codes::SUCCESS);  // sent
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(MOTION_START_WAIT);
  while (std::fabs(group_->getCurrentJointValues().at(0) - start) < MOVED && ros::WallTime::now() < deadline)
    ros::WallDuration(POLL).sleep();
  ASSERT_GE(std::fabs(group_->getCurrentJointValues().at(0) - start), MOVED) << "the motion did not start";
  group_->stop();
  ASSERT_TRUE(group_->getMoveGroupClient().waitForResult(ros::Duration(STOP_WAIT)));
  EXPECT_EQ(group_->getMoveGroupClient().getResult()->error_code.val, Codes::PREEMPTED);
  // the arm stays short of the goal (a state stamped after the stop)
  EXPECT_LT(group_->getCurrentJointValues().at(0), goal[0] - MOVED);
  group_->setMaxVelocityScalingFactor(1.0);
}

TEST_F(MoveGroupInterfaceTest, AttachesAndDetachesThroughTheScene)
{
  PlanningSceneInterface scene;
  moveit_msgs::CollisionObject box;
  box.id = "test_box";
  box.header.frame_id = group_->getPlanningFrame();
  shape_msgs::SolidPrimitive primitive;
  primitive.type = primitive.BOX;
  primitive.dimensions = { 0.02, 0.02, 0.02 };
  box.primitives.push_back(primitive);
  box.primitive_poses.resize(1);
  box.primitive_poses[0].orientation.w = 1.0;
  box.pose.position.x = 0.5;  // out of the arm's reach
  box.pose.orientation.w = 1.0;
  box.operation = box.ADD;
  ASSERT_TRUE(scene.applyCollisionObject(box));
  EXPECT_EQ(scene.getKnownObjectNames(), std::vector<std::string>{ "test_box" });
  EXPECT_EQ(scene.getKnownObjectNamesInROI(0.4, -0.1, -0.1, 0.6, 0.1, 0.1).size(), 1u);
  EXPECT_TRUE(scene.getKnownObjectNamesInROI(-0.6, -0.1, -0.1, -0.4, 0.1, 0.1).empty());
  EXPECT_NEAR(scene.getObjectPoses({ "test_box" })["test_box"].position.x, 0.5, 1e-9);

  EXPECT_FALSE(group_->attachObject("no_such_object"));
  ASSERT_TRUE(group_->attachObject("test_box"));  // to the end effector link
  const auto attached = scene.getAttachedObjects();
  ASSERT_EQ(attached.count("test_box"), 1u);
  EXPECT_EQ(attached.at("test_box").link_name, TIP);
  EXPECT_TRUE(scene.getKnownObjectNames().empty());
  ASSERT_TRUE(group_->detachObject());  // every object on the group's links
  EXPECT_TRUE(scene.getAttachedObjects().empty());
  EXPECT_EQ(scene.getKnownObjectNames(), std::vector<std::string>{ "test_box" });

  ASSERT_TRUE(scene.clear());
  EXPECT_TRUE(scene.getKnownObjectNames().empty());

  // asynchronously, on the planning_scene topic: the object appears, then goes
  auto known = [&scene] { return scene.getKnownObjectNames(); };
  auto waitFor = [&known](const std::vector<std::string>& wanted) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(SCENE_WAIT);
    while (known() != wanted && ros::WallTime::now() < deadline)
      ros::WallDuration(POLL).sleep();
    return known();
  };
  scene.addCollisionObjects({ box });
  EXPECT_EQ(waitFor({ "test_box" }), std::vector<std::string>{ "test_box" });
  scene.removeCollisionObjects({ "test_box" });
  EXPECT_TRUE(waitFor({}).empty());
}

// A goal move_group aborts is reported as noetic-devel's MoveGroupInterface reports it
// (move_group_interface.cpp l. 899-900 plan, 854-855 move, 764-765 pick): plan() at INFO "ABORTED: <text>",
// move() and pick() at WARN "Fail: ABORTED: <text>"
TEST_F(MoveGroupInterfaceTest, ReportsAnAbortedGoalAsMoveIt)
{
  LogRecorder recorder;
  ros::console::register_appender(&recorder);
  group_->setStartStateToCurrentState();
  ASSERT_TRUE(group_->setPositionTarget(OUT_OF_REACH_X, 0.0, 0.0));
  MoveGroupInterface::Plan plan;
  EXPECT_NE(group_->plan(plan), Codes::SUCCESS);
  const auto planned = recorder.take();
  EXPECT_EQ(levelsOf(planned, "ABORTED: "), std::vector<ros::console::Level>{ ros::console::levels::Info });
  EXPECT_TRUE(levelsOf(planned, "Fail: ").empty());

  EXPECT_NE(group_->move(), Codes::SUCCESS);
  EXPECT_EQ(levelsOf(recorder.take(), "Fail: ABORTED: "), std::vector<ros::console::Level>{ ros::console::levels::Warn });

  EXPECT_NE(group_->pick("no_such_object"), Codes::SUCCESS);
  EXPECT_EQ(levelsOf(recorder.take(), "Fail: ABORTED: "), std::vector<ros::console::Level>{ ros::console::levels::Warn });
  ros::console::deregister_appender(&recorder);
  group_->clearPoseTargets();
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "move_group_interface_check");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
