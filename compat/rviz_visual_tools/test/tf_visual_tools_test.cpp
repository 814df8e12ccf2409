// TFVisualTools against rviz_visual_tools noetic-devel 3.9.1's src/tf_visual_tools.cpp (lines cited): what a tf2
// listener and a /tf subscriber receive from it. Run by test/tf_visual_tools.test (a master).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <string>

#include <Eigen/Geometry>
#include <ros/ros.h>
#include <rviz_visual_tools/tf_visual_tools.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace
{
const double LOOP_HZ = 20.0;   // the broadcast rate under test
const double WAIT = 5.0;       // s (wall): the longest wait for a condition
const double POLL = 0.01;      // s (wall)
const double EXACT = 1e-9;     // m, and quaternion components
const char PARENT[] = "tf_visual_tools_parent";
const char CHILD[] = "tf_visual_tools_child";
const char OTHER[] = "tf_visual_tools_other";

Eigen::Isometry3d makePose(double x, double y, double z, double angle)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  pose.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return pose;
}

bool waitFor(const std::function<bool()>& condition)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(WAIT);
  while (!condition() && ros::WallTime::now() < deadline)
    ros::WallDuration(POLL).sleep();
  return condition();
}

// The /tf messages this process's broadcaster sends, counted, the last one kept
class TfRecorder
{
public:
  TfRecorder() : sub_(ros::NodeHandle().subscribe("/tf", 100, &TfRecorder::callback, this))
  {
  }
  int count()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_;
  }
  tf2_msgs::TFMessage last()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_;
  }

private:
  void callback(const tf2_msgs::TFMessage& msg)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++count_;
    last_ = msg;
  }
  std::mutex mutex_;
  int count_ = 0;
  tf2_msgs::TFMessage last_;
  ros::Subscriber sub_;
};

// waits for a /tf message sent after now, returns it
tf2_msgs::TFMessage nextMessage(TfRecorder& recorder)
{
  const int seen = recorder.count();
  EXPECT_TRUE(waitFor([&] { return recorder.count() > seen; }));
  return recorder.last();
}
}  // namespace

// A kept transform is what a tf2 listener then looks up; the same pair again replaces it (l. 82-91)
TEST(TFVisualTools, BroadcastsKeptTransformsAndReplacesAPair)
{
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  TfRecorder recorder;
  rviz_visual_tools::TFVisualTools tools(LOOP_HZ);

  const Eigen::Isometry3d first = makePose(0.1, -0.2, 0.3, 0.7);
  EXPECT_TRUE(tools.publishTransform(first, PARENT, CHILD));
  ASSERT_TRUE(buffer.canTransform(PARENT, CHILD, ros::Time(0), ros::Duration(WAIT)));
  geometry_msgs::TransformStamped got = buffer.lookupTransform(PARENT, CHILD, ros::Time(0));
  EXPECT_NEAR(got.transform.translation.x, 0.1, EXACT);
  EXPECT_NEAR(got.transform.translation.y, -0.2, EXACT);
  EXPECT_NEAR(got.transform.translation.z, 0.3, EXACT);
  const Eigen::Quaterniond q(first.rotation());
  EXPECT_NEAR(std::abs(got.transform.rotation.x * q.x() + got.transform.rotation.y * q.y() +
                       got.transform.rotation.z * q.z() + got.transform.rotation.w * q.w()),
              1.0, EXACT);

  // the same pair again and a second pair: two transforms in each message, the first one moved
  EXPECT_TRUE(tools.publishTransform(makePose(0.4, 0.5, 0.6, 0.0), PARENT, CHILD));
  EXPECT_TRUE(tools.publishTransform(makePose(1.0, 0.0, 0.0, 0.0), PARENT, OTHER));
  const tf2_msgs::TFMessage msg = nextMessage(recorder);
  ASSERT_EQ(msg.transforms.size(), 2u);
  EXPECT_EQ(msg.transforms[0].child_frame_id, CHILD);
  EXPECT_NEAR(msg.transforms[0].transform.translation.x, 0.4, EXACT);
  EXPECT_EQ(msg.transforms[1].child_frame_id, OTHER);
  EXPECT_EQ(msg.transforms[0].header.frame_id, PARENT);

  // cleared: the next message holds none (l. 98-101)
  tools.clearAllTransforms();
  nextMessage(recorder);  // one may have been under way
  EXPECT_TRUE(nextMessage(recorder).transforms.empty());
}

// A rotation whose quaternion is not of unit length is sent normalised (l. 66-77)
TEST(TFVisualTools, NormalisesTheQuaternion)
{
  TfRecorder recorder;
  rviz_visual_tools::TFVisualTools tools(LOOP_HZ);
  Eigen::Isometry3d scaled = makePose(0.0, 0.0, 0.0, 0.3);
  const double scale = 1.01;  // a rotation block 1 % too long: Eigen's quaternion of it is not unit
  scaled.linear() *= scale;
  ASSERT_GT(std::abs(Eigen::Quaterniond(scaled.linear()).norm() - 1.0), 1e-3);
  tools.publishTransform(scaled, PARENT, CHILD);
  tf2_msgs::TFMessage msg;
  ASSERT_TRUE(waitFor([&] {
    msg = recorder.last();
    return !msg.transforms.empty();
  }));
  const geometry_msgs::Quaternion& r = msg.transforms[0].transform.rotation;
  EXPECT_NEAR(r.x * r.x + r.y * r.y + r.z * r.z + r.w * r.w, 1.0, EXACT);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "tf_visual_tools_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
