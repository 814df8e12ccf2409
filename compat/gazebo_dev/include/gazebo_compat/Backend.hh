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

  // a <sensor> of a model, on one of Gazebo's links (after fixed-joint lumping)
  struct SensorInfo
  {
    std::string name;
    std::string type;  // contact, ray, gpu_ray, imu, ...
    std::string link;
    double updateRate = 0.0;
    bool alwaysOn = false;
    // ray sensors: the scan's angles (rad), samples and range (m)
    double angleMin = 0.0;
    double angleMax = 0.0;
    int samples = 0;
    double rangeMin = 0.0;
    double rangeMax = 0.0;
  };

  // what one pair of collisions touches: scoped collision names (model::link::collision),
  // and per contact point, flat [x y z ...] in world axes, the normal pointing at
  // collision1, the depth, and the force and torque on collision1
  struct ContactInfo
  {
    std::string collision1;
    std::string collision2;
    std::vector<double> positions;
    std::vector<double> normals;
    std::vector<double> depths;
    std::vector<double> forces;
    std::vector<double> torques;
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
    // the model's sensors (its robot's <sensor>s), and what each reads now (after the last
    // physics step)
    public: virtual std::vector<SensorInfo> Sensors(const std::string &_model) = 0;
    public: virtual std::vector<ContactInfo> SensorContacts(const std::string &_model,
                                                            const std::string &_sensor) = 0;
    // metres; +inf where a ray hits nothing within range
    public: virtual std::vector<double> SensorRanges(const std::string &_model,
                                                     const std::string &_sensor) = 0;
    // [wx wy wz ax ay az qx qy qz qw]: the rate and specific force in the sensor's axes,
    // its orientation in the world
    public: virtual std::vector<double> SensorImu(const std::string &_model,
                                                  const std::string &_sensor) = 0;
  };
}
#endif
