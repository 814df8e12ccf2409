// The /rotate_robot service of the RB1 project written in C++, as the guide allows: turns the
// robot in place by the requested degrees, closed loop on the yaw read from /odom (summed
// across the +-180 degree seam, so 270 and 360 turn that far), slowing near the goal, and
// answers once the robot has stopped. A fixture of course_grader's tests (rb1_fault_fixtures):
// a correct C++ submission must score full marks.
#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2/utils.h>

#include "my_rb1_ros/Rotate.h"

namespace {

// Turning speeds (rad/s), the gain (1/s) of speed on the remaining angle, and when a turn
// is done (rad); the robot is still below kStillSpeed (rad/s).
constexpr double kMaxSpeed = 0.8;
constexpr double kMinSpeed = 0.05;
constexpr double kGain = 1.5;
constexpr double kTolerance = 0.005;
constexpr double kStillSpeed = 0.01;
constexpr double kRate = 50.0;         // Hz, the control loop
constexpr double kOdomTimeout = 5.0;   // s without odometry before a request fails
constexpr double kSettleTime = 1.0;    // s at most waiting for the robot to be still
constexpr double kSlack = 2.0;         // a turn may take this many times its time at full speed
constexpr double kMargin = 5.0;        // s on top of that

double wrap(double angle) { return std::atan2(std::sin(angle), std::cos(angle)); }

}  // namespace

class RotateService {
 public:
  explicit RotateService(ros::NodeHandle &nh) {
    command_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    odometry_ = nh.subscribe("odom", 10, &RotateService::onOdometry, this);
    server_ = nh.advertiseService("/rotate_robot", &RotateService::serve, this);
    ROS_INFO("Service Ready");
  }

 private:
  void onOdometry(const nav_msgs::Odometry::ConstPtr &message) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double yaw = tf2::getYaw(message->pose.pose.orientation);
    total_ = have_odometry_ ? total_ + wrap(yaw - last_) : yaw;
    last_ = yaw;
    rate_ = message->twist.twist.angular.z;
    have_odometry_ = true;
  }

  bool reading(double *total, double *rate) {
    std::lock_guard<std::mutex> lock(mutex_);
    *total = total_;
    *rate = rate_;
    return have_odometry_;
  }

  void turn(double speed) {
    geometry_msgs::Twist twist;
    twist.angular.z = speed;
    command_.publish(twist);
  }

  bool serve(my_rb1_ros::Rotate::Request &request, my_rb1_ros::Rotate::Response &response) {
    ROS_INFO("Service Requested: rotate %d degrees", request.degrees);
    response.result = rotate(request.degrees);
    turn(0.0);
    ROS_INFO("Service Completed: %s", response.result.c_str());
    return true;
  }

  std::string rotate(int degrees) {
    double total = 0.0, rate = 0.0;
    const ros::WallTime asked = ros::WallTime::now();
    while (!reading(&total, &rate)) {
      if (!ros::ok() || (ros::WallTime::now() - asked).toSec() > kOdomTimeout) {
        return "failure: no odometry on odom; the robot did not move";
      }
      ros::WallDuration(1.0 / kRate).sleep();
    }
    const double target = total + degrees * M_PI / 180.0;
    const ros::Time began = ros::Time::now();
    const double allowed = kSlack * std::fabs(target - total) / kMaxSpeed + kMargin;
    ros::Rate loop(kRate);
    while (ros::ok()) {
      reading(&total, &rate);
      const double error = target - total;
      if (std::fabs(error) <= kTolerance) {
        turn(0.0);
        const ros::Time stopping = ros::Time::now();
        while (ros::ok() && std::fabs(rate) >= kStillSpeed &&
               (ros::Time::now() - stopping).toSec() < kSettleTime) {
          loop.sleep();
          reading(&total, &rate);
        }
        if (std::fabs(target - total) <= kTolerance) {
          return "success: rotated " + std::to_string(degrees) + " degrees";
        }
        continue;  // it drifted out while stopping: turn again
      }
      if ((ros::Time::now() - began).toSec() > allowed) {
        return "failure: timed out with " + std::to_string(error * 180.0 / M_PI) +
               " degrees to go";
      }
      const double speed = std::min(kMaxSpeed, std::max(kMinSpeed, kGain * std::fabs(error)));
      turn(std::copysign(speed, error));
      loop.sleep();
    }
    return "failure: the node is shutting down";
  }

  ros::Publisher command_;
  ros::Subscriber odometry_;
  ros::ServiceServer server_;
  std::mutex mutex_;
  double total_ = 0.0;
  double last_ = 0.0;
  double rate_ = 0.0;
  bool have_odometry_ = false;
};

int main(int argc, char **argv) {
  ros::init(argc, argv, "rotate_service");
  ros::NodeHandle nh;
  RotateService service(nh);
  ros::AsyncSpinner spinner(2);  // odometry keeps arriving while a request turns the robot
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
