// rviz_visual_tools' markers and remote control against upstream's rules (rviz_visual_tools
// noetic-devel 3.9.1 src/rviz_visual_tools.cpp and src/remote_control.cpp, lines cited), run by
// test/rviz_visual_tools.test (a master: RemoteControl subscribes).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <rviz_visual_tools/rviz_visual_tools.h>

namespace rvt = rviz_visual_tools;

namespace
{
const double EPS = 1e-12;

// The queued markers, which trigger() would send
class QueuedVisualTools : public rvt::RvizVisualTools
{
public:
  QueuedVisualTools() : RvizVisualTools("base", "/rviz_visual_tools_test")
  {
  }
  const std::vector<visualization_msgs::Marker>& queued() const
  {
    return markers_.markers;
  }
};

Eigen::Vector3d position(const visualization_msgs::Marker& marker)
{
  return Eigen::Vector3d(marker.pose.position.x, marker.pose.position.y, marker.pose.position.z);
}

Eigen::Matrix3d rotation(const visualization_msgs::Marker& marker)
{
  const geometry_msgs::Quaternion& q = marker.pose.orientation;
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
}
}  // namespace

TEST(RvizVisualTools, ScalesAreUpstreamsSizes)
{
  QueuedVisualTools tools;
  // l. 669-707
  const std::vector<std::pair<rvt::scales, double>> sizes = {
    { rvt::XXXXSMALL, 0.001 }, { rvt::XXXSMALL, 0.0025 }, { rvt::XXSMALL, 0.005 }, { rvt::XSMALL, 0.0065 },
    { rvt::SMALL, 0.0075 },    { rvt::MEDIUM, 0.01 },     { rvt::LARGE, 0.025 },   { rvt::XLARGE, 0.05 },
    { rvt::XXLARGE, 0.075 },   { rvt::XXXLARGE, 0.1 },    { rvt::XXXXLARGE, 0.5 }
  };
  for (const auto& size : sizes)
  {
    EXPECT_DOUBLE_EQ(tools.getScale(size.first).x, size.second) << rvt::RvizVisualTools::scaleToString(size.first);
    EXPECT_DOUBLE_EQ(tools.getScale(size.first, 2.0).z, 2.0 * size.second);
  }
  tools.setGlobalScale(3.0);
  EXPECT_DOUBLE_EQ(tools.getScale(rvt::MEDIUM).y, 0.03);
  EXPECT_EQ(rvt::RvizVisualTools::intToRvizScale(6), rvt::MEDIUM);
  EXPECT_THROW(rvt::RvizVisualTools::intToRvizScale(12), std::runtime_error);
  EXPECT_EQ(rvt::RvizVisualTools::intToRvizColor(11), rvt::RED);
  EXPECT_EQ(rvt::RvizVisualTools::intToRvizColor(99), rvt::DEFAULT);
}

TEST(RvizVisualTools, ColorsAreUpstreamsValues)
{
  QueuedVisualTools tools;
  const std_msgs::ColorRGBA red = tools.getColor(rvt::RED);
  EXPECT_FLOAT_EQ(red.r, 0.8);
  EXPECT_FLOAT_EQ(red.g, 0.1);
  EXPECT_FLOAT_EQ(red.a, 1.0);
  EXPECT_FLOAT_EQ(tools.getColor(rvt::LIME_GREEN).r, 0.6);
  EXPECT_FLOAT_EQ(tools.getColor(rvt::TRANSLUCENT).a, 0.25);
  EXPECT_FLOAT_EQ(tools.getColor(rvt::CLEAR).a, 0.0);
  tools.setAlpha(0.5);
  EXPECT_FLOAT_EQ(tools.getColor(rvt::BLUE).a, 0.5);
  EXPECT_FLOAT_EQ(tools.getColor(rvt::TRANSLUCENT_DARK).a, 0.5);
  // 0.25 is halfway from red to yellow (l. 644-661)
  const std_msgs::ColorRGBA quarter = tools.getColorScale(0.25);
  EXPECT_NEAR(quarter.r, 0.9, 1e-6);
  EXPECT_NEAR(quarter.g, 0.55, 1e-6);
}

