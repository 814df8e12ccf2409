// robot_model_loader::RobotModelLoader against a master (test/robot_model_loader.test): the six-axis fixture arm's
// URDF and SRDF as robot_description(_semantic), its joint limits overridden under robot_description_planning as a
// Setup-Assistant config's joint_limits.yaml does; its kinematics.yaml's timeouts and solvers (no C++ plugin for
// MoveIt's KDL name or for a plugin not installed: setFromIK answers with KDL); a description with no SRDF; one that
// is not there.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <moveit/robot_model_loader/robot_model_loader.h>
#include <moveit/robot_state/robot_state.h>
#include <ros/ros.h>

namespace
{
// test/robot_model_loader.test's joint_limits for shoulder_pan_joint (the URDF says velocity 3.0, no acceleration)
const double PLANNING_MAX_VELOCITY = 0.75;
const double PLANNING_MAX_ACCELERATION = 1.25;
const double URDF_MAX_VELOCITY = 3.0;
// test/robot_model_loader.test's kinematics_solver_timeout values; MoveIt's default for a group without one
// (joint_model_group.h's KinematicsSolver)
const double MANIPULATOR_IK_TIMEOUT = 0.02;
const double WRIST_IK_TIMEOUT = 1.0;
const double DEFAULT_IK_TIMEOUT = 0.5;
const double IK_TOLERANCE = 1e-6;
const double IK_TIMEOUT = 2.0;   // s for the KDL answer on a shared machine
}  // namespace

TEST(RobotModelLoader, ModelFromTheParameterServer)
{
  robot_model_loader::RobotModelLoader loader("robot_description");
  const moveit::core::RobotModelPtr& model = loader.getModel();
  ASSERT_TRUE(model);
  // the name ros::NodeHandle::searchParam found, resolved, as MoveIt's rdf_loader keeps it
  EXPECT_EQ(loader.getRobotDescription(), "/robot_description");
  EXPECT_EQ(model->getName(), "six_axis_arm");
  EXPECT_TRUE(model->hasJointModelGroup("manipulator"));
  EXPECT_TRUE(model->hasJointModelGroup("wrist"));
  ASSERT_TRUE(loader.getURDF());
  ASSERT_TRUE(loader.getSRDF());
  EXPECT_EQ(loader.getSRDF()->getName(), model->getName());
}

TEST(RobotModelLoader, PlanningJointLimitsOverrideTheUrdfs)
{
  robot_model_loader::RobotModelLoader loader("robot_description");
  ASSERT_TRUE(loader.getModel());
  const moveit::core::VariableBounds& pan = loader.getModel()->getVariableBounds("shoulder_pan_joint");
  EXPECT_TRUE(pan.velocity_bounded_);
  EXPECT_DOUBLE_EQ(pan.max_velocity_, PLANNING_MAX_VELOCITY);
  EXPECT_TRUE(pan.acceleration_bounded_);
  EXPECT_DOUBLE_EQ(pan.max_acceleration_, PLANNING_MAX_ACCELERATION);
  // a joint the yaml leaves alone keeps the URDF's velocity
  const moveit::core::VariableBounds& lift = loader.getModel()->getVariableBounds("shoulder_lift_joint");
  EXPECT_DOUBLE_EQ(lift.max_velocity_, URDF_MAX_VELOCITY);
}

TEST(RobotModelLoader, WithoutAnSrdfTheModelHasNoGroups)
{
  robot_model_loader::RobotModelLoader loader("bare_description");
  ASSERT_TRUE(loader.getModel());
  EXPECT_TRUE(loader.getModel()->getJointModelGroupNames().empty());
  EXPECT_TRUE(loader.getModel()->hasJointModel("shoulder_pan_joint"));
}

TEST(RobotModelLoader, KinematicsTimeoutsAndTheKdlFallback)
{
  robot_model_loader::RobotModelLoader loader("robot_description");
  const moveit::core::RobotModelPtr& model = loader.getModel();
  ASSERT_TRUE(model);
  ASSERT_TRUE(loader.getKinematicsPluginLoader());
  const std::vector<std::string>& known = loader.getKinematicsPluginLoader()->getKnownGroups();
  EXPECT_EQ(known, (std::vector<std::string>{ "manipulator", "wrist" }));
  const moveit::core::JointModelGroup* manipulator = model->getJointModelGroup("manipulator");
  EXPECT_FALSE(manipulator->getSolverInstance());
  EXPECT_DOUBLE_EQ(manipulator->getDefaultIKTimeout(), MANIPULATOR_IK_TIMEOUT);
  EXPECT_FALSE(model->getJointModelGroup("wrist")->getSolverInstance());
  EXPECT_DOUBLE_EQ(model->getJointModelGroup("wrist")->getDefaultIKTimeout(), WRIST_IK_TIMEOUT);
  EXPECT_DOUBLE_EQ(model->getJointModelGroup("arm_by_parts")->getDefaultIKTimeout(), DEFAULT_IK_TIMEOUT);

  // without a plugin, setFromIK is the KDL solver's
  moveit::core::RobotState goal(model), state(model);
  goal.setToDefaultValues();
  goal.setToRandomPositions(manipulator);
  goal.update();
  const Eigen::Isometry3d target = goal.getGlobalLinkTransform("tool0");
  state.setToDefaultValues();
  ASSERT_TRUE(state.setFromIK(manipulator, target, "tool0", IK_TIMEOUT));
  state.update();
  EXPECT_LT((state.getGlobalLinkTransform("tool0").translation() - target.translation()).norm(), IK_TOLERANCE);

  // asked not to, the loader loads nothing
  robot_model_loader::RobotModelLoader bare("robot_description", false);
  ASSERT_TRUE(bare.getModel());
  EXPECT_FALSE(bare.getKinematicsPluginLoader());
  EXPECT_DOUBLE_EQ(bare.getModel()->getJointModelGroup("manipulator")->getDefaultIKTimeout(), DEFAULT_IK_TIMEOUT);
}

TEST(RobotModelLoader, AnAbsentDescriptionGivesNoModel)
{
  robot_model_loader::RobotModelLoader loader("no_such_description");
  EXPECT_FALSE(loader.getModel());
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "robot_model_loader_check");
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
