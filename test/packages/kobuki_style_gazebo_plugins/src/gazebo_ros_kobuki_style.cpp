// A Kobuki-style drive plugin, as robot packages write their own (in the manner of
// kobuki_gazebo_plugins; written here, not copied): a ModelPlugin that takes velocity
// commands on <base_prefix>/commands/velocity and publishes encoder odometry on odom, both
// through GazeboRos's NodeHandle in the robot's namespace, stamped with ros::Time::now()
// (simulated time under use_sim_time). The wheels are driven one of two ways, by
// <wheel_command>:
//   set_param     ODE's joint motor: SetParam("fmax") once in Load, SetParam("vel") each
//                 WorldUpdateBegin (gazebo_ros_diff_drive's way);
//   set_velocity  Joint::SetVelocity each WorldUpdateEnd, for the step to come (Kobuki's way
//                 since Gazebo 7).
// A command older than <velocity_command_timeout> (s of simulated time) stops the wheels.
#include <cmath>
#include <mutex>
#include <string>

#include <gazebo/common/common.hh>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo_plugins/gazebo_ros_utils.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

namespace gazebo
{
class GazeboRosKobukiStyle : public ModelPlugin
{
  public: void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override
  {
    if (!ros::isInitialized())
    {
      ROS_FATAL_STREAM("A ROS node for Gazebo has not been initialized, unable to load "
                       "plugin. Load the Gazebo system plugin 'libgazebo_ros_api_plugin.so' "
                       "in the gazebo_ros package)");
      return;
    }
    this->model = _model;
    this->ros.reset(new GazeboRos(_model, _sdf, "KobukiStyle"));
    this->ros->isInitialized();

    this->left = this->ros->getJoint(_model, "left_wheel_joint_name", "wheel_left_joint");
    this->right = this->ros->getJoint(_model, "right_wheel_joint_name", "wheel_right_joint");
    // the defaults are a Kobuki's: its wheels, its motors' torque, its command timeout
    this->ros->getParameter<double>(this->separation, "wheel_separation", 0.230);
    double diameter = 0.0;
    this->ros->getParameter<double>(diameter, "wheel_diameter", 0.070);
    this->radius = diameter / 2.0;
    this->ros->getParameter<double>(this->torque, "torque", 1.0);
    this->ros->getParameter<double>(this->timeout, "velocity_command_timeout", 0.6);
    double rate = 0.0;
    this->ros->getParameter<double>(rate, "update_rate", 50.0);
    this->period = rate > 0.0 ? 1.0 / rate : 0.0;
    std::string prefix;
    this->ros->getParameter<std::string>(prefix, "base_prefix", "mobile_base");
    std::string command;
    this->ros->getParameter<std::string>(command, "wheel_command", "set_param");
    this->bySetParam = command != "set_velocity";
    this->odomFrame = this->ros->resolveTF("odom");
    this->baseFrame = this->ros->resolveTF("base_footprint");

    this->odomPublisher = this->ros->node()->advertise<nav_msgs::Odometry>("odom", 1);
    this->commandSubscriber = this->ros->node()->subscribe(
        prefix + "/commands/velocity", 10, &GazeboRosKobukiStyle::OnCommand, this);
    ROS_INFO_STREAM(this->ros->info() << ": wheels by "
                    << (this->bySetParam ? "SetParam(\"vel\")" : "SetVelocity")
                    << ", commands on " << this->commandSubscriber.getTopic()
                    << ", odometry on " << this->odomPublisher.getTopic());

    if (this->bySetParam)
    {
      this->left->SetParam("fmax", 0, this->torque);
      this->right->SetParam("fmax", 0, this->torque);
    }
    this->lastLeft = this->left->Position(0);
    this->lastRight = this->right->Position(0);
    this->lastUpdate = _model->GetWorld()->SimTime();
    this->beginConnection = event::Events::ConnectWorldUpdateBegin(
        boost::bind(&GazeboRosKobukiStyle::OnUpdateBegin, this));
    this->endConnection = event::Events::ConnectWorldUpdateEnd(
        boost::bind(&GazeboRosKobukiStyle::OnUpdateEnd, this));
  }

