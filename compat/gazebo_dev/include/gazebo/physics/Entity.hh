// gazebo::physics::Entity: what has a pose and a velocity (models and links). Values are
// read from sim_bridge's world when asked; writes act on the next physics step.
#ifndef GAZEBO_COMPAT_PHYSICS_ENTITY_HH
#define GAZEBO_COMPAT_PHYSICS_ENTITY_HH
#include <vector>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/Base.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE Entity : public Base
    {
      public: explicit Entity(BasePtr _parent);
      public: virtual ~Entity();
      public: virtual const ignition::math::Pose3d &WorldPose() const;
      public: ignition::math::Pose3d RelativePose() const;
      public: void SetWorldPose(const ignition::math::Pose3d &_pose, const bool _notify = true,
                                const bool _publish = true);
      public: void SetRelativePose(const ignition::math::Pose3d &_pose,
                                   const bool _notify = true, const bool _publish = true);
      // the velocity of the entity frame's origin, world axes
      public: virtual ignition::math::Vector3d WorldLinearVel() const;
      public: virtual ignition::math::Vector3d WorldAngularVel() const;
      // the same in the entity's own axes
      public: virtual ignition::math::Vector3d RelativeLinearVel() const;
      public: virtual ignition::math::Vector3d RelativeAngularVel() const;
      public: ModelPtr GetParentModel();

      // [x y z qx qy qz qw vx vy vz wx wy wz] from the world
      protected: virtual std::vector<double> State() const = 0;
      protected: virtual void SetPose(const ignition::math::Pose3d &_pose) = 0;
      protected: mutable ignition::math::Pose3d worldPose;
    };
  }
}
#endif
