// gazebo::physics::Base: a named thing of the world, scoped as model::link.
#ifndef GAZEBO_COMPAT_PHYSICS_BASE_HH
#define GAZEBO_COMPAT_PHYSICS_BASE_HH
#include <string>
#include <boost/enable_shared_from_this.hpp>
#include <boost/weak_ptr.hpp>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE Base : public boost::enable_shared_from_this<Base>
    {
      // Gazebo's type bits: an entity's type is its own bit or-ed with its bases'
      public: enum EntityType
              {
                BASE = 0x00000000,
                ENTITY = 0x00000001,
                MODEL = 0x00000002,
                LINK = 0x00000004,
                COLLISION = 0x00000008,
                LIGHT = 0x00000010,
                VISUAL = 0x00000020,
                JOINT = 0x00000040,
                BALL_JOINT = 0x00000080,
                HINGE2_JOINT = 0x00000100,
                HINGE_JOINT = 0x00000200,
                SLIDER_JOINT = 0x00000400,
                SCREW_JOINT = 0x00000800,
                UNIVERSAL_JOINT = 0x00001000,
                GEARBOX_JOINT = 0x00002000,
                FIXED_JOINT = 0x00004000,
                ACTOR = 0x00008000,
                SHAPE = 0x00010000
              };

      public: explicit Base(BasePtr _parent);
      public: virtual ~Base();
      public: virtual void Reset();
      public: virtual void SetName(const std::string &_name);
      public: std::string GetName() const;
      public: uint32_t GetId() const;
      public: BasePtr GetParent() const;
      public: void AddType(EntityType _type);
      public: bool HasType(const EntityType &_t) const;
      public: unsigned int GetType() const;
      public: std::string TypeStr() const;
      // ancestors' names joined by "::", the world's first when asked
      public: std::string GetScopedName(bool _prependWorldName = false) const;
      public: const WorldPtr &GetWorld() const;
      public: void SetWorld(const WorldPtr &_newWorld);

      protected: std::string name;
      protected: boost::weak_ptr<Base> parent;
      protected: WorldPtr world;
      private: unsigned int type = BASE;
      private: uint32_t id;
    };
  }
}
#endif
