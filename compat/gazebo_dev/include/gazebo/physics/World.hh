// gazebo::physics::World: sim_bridge's world (one per process), its simulated time and its
// models. Inserting models from a plugin (InsertModelFile/String/SDF) is not provided.
#ifndef GAZEBO_COMPAT_PHYSICS_WORLD_HH
#define GAZEBO_COMPAT_PHYSICS_WORLD_HH
#include <string>
#include <boost/enable_shared_from_this.hpp>
#include <boost/weak_ptr.hpp>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE World : public boost::enable_shared_from_this<World>
    {
      public: World();
      public: virtual ~World();
      public: std::string Name() const;
      public: PhysicsEnginePtr Physics() const;
      // the time of the step being simulated: WorldUpdateBegin sees it one step on
      public: common::Time SimTime() const;
      public: common::Time RealTime() const;
      public: uint32_t Iterations() const;
      public: bool IsPaused() const;
      public: unsigned int ModelCount() const;
      public: ModelPtr ModelByIndex(unsigned int _index) const;
      public: Model_V Models() const;
      public: ModelPtr ModelByName(const std::string &_name) const;
      public: void InsertModelFile(const std::string &_sdfFilename);
      public: void InsertModelString(const std::string &_sdfString);

      private: mutable PhysicsEnginePtr physics;
    };
  }
}
#endif
