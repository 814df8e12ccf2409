// gazebo::physics::Joint: a model's joint, read from and acting on sim_bridge's world.
//   SetParam("fmax"/"vel", 0, double): a motor as ODE's (persistent; drives the joint's rate
//     to vel with at most fmax; fmax 0 is off), "friction" (fmax = value, vel = 0); another
//     key, a value that is not a double (an int literal) or an index other than 0 is a gzerr
//     and false, as in Gazebo.
//   SetVelocity(0, v): the joint's rate set for the next step (no motor; call it each step).
//   SetForce(0, f): an effort for the next step, added to what was set in this step,
//     truncated by the effort limit when there is one.
// Joints have one axis here: index 0.
#ifndef GAZEBO_COMPAT_PHYSICS_JOINT_HH
#define GAZEBO_COMPAT_PHYSICS_JOINT_HH
#include <string>
#include <boost/any.hpp>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/Base.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE Joint : public Base
    {
      public: Joint(BasePtr _parent, const std::string &_type);
      public: virtual ~Joint();
      public: LinkPtr GetChild() const;
      public: LinkPtr GetParent() const;
      public: ModelPtr GetModel() const;
      public: virtual unsigned int DOF() const;
      public: virtual double Position(const unsigned int _index = 0) const final;
      public: virtual double GetVelocity(unsigned int _index) const;
      public: virtual void SetVelocity(unsigned int _index, double _vel);
      public: virtual void SetForce(unsigned int _index, double _effort);
      public: virtual double GetForce(unsigned int _index);
      public: virtual bool SetParam(const std::string &_key, unsigned int _index,
                                    const boost::any &_value);
      public: virtual double GetParam(const std::string &_key, unsigned int _index);
      public: virtual double LowerLimit(unsigned int _index = 0) const;
      public: virtual double UpperLimit(const unsigned int _index = 0) const;
      public: virtual double GetEffortLimit(unsigned int _index);
      public: virtual double GetVelocityLimit(unsigned int _index);
      public: virtual void Reset() override;

      // for sim_bridge's host: how the joint is connected, and the end of a step
      public: void Attach(LinkPtr _parent, LinkPtr _child, double _lower, double _upper,
                          double _effort, double _velocity);
      public: void ClearForce();

      private: bool CheckIndex(unsigned int _index, const char *_what) const;
      private: LinkPtr parentLink;
      private: LinkPtr childLink;
      private: double lower = 0.0;
      private: double upper = 0.0;
      private: double effortLimit = -1.0;
      private: double velocityLimit = -1.0;
      private: double fmax = 0.0;
      private: double vel = 0.0;
      private: double force = 0.0;
    };
  }
}
#endif
