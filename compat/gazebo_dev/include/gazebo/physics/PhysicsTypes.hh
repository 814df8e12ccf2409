// gazebo::physics' pointer types (boost::shared_ptr, as Gazebo 11's).
#ifndef GAZEBO_COMPAT_PHYSICS_PHYSICSTYPES_HH
#define GAZEBO_COMPAT_PHYSICS_PHYSICSTYPES_HH
#include <map>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>

namespace gazebo
{
  namespace physics
  {
    class Base;
    class Entity;
    class World;
    class Model;
    class Link;
    class Collision;
    class Joint;
    class JointController;
    class PhysicsEngine;
    class Contact;
    typedef boost::shared_ptr<Base> BasePtr;
    typedef boost::shared_ptr<Entity> EntityPtr;
    typedef boost::shared_ptr<World> WorldPtr;
    typedef boost::shared_ptr<Model> ModelPtr;
    typedef boost::shared_ptr<Link> LinkPtr;
    typedef boost::shared_ptr<Collision> CollisionPtr;
    typedef boost::shared_ptr<Joint> JointPtr;
    typedef boost::shared_ptr<JointController> JointControllerPtr;
    typedef boost::shared_ptr<PhysicsEngine> PhysicsEnginePtr;
    typedef boost::shared_ptr<Contact> ContactPtr;
    typedef std::vector<BasePtr> Base_V;
    typedef std::vector<ModelPtr> Model_V;
    typedef std::vector<LinkPtr> Link_V;
    typedef std::vector<JointPtr> Joint_V;
    typedef std::vector<CollisionPtr> Collision_V;
  }
}
#endif