TEST(RvizVisualTools, MarkersAreBatchedUntilTrigger)
{
  QueuedVisualTools tools;
  EXPECT_FALSE(tools.trigger()) << "nothing queued";
  tools.publishSphere(Eigen::Vector3d(1, 2, 3));
  tools.publishSphere(Eigen::Vector3d(4, 5, 6));
  ASSERT_EQ(tools.queued().size(), 2u);
  EXPECT_EQ(tools.queued()[0].ns, "Sphere");
  EXPECT_EQ(tools.queued()[1].id, tools.queued()[0].id + 1) << "id 0 asks for the next id";
  EXPECT_EQ(tools.queued()[0].header.frame_id, "base");
  EXPECT_TRUE(tools.trigger());
  EXPECT_TRUE(tools.queued().empty());
  tools.deleteAllMarkers();
  ASSERT_EQ(tools.queued().size(), 1u);
  EXPECT_EQ(tools.queued()[0].action, visualization_msgs::Marker::DELETEALL);
}

TEST(RvizVisualTools, StaticTextKeepsIdZeroAndTheCount)
{
  QueuedVisualTools tools;
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  tools.publishText(pose, "a", rvt::WHITE, rvt::LARGE, false);
  tools.publishText(pose, "b", rvt::WHITE, rvt::LARGE, true);
  tools.publishText(pose, "c", rvt::WHITE, rvt::LARGE, false);
  ASSERT_EQ(tools.queued().size(), 3u);
  EXPECT_EQ(tools.queued()[0].id, 1);
  EXPECT_EQ(tools.queued()[1].id, 0);
  EXPECT_EQ(tools.queued()[2].id, 2);
  EXPECT_EQ(tools.queued()[1].type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_DOUBLE_EQ(tools.queued()[1].scale.x, 0.0);
  EXPECT_DOUBLE_EQ(tools.queued()[1].scale.z, 0.025);
}

TEST(RvizVisualTools, PathCylindersJoinThePoints)
{
  QueuedVisualTools tools;
  EigenSTL::vector_Vector3d path = { Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, 0.1, -0.2),
                                     Eigen::Vector3d(0.3, 0.1, 0.5), Eigen::Vector3d(0.3, 0.1, 0.1) };
  ASSERT_TRUE(tools.publishPath(path, rvt::RED, 0.02));
  ASSERT_EQ(tools.queued().size(), path.size() - 1);
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    const visualization_msgs::Marker& cylinder = tools.queued()[i - 1];
    EXPECT_EQ(cylinder.type, visualization_msgs::Marker::CYLINDER);
    EXPECT_EQ(cylinder.ns, "Path");
    EXPECT_NEAR((position(cylinder) - (path[i - 1] + path[i]) / 2).norm(), 0.0, EPS);
    EXPECT_NEAR(cylinder.scale.z, (path[i] - path[i - 1]).norm(), EPS);
    EXPECT_DOUBLE_EQ(cylinder.scale.x, 0.02);
    // along its z, whichever way the segment points (straight up and down included)
    const Eigen::Vector3d along = rotation(cylinder).col(2);
    EXPECT_NEAR(std::fabs(along.dot((path[i] - path[i - 1]).normalized())), 1.0, 1e-9) << "segment " << i;
  }
  EXPECT_FALSE(tools.publishPath(EigenSTL::vector_Vector3d(1, Eigen::Vector3d::Zero()), rvt::RED, 0.02));
}

TEST(RvizVisualTools, AxisIsThreeCylindersAlongThePosesAxes)
{
  QueuedVisualTools tools;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(1, 2, 3);
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  tools.publishAxis(pose, rvt::LARGE);
  ASSERT_EQ(tools.queued().size(), 3u);
  const double length = 0.25;  // ten times LARGE's 0.025 (l. 1449-1450)
  for (int axis = 0; axis < 3; ++axis)
  {
    const visualization_msgs::Marker& cylinder = tools.queued()[axis];
    EXPECT_EQ(cylinder.ns, "Axis");
    EXPECT_NEAR(cylinder.scale.z, length, EPS);
    EXPECT_NEAR((position(cylinder) - (pose.translation() + pose.linear().col(axis) * length / 2)).norm(), 0.0,
                1e-9);
    // a cylinder lies along its z (upstream's y cylinder points its z along -y, l. 1484)
    EXPECT_NEAR(std::fabs(rotation(cylinder).col(2).dot(pose.linear().col(axis))), 1.0, 1e-9);
  }
  EXPECT_FLOAT_EQ(tools.queued()[0].color.r, 0.8) << "x is red";
  EXPECT_FLOAT_EQ(tools.queued()[1].color.g, 0.8) << "y is green";
  EXPECT_FLOAT_EQ(tools.queued()[2].color.b, 0.8) << "z is blue";
}

