// gazebo::physics::Link: one of Gazebo's links of a model (after sdformat's lumping of
// fixed joints). Forces and torques act on the next physics step only (Gazebo clears them
// after each step); a force is applied at the link's centre of mass.
#ifndef GAZEBO_COMPAT_PHYSICS_LINK_HH
#define GAZEBO_COMPAT_PHYSICS_LINK_HH
#include "gazebo/physics/Entity.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE Link : public Entity
    {
      public: explicit Link(EntityPtr _parent);
      public: virtual ~Link();
      public: ModelPtr GetModel() const;
      public: virtual void SetLinearVel(const ignition::math::Vector3d &_vel);
      public: virtual void SetAngularVel(const ignition::math::Vector3d &_vel);
      public: virtual void AddForce(const ignition::math::Vector3d &_force);
      public: virtual void AddRelativeForce(const ignition::math::Vector3d &_force);
      public: virtual void AddTorque(const ignition::math::Vector3d &_torque);
      public: virtual void AddRelativeTorque(const ignition::math::Vector3d &_torque);
      public: Joint_V GetParentJoints() const;
      public: Joint_V GetChildJoints() const;

      protected: virtual std::vector<double> State() const override;
      protected: virtual void SetPose(const ignition::math::Pose3d &_pose) override;
      private: void Wrench(const ignition::math::Vector3d &_force,
                           const ignition::math::Vector3d &_torque, bool _inLinkFrame);
      private: void Velocity(const ignition::math::Vector3d *_linear,
                             const ignition::math::Vector3d *_angular);
    };
  }
}
#endif
