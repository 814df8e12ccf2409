// What sim_bridge provides of gazebo::physics.
#ifndef GAZEBO_COMPAT_PHYSICS_PHYSICS_HH
#define GAZEBO_COMPAT_PHYSICS_PHYSICS_HH
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/physics/Base.hh"
#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/JointController.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PhysicsEngine.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/World.hh"
#endif
