// gazebo::physics::PhysicsEngine: the world's step size. The engine is pybullet; GetType
// answers "ode", the engine whose behaviour sim_bridge stands in for.
#ifndef GAZEBO_COMPAT_PHYSICS_PHYSICSENGINE_HH
#define GAZEBO_COMPAT_PHYSICS_PHYSICSENGINE_HH
#include <string>
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE PhysicsEngine
    {
      public: explicit PhysicsEngine(WorldPtr _world);
      public: virtual ~PhysicsEngine();
      public: double GetMaxStepSize() const;
      public: virtual std::string GetType() const;
      public: WorldPtr World() const;
      private: boost::weak_ptr<physics::World> world;
    };
  }
}
#endif
