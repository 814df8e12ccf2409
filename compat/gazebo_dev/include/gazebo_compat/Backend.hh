// The world behind sim_bridge's Gazebo plugin API.
//
// Plugins see gazebo::physics classes; those classes ask this interface, which the
// simulator implements (sim_bridge's pybind11 module `sim_bridge._gazebo_host`, over its
// pybullet world). Entities are named as Gazebo names them: a model's name, a link's or
// joint's plain name within it. States are [x y z qx qy qz qw vx vy vz wx wy wz]: the
// frame's pose in the world and the velocity of its origin, world axes. Writes act on the
// next physics step. Every call may come from any thread (ROS callbacks call it too): the
// implementation serialises them.
#ifndef GAZEBO_COMPAT_BACKEND_HH
#define GAZEBO_COMPAT_BACKEND_HH
#include <string>
#include <vector>

namespace gazebo_compat
{
  struct JointInfo
  {
    std::string name;
    std::string type;  // revolute, continuous, prismatic, fixed, ...
    std::string parent;  // Gazebo's links; "" for the world
    std::string child;
    double lower = 0.0;
    double upper = 0.0;
    double effort = -1.0;  // < 0: no limit
    double velocity = -1.0;
  };

  struct ModelInfo
  {
    std::vector<std::string> links;  // the canonical link first
    std::vector<JointInfo> joints;
  };

  class Backend
  {
    public: virtual ~Backend() = default;
    public: virtual std::string WorldName() = 0;
    public: virtual double StepSize() = 0;
    public: virtual std::vector<std::string> ModelNames() = 0;
    public: virtual ModelInfo Describe(const std::string &_model) = 0;
    public: virtual std::vector<double> ModelState(const std::string &_model) = 0;
    public: virtual std::vector<double> LinkState(const std::string &_model,
                                                  const std::string &_link) = 0;
    public: virtual void SetModelPose(const std::string &_model,
                                      const std::vector<double> &_pose) = 0;
    // [vx vy vz wx wy wz] of the model's base; NaN keeps that component as it is
    public: virtual void SetModelVelocity(const std::string &_model,
                                          const std::vector<double> &_twist) = 0;
    public: virtual void SetLinkVelocity(const std::string &_model, const std::string &_link,
                                         const std::vector<double> &_twist) = 0;
    // [fx fy fz tx ty tz] at the link's centre of mass, world axes or the link's
    public: virtual void AddLinkWrench(const std::string &_model, const std::string &_link,
                                       const std::vector<double> &_wrench,
                                       bool _inLinkFrame) = 0;
    public: virtual void SetGravityMode(const std::string &_model, bool _on) = 0;
    // [position, velocity]
    public: virtual std::vector<double> JointState(const std::string &_model,
                                                   const std::string &_joint) = 0;
    public: virtual void SetJointVelocity(const std::string &_model, const std::string &_joint,
                                          double _velocity) = 0;
    public: virtual void SetJointMotor(const std::string &_model, const std::string &_joint,
                                       double _velocity, double _maxForce) = 0;
    // the joint's whole effort for the next step (replaces what was set in this step)
    public: virtual void SetJointForce(const std::string &_model, const std::string &_joint,
                                       double _force) = 0;
  };
}
#endif
