// A drive plugin in the style of gazebo_ros_diff_drive's joint handling: wheel motors by
// SetParam("fmax") once in Load and SetParam("vel") every WorldUpdateBegin, the speeds from
// a fixed <linear> (m/s) and <angular> (rad/s) command (no ROS: the ROS-driven variant is
// the next landing's).
#include <string>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>

namespace gazebo
{
  class WheelDrive : public ModelPlugin
  {
    public: void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
    {
      this->left = _model->GetJoint(_sdf->Get<std::string>("leftJoint"));
      this->right = _model->GetJoint(_sdf->Get<std::string>("rightJoint"));
      if (!this->left || !this->right)
        gzthrow("WheelDrive: a wheel joint is missing in " << _model->GetName());
      this->radius = _sdf->Get<double>("wheelDiameter") / 2.0;
      this->separation = _sdf->Get<double>("wheelSeparation");
      this->linear = _sdf->Get<double>("linear");
      this->angular = _sdf->Get<double>("angular");
      const double torque = _sdf->Get<double>("torque");
      this->left->SetParam("fmax", 0, torque);
      this->right->SetParam("fmax", 0, torque);
      this->connection = event::Events::ConnectWorldUpdateBegin(
          std::bind(&WheelDrive::OnUpdate, this, std::placeholders::_1));
    }

    private: void OnUpdate(const common::UpdateInfo &)
    {
      const double half = this->angular * this->separation / 2.0;
      this->left->SetParam("vel", 0, (this->linear - half) / this->radius);
      this->right->SetParam("vel", 0, (this->linear + half) / this->radius);
    }

    private: physics::JointPtr left, right;
    private: double radius = 0.0, separation = 0.0, linear = 0.0, angular = 0.0;
    private: event::ConnectionPtr connection;
  };

  GZ_REGISTER_MODEL_PLUGIN(WheelDrive)
}
