// robot_model_loader::RobotModelLoader against a master (test/robot_model_loader.test): the six-axis fixture arm's
// URDF and SRDF as robot_description(_semantic), its joint limits overridden under robot_description_planning as a
// Setup-Assistant config's joint_limits.yaml does; a description with no SRDF; one that is not there.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <moveit/robot_model_loader/robot_model_loader.h>
#include <ros/ros.h>

namespace
{
// test/robot_model_loader.test's joint_limits for shoulder_pan_joint (the URDF says velocity 3.0, no acceleration)
const double PLANNING_MAX_VELOCITY = 0.75;
const double PLANNING_MAX_ACCELERATION = 1.25;
const double URDF_MAX_VELOCITY = 3.0;
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
