// gazebo::physics::JointController: PIDs on joints, keyed by scoped joint names. Each step,
// after WorldUpdateBegin and before the physics (as Gazebo's Model::Update), forces set are
// applied, then the position PIDs and the velocity PIDs act through Joint::SetForce.
#ifndef GAZEBO_COMPAT_PHYSICS_JOINTCONTROLLER_HH
#define GAZEBO_COMPAT_PHYSICS_JOINTCONTROLLER_HH
#include <map>
#include <mutex>
#include <string>

#include "gazebo/common/PID.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace physics
  {
    class GZ_PHYSICS_VISIBLE JointController
    {
      public: explicit JointController(ModelPtr _model);
      public: virtual ~JointController();
      public: void AddJoint(JointPtr _joint);
      public: void Update();
      public: void Reset();
      public: void SetVelocityPID(const std::string &_jointName, const common::PID &_pid);
      public: bool SetVelocityTarget(const std::string &_jointName, const double _target);
      public: void SetPositionPID(const std::string &_jointName, const common::PID &_pid);
      public: bool SetPositionTarget(const std::string &_jointName, const double _target);
      public: bool SetForce(const std::string &_jointName, const double _force);
      public: std::map<std::string, JointPtr> GetJoints() const;
      public: std::map<std::string, common::PID> GetPositionPIDs() const;
      public: std::map<std::string, common::PID> GetVelocityPIDs() const;
      public: std::map<std::string, double> GetForces() const;
      public: std::map<std::string, double> GetPositions() const;
      public: std::map<std::string, double> GetVelocities() const;

      private: JointPtr Find(const std::string &_jointName) const;
      private: ModelPtr model;
      private: mutable std::recursive_mutex mutex;
      private: std::map<std::string, JointPtr> joints;
      private: std::map<std::string, common::PID> posPids;
      private: std::map<std::string, common::PID> velPids;
      private: std::map<std::string, double> forces;
      private: std::map<std::string, double> positions;
      private: std::map<std::string, double> velocities;
      private: common::Time prevUpdateTime;
    };
  }
}
#endif
