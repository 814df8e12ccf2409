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
// Its sensors, found in Load by their plain names as Kobuki's finds them: a contact sensor
// (<bumper_name>) whose contacts, by their direction from the base, press the left, centre
// or right bumper; an IMU (<imu_name>) whose yaw and rate are the odometry's heading and
// turn rate; a downward ray (<cliff_sensor_name>), the floor's distance under the front. The
// bumpers (Kobuki's SensorState bits: right 1, centre 2, left 4) and the cliff range are
// published with the odometry on <base_prefix>/sensors/bumper and .../cliff_range.
#include <cmath>
#include <mutex>
#include <string>

#include <gazebo/common/common.hh>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/sensors/sensors.hh>
#include <gazebo_plugins/gazebo_ros_utils.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_msgs/UInt8.h>

namespace gazebo
{
// kobuki_msgs/SensorState's bumper bits
const uint8_t BUMPER_RIGHT = 1;
const uint8_t BUMPER_CENTRE = 2;
const uint8_t BUMPER_LEFT = 4;
// a contact this far (rad) either side of straight ahead presses the centre bumper, up to a
// right angle the side's
const double CENTRE_HALF_WIDTH = M_PI / 6;

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
    if (!this->FindSensors())
      return;
    this->odomFrame = this->ros->resolveTF("odom");
    this->baseFrame = this->ros->resolveTF("base_footprint");

    this->odomPublisher = this->ros->node()->advertise<nav_msgs::Odometry>("odom", 1);
    this->bumperPublisher =
        this->ros->node()->advertise<std_msgs::UInt8>(prefix + "/sensors/bumper", 1);
    this->cliffPublisher =
        this->ros->node()->advertise<std_msgs::Float64>(prefix + "/sensors/cliff_range", 1);
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
    this->x = this->y = 0.0;
    this->yaw = this->imu->Orientation().Yaw();
    this->lastLeft = this->left->Position(0);
    this->lastRight = this->right->Position(0);
    this->lastUpdate = this->model->GetWorld()->SimTime();
    if (this->bySetParam)  // a joint's reset turns its motor off, as ODE's
    {
      this->left->SetParam("fmax", 0, this->torque);
      this->right->SetParam("fmax", 0, this->torque);
    }
  }

  // the sensors the URDF names, on the base's link (all lumped into base_footprint), by
  // their scoped names as Kobuki finds its gyro (an unscoped name is ambiguous once two
  // robots share the world, in Gazebo as here); the plugin does not run without them
  private: bool FindSensors()
  {
    std::string bumper, imu, cliff;
    this->ros->getParameter<std::string>(bumper, "bumper_name", "bumpers");
    this->ros->getParameter<std::string>(imu, "imu_name", "imu");
    this->ros->getParameter<std::string>(cliff, "cliff_sensor_name", "cliff_sensor_front");
    const std::string link = this->model->GetWorld()->Name() + "::" + this->model->GetName() +
                             "::base_footprint::";
    this->bumper = std::dynamic_pointer_cast<sensors::ContactSensor>(
        sensors::SensorManager::Instance()->GetSensor(link + bumper));
    this->imu = std::dynamic_pointer_cast<sensors::ImuSensor>(sensors::get_sensor(link + imu));
    this->cliff = std::dynamic_pointer_cast<sensors::RaySensor>(
        sensors::SensorManager::Instance()->GetSensor(link + cliff));
    if (!this->bumper || !this->imu || !this->cliff)
    {
      ROS_ERROR_STREAM(this->ros->info() << ": a sensor is missing (bumper " << bumper
                       << (this->bumper ? "" : " not found") << ", imu " << imu
                       << (this->imu ? "" : " not found") << ", cliff " << cliff
                       << (this->cliff ? "" : " not found") << "); the plugin does not run");
      return false;
    }
    this->bumper->SetActive(true);
    this->imu->SetActive(true);
    this->cliff->SetActive(true);
    return true;
  }

  // the bumpers pressed: the contacts on the base, by their direction in the base's frame
  private: uint8_t Bumpers()
  {
    const msgs::Contacts contacts = this->bumper->Contacts();
    const double yaw = this->model->WorldPose().Rot().Yaw();
    uint8_t pressed = 0;
    for (int i = 0; i < contacts.contact_size(); ++i)
    {
      const msgs::Contact &contact = contacts.contact(i);
      // the normal points at collision1, the base: the obstacle is the other way
      if (contact.collision1().find(this->bumper->ParentName()) != 0 ||
          contact.normal_size() == 0)
        continue;
      const double towards = std::atan2(-contact.normal(0).y(), -contact.normal(0).x());
      const double relative = std::remainder(towards - yaw, 2 * M_PI);
      if (std::fabs(relative) <= CENTRE_HALF_WIDTH)
        pressed |= BUMPER_CENTRE;
      else if (relative > 0 && relative <= M_PI / 2)
        pressed |= BUMPER_LEFT;
      else if (relative < 0 && relative >= -M_PI / 2)
        pressed |= BUMPER_RIGHT;
    }
    return pressed;
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
    // the heading from the gyro (relative to the base's at load), as Kobuki's
    const double heading = this->imu->Orientation().Yaw();
    const double turn = std::remainder(heading - this->yaw, 2 * M_PI);
    this->x += run * std::cos(this->yaw + turn / 2.0);
    this->y += run * std::sin(this->yaw + turn / 2.0);
    this->yaw = heading;

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
    }
    odometry.twist.twist.angular.z = this->imu->AngularVelocity().Z();
    this->odomPublisher.publish(odometry);

    std_msgs::UInt8 bumpers;
    bumpers.data = this->Bumpers();
    this->bumperPublisher.publish(bumpers);
    std_msgs::Float64 cliffRange;
    cliffRange.data = this->cliff->Range(0);
    this->cliffPublisher.publish(cliffRange);
  }

  private: physics::ModelPtr model;
  private: GazeboRosPtr ros;
  private: physics::JointPtr left, right;
  private: double separation = 0.0, radius = 0.0, torque = 0.0, timeout = 0.0, period = 0.0;
  private: bool bySetParam = true;
  private: std::string odomFrame, baseFrame;
  private: ros::Publisher odomPublisher, bumperPublisher, cliffPublisher;
  private: sensors::ContactSensorPtr bumper;
  private: sensors::ImuSensorPtr imu;
  private: sensors::RaySensorPtr cliff;
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
