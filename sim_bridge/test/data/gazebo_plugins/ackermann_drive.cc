// A car-like drive plugin in the style of AgileX LIMO's and Hunter's Gazebo plugins: the two
// front steering hinges held at their Ackermann angles by common::PID efforts (SetForce every
// WorldUpdateBegin), the rear wheels by velocity motors (SetParam("fmax") once, "vel" each
// step). The command is a fixed <linear> (m/s) and <curvature> (1/m) from the SDF; no ROS.
#include <cmath>
#include <string>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>

namespace gazebo
{
  class AckermannDrive : public ModelPlugin
  {
    public: void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
    {
      this->world = _model->GetWorld();
      this->leftSteer = this->Joint(_model, _sdf, "leftSteerJoint");
      this->rightSteer = this->Joint(_model, _sdf, "rightSteerJoint");
      this->leftRear = this->Joint(_model, _sdf, "leftRearJoint");
      this->rightRear = this->Joint(_model, _sdf, "rightRearJoint");
      this->wheelbase = _sdf->Get<double>("wheelbase");
      this->track = _sdf->Get<double>("track");
      this->radius = _sdf->Get<double>("wheelDiameter") / 2.0;
      this->linear = _sdf->Get<double>("linear");
      this->curvature = _sdf->Get<double>("curvature");
      const double torque = _sdf->Get<double>("torque");
      const double steerTorque = _sdf->Get<double>("steerTorque");
      // the LIMO's steering gains shape: stiff proportional, some damping, no integral
      for (auto *pid : {&this->leftPid, &this->rightPid})
        pid->Init(_sdf->Get<double>("steerP"), 0.0, _sdf->Get<double>("steerD"), 0.0, 0.0,
                  steerTorque, -steerTorque);
      this->leftRear->SetParam("fmax", 0, torque);
      this->rightRear->SetParam("fmax", 0, torque);
      this->lastTime = this->world->SimTime();
      this->connection = event::Events::ConnectWorldUpdateBegin(
          std::bind(&AckermannDrive::OnUpdate, this));
      gzmsg << "AckermannDrive: " << _model->GetName() << " at " << this->linear
            << " m/s, curvature " << this->curvature << " 1/m\n";
    }

    private: physics::JointPtr Joint(physics::ModelPtr _model, sdf::ElementPtr _sdf,
                                     const std::string &_tag)
    {
      const std::string name = _sdf->Get<std::string>(_tag);
      physics::JointPtr joint = _model->GetJoint(name);
      if (!joint)
        gzthrow("AckermannDrive: no joint named " << name << " in " << _model->GetName());
      return joint;
    }

    private: void OnUpdate()
    {
      const common::Time now = this->world->SimTime();
      const common::Time dt = now - this->lastTime;
      this->lastTime = now;
      // each front wheel points along its own circle about the centre on the rear axle
      double left = 0.0, right = 0.0, leftSpeed = this->linear, rightSpeed = this->linear;
      if (this->curvature != 0.0)
      {
        const double turnRadius = 1.0 / this->curvature;
        left = std::atan(this->wheelbase / (turnRadius - this->track / 2.0));
        right = std::atan(this->wheelbase / (turnRadius + this->track / 2.0));
        leftSpeed = this->linear * (1.0 - this->curvature * this->track / 2.0);
        rightSpeed = this->linear * (1.0 + this->curvature * this->track / 2.0);
      }
      if (dt > common::Time::Zero)
      {
        this->leftSteer->SetForce(0, this->leftPid.Update(
            this->leftSteer->Position(0) - left, dt));
        this->rightSteer->SetForce(0, this->rightPid.Update(
            this->rightSteer->Position(0) - right, dt));
      }
      this->leftRear->SetParam("vel", 0, leftSpeed / this->radius);
      this->rightRear->SetParam("vel", 0, rightSpeed / this->radius);
    }

    private: physics::WorldPtr world;
    private: physics::JointPtr leftSteer, rightSteer, leftRear, rightRear;
    private: common::PID leftPid, rightPid;
    private: common::Time lastTime;
    private: double wheelbase = 0.0, track = 0.0, radius = 0.0;
    private: double linear = 0.0, curvature = 0.0;
    private: event::ConnectionPtr connection;
  };

  GZ_REGISTER_MODEL_PLUGIN(AckermannDrive)
}
