// gazebo::physics::get_world and has_world over sim_bridge's one world (gazebo-classic,
// Debian's gazebo 11.10.2 source, gazebo/physics/PhysicsIface.cc:58-97).
#ifndef GAZEBO_COMPAT_PHYSICS_PHYSICSIFACE_HH
#define GAZEBO_COMPAT_PHYSICS_PHYSICSIFACE_HH
#include <string>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace physics
  {
    // the world of that name ("": the first); gzerr and gzthrow when there is none
    GZ_PHYSICS_VISIBLE WorldPtr get_world(const std::string &_name = "");
    GZ_PHYSICS_VISIBLE bool has_world(const std::string &_name = "");
  }
}
#endif