TEST(RvizVisualTools, ArrowsAndCuboids)
{
  QueuedVisualTools tools;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  tools.publishZArrow(pose, rvt::BLUE, rvt::MEDIUM, 0.3);
  ASSERT_EQ(tools.queued().size(), 1u);
  EXPECT_EQ(tools.queued()[0].type, visualization_msgs::Marker::ARROW);
  EXPECT_DOUBLE_EQ(tools.queued()[0].scale.x, 0.3);
  // an arrow points along its x: a z arrow's x is the pose's z
  EXPECT_NEAR((rotation(tools.queued()[0]).col(0) - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-9);

  tools.publishCuboid(Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 3, 1));
  const visualization_msgs::Marker& cuboid = tools.queued()[1];
  EXPECT_EQ(cuboid.type, visualization_msgs::Marker::CUBE);
  EXPECT_NEAR((position(cuboid) - Eigen::Vector3d(0.5, 2, 1)).norm(), 0.0, EPS);
  EXPECT_DOUBLE_EQ(cuboid.scale.y, 2.0);
  EXPECT_DOUBLE_EQ(cuboid.scale.z, rvt::SMALL_SCALE) << "a flat side is drawn SMALL_SCALE thick";
}

TEST(RvizVisualTools, PoseConversionsRoundTrip)
{
  const Eigen::Isometry3d pose = rvt::RvizVisualTools::convertFromXYZRPY(0.1, -0.2, 0.3, 0.4, -0.5, 0.6, rvt::ZYX);
  const Eigen::Isometry3d back = rvt::RvizVisualTools::convertPose(rvt::RvizVisualTools::convertPose(pose));
  EXPECT_TRUE(rvt::RvizVisualTools::posesEqual(pose, back, 1e-12));
  // ZYX is roll about x, then pitch about y, then yaw about z, in the fixed frame (REP 103)
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_NEAR((pose.linear() - expected).norm(), 0.0, 1e-12);
}

TEST(RemoteControl, NextOnlyCountsWhileWaiting)
{
  ros::NodeHandle nh("~");
  rvt::RemoteControl remote(nh);
  // A press while nothing waits is forgotten (remote_control.cpp l. 89-98): the wait below
  // would otherwise return at once, and autonomous mode is what lets it return here
  remote.setReadyForNextStep();
  EXPECT_FALSE(remote.isWaiting());
  remote.setAutonomous();
  EXPECT_TRUE(remote.waitForNextStep("autonomous: no wait"));
  remote.setStop();
  EXPECT_FALSE(remote.getAutonomous());
  EXPECT_TRUE(remote.getStop());
  remote.setFullAutonomous();
  EXPECT_TRUE(remote.getAutonomous());
  EXPECT_FALSE(remote.getStop());
}

TEST(RemoteControl, JoyButtonsFromThePanel)
{
  ros::NodeHandle nh("~");
  rvt::RemoteControl remote(nh);
  sensor_msgs::Joy::Ptr joy(new sensor_msgs::Joy);
  joy->buttons = { 0, 0, 1, 0, 0 };
  remote.rvizDashboardCallback(joy);
  EXPECT_TRUE(remote.getAutonomous());
  EXPECT_FALSE(remote.getFullAutonomous());
  joy->buttons = { 0, 0, 0, 0, 1 };
  remote.rvizDashboardCallback(joy);
  EXPECT_FALSE(remote.getAutonomous());
  EXPECT_TRUE(remote.getStop());
  joy->buttons = { 0, 0, 0, 1, 0 };
  remote.rvizDashboardCallback(joy);
  EXPECT_TRUE(remote.getFullAutonomous());
  EXPECT_TRUE(remote.waitForNextFullStep("full autonomous: no wait"));
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rviz_visual_tools_test");
  return RUN_ALL_TESTS();
}
