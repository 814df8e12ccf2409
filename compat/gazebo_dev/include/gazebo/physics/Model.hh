// gazebo::physics::Model: a model of sim_bridge's world (a robot from URDF, a body from
// SDF), its links and joints as Gazebo shows them. SetLinearVel/SetAngularVel set the
// model's base (its canonical link; a robot's other links follow through their joints).
#ifndef GAZEBO_COMPAT_PHYSICS_MODEL_HH
#define GAZEBO_COMPAT_PHYSICS_MODEL_HH
#include <string>
#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/JointController.hh"
#include "gazebo/physics/Link.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE Model : public Entity
    {
      public: explicit Model(BasePtr _parent);
      public: virtual ~Model();
      public: void SetLinearVel(const ignition::math::Vector3d &_vel);
      public: void SetAngularVel(const ignition::math::Vector3d &_vel);
      public: unsigned int GetJointCount() const;
      public: const Joint_V &GetJoints() const;
      // by scoped (model::joint) or plain name; null if there is none
      public: JointPtr GetJoint(const std::string &_name);
      public: const Link_V &GetLinks() const;
      // by scoped or plain name, "canonical" for the canonical link; null if there is none
      public: LinkPtr GetLink(const std::string &_name = "canonical") const;
      public: LinkPtr GetChildLink(const std::string &_name) const;
      public: void SetGravityMode(const bool &_value);
      public: JointControllerPtr GetJointController();
      public: virtual void Reset() override;

      // for sim_bridge's host: the links and joints, and the step's controller update
      public: void Build(const Link_V &_links, const Joint_V &_joints);
      public: void UpdateControllers();
      public: void ClearForces();

      protected: virtual std::vector<double> State() const override;
      protected: virtual void SetPose(const ignition::math::Pose3d &_pose) override;
      private: Link_V links;
      private: Joint_V joints;
      private: JointControllerPtr jointController;
    };
  }
}
#endif