  public: void Reset() override
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    this->linear = this->angular = 0.0;
    this->x = this->y = this->yaw = 0.0;
    this->lastLeft = this->left->Position(0);
    this->lastRight = this->right->Position(0);
    this->lastUpdate = this->model->GetWorld()->SimTime();
    if (this->bySetParam)  // a joint's reset turns its motor off, as ODE's
    {
      this->left->SetParam("fmax", 0, this->torque);
      this->right->SetParam("fmax", 0, this->torque);
    }
  }

  // ROS's thread (the simulator's spinner)
  private: void OnCommand(const geometry_msgs::Twist::ConstPtr &_twist)
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    this->linear = _twist->linear.x;
    this->angular = _twist->angular.z;
    this->commandTime = this->model->GetWorld()->SimTime();
    this->commanded = true;
  }

  // wheel speeds (rad/s) of the latest command, zero once it is too old
  private: void WheelSpeeds(double &_left, double &_right)
  {
    std::lock_guard<std::mutex> lock(this->mutex);
    const common::Time now = this->model->GetWorld()->SimTime();
    if (!this->commanded || (now - this->commandTime).Double() > this->timeout)
    {
      _left = _right = 0.0;
      return;
    }
    const double half = this->angular * this->separation / 2.0;
    _left = (this->linear - half) / this->radius;
    _right = (this->linear + half) / this->radius;
  }

  private: void OnUpdateBegin()
  {
    if (!this->bySetParam)
      return;
    double leftSpeed, rightSpeed;
    this->WheelSpeeds(leftSpeed, rightSpeed);
    this->left->SetParam("vel", 0, leftSpeed);
    this->right->SetParam("vel", 0, rightSpeed);
  }

  private: void OnUpdateEnd()
  {
    if (!this->bySetParam)
    {
      double leftSpeed, rightSpeed;
      this->WheelSpeeds(leftSpeed, rightSpeed);
      this->left->SetVelocity(0, leftSpeed);
      this->right->SetVelocity(0, rightSpeed);
    }
    const common::Time now = this->model->GetWorld()->SimTime();
    const double elapsed = (now - this->lastUpdate).Double();
    if (elapsed < this->period)
      return;
    this->lastUpdate = now;
    this->PublishOdometry(elapsed);
  }

  // dead reckoning from the wheels' turn since the last update
  private: void PublishOdometry(double _elapsed)
  {
    const double leftNow = this->left->Position(0);
    const double rightNow = this->right->Position(0);
    const double leftRun = (leftNow - this->lastLeft) * this->radius;
    const double rightRun = (rightNow - this->lastRight) * this->radius;
    this->lastLeft = leftNow;
    this->lastRight = rightNow;
    const double run = (leftRun + rightRun) / 2.0;
    const double turn = (rightRun - leftRun) / this->separation;
    this->x += run * std::cos(this->yaw + turn / 2.0);
    this->y += run * std::sin(this->yaw + turn / 2.0);
    this->yaw += turn;

    nav_msgs::Odometry odometry;
    odometry.header.stamp = ros::Time::now();
    odometry.header.frame_id = this->odomFrame;
    odometry.child_frame_id = this->baseFrame;
    odometry.pose.pose.position.x = this->x;
    odometry.pose.pose.position.y = this->y;
    odometry.pose.pose.orientation.z = std::sin(this->yaw / 2.0);
    odometry.pose.pose.orientation.w = std::cos(this->yaw / 2.0);
    if (_elapsed > 0.0)
    {
      odometry.twist.twist.linear.x = run / _elapsed;
      odometry.twist.twist.angular.z = turn / _elapsed;
    }
    this->odomPublisher.publish(odometry);
  }

  private: physics::ModelPtr model;
  private: GazeboRosPtr ros;
  private: physics::JointPtr left, right;
  private: double separation = 0.0, radius = 0.0, torque = 0.0, timeout = 0.0, period = 0.0;
  private: bool bySetParam = true;
  private: std::string odomFrame, baseFrame;
  private: ros::Publisher odomPublisher;
  private: ros::Subscriber commandSubscriber;
  private: event::ConnectionPtr beginConnection, endConnection;
  private: std::mutex mutex;
  private: double linear = 0.0, angular = 0.0;
  private: bool commanded = false;
  private: common::Time commandTime, lastUpdate;
  private: double lastLeft = 0.0, lastRight = 0.0, x = 0.0, y = 0.0, yaw = 0.0;
};

GZ_REGISTER_MODEL_PLUGIN(GazeboRosKobukiStyle);
}  // namespace gazebo
