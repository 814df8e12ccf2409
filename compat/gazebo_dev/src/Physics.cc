// gazebo::physics over gazebo_compat::Backend: every read asks the backend, every write
// goes to it (acting on the next physics step).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/physics/physics.hh"
#include "gazebo_compat/Host.hh"

namespace gazebo
{
namespace physics
{
namespace
{
std::atomic<uint32_t> nextId{0};

std::shared_ptr<gazebo_compat::Backend> backend()
{
  return gazebo_compat::Host::Instance().GetBackend();
}

ignition::math::Pose3d PoseOf(const std::vector<double> &_s)
{
  return ignition::math::Pose3d(_s.at(0), _s.at(1), _s.at(2), _s.at(6), _s.at(3), _s.at(4),
                                _s.at(5));
}

std::vector<double> Values(const ignition::math::Pose3d &_p)
{
  return {_p.Pos().X(), _p.Pos().Y(), _p.Pos().Z(), _p.Rot().X(), _p.Rot().Y(), _p.Rot().Z(),
          _p.Rot().W()};
}

const double kKeep = std::numeric_limits<double>::quiet_NaN();

std::vector<double> Twist(const ignition::math::Vector3d *_linear,
                          const ignition::math::Vector3d *_angular)
{
  std::vector<double> twist(6, kKeep);
  for (int i = 0; i < 3; ++i)
  {
    if (_linear)
      twist[i] = (*_linear)[i];
    if (_angular)
      twist[3 + i] = (*_angular)[i];
  }
  return twist;
}
}  // namespace

// --- Base ---------------------------------------------------------------------------------
Base::Base(BasePtr _parent) : parent(_parent), id(nextId++)
{
  if (_parent)
    this->world = _parent->GetWorld();
}
Base::~Base() {}
void Base::Reset() {}
void Base::SetName(const std::string &_name) { this->name = _name; }
std::string Base::GetName() const { return this->name; }
uint32_t Base::GetId() const { return this->id; }
BasePtr Base::GetParent() const { return this->parent.lock(); }
void Base::AddType(EntityType _type) { this->type |= _type; }
bool Base::HasType(const EntityType &_t) const
{
  return (this->type & static_cast<unsigned int>(_t)) == static_cast<unsigned int>(_t);
}
unsigned int Base::GetType() const { return this->type; }

std::string Base::TypeStr() const
{
  if (this->HasType(MODEL)) return "model";
  if (this->HasType(LINK)) return "link";
  if (this->HasType(JOINT)) return "joint";
  return "base";
}

std::string Base::GetScopedName(bool _prependWorldName) const
{
  std::string scoped = this->name;
  for (BasePtr p = this->GetParent(); p; p = p->GetParent())
    scoped = p->GetName() + "::" + scoped;
  if (_prependWorldName && this->world)
    scoped = this->world->Name() + "::" + scoped;
  return scoped;
}

const WorldPtr &Base::GetWorld() const { return this->world; }
void Base::SetWorld(const WorldPtr &_newWorld) { this->world = _newWorld; }

// --- Entity -------------------------------------------------------------------------------
Entity::Entity(BasePtr _parent) : Base(_parent) { this->AddType(ENTITY); }
Entity::~Entity() {}

const ignition::math::Pose3d &Entity::WorldPose() const
{
  this->worldPose = PoseOf(this->State());
  return this->worldPose;
}

ignition::math::Pose3d Entity::RelativePose() const
{
  auto parentEntity = boost::dynamic_pointer_cast<Entity>(this->GetParent());
  const ignition::math::Pose3d own = this->WorldPose();
  if (!parentEntity)
    return own;
  return own - parentEntity->WorldPose();
}

void Entity::SetWorldPose(const ignition::math::Pose3d &_pose, const bool, const bool)
{
  this->SetPose(_pose);
}

void Entity::SetRelativePose(const ignition::math::Pose3d &_pose, const bool, const bool)
{
  auto parentEntity = boost::dynamic_pointer_cast<Entity>(this->GetParent());
  this->SetPose(parentEntity ? _pose + parentEntity->WorldPose() : _pose);
}

ignition::math::Vector3d Entity::WorldLinearVel() const
{
  const auto s = this->State();
  return ignition::math::Vector3d(s.at(7), s.at(8), s.at(9));
}

ignition::math::Vector3d Entity::WorldAngularVel() const
{
  const auto s = this->State();
  return ignition::math::Vector3d(s.at(10), s.at(11), s.at(12));
}

ignition::math::Vector3d Entity::RelativeLinearVel() const
{
  const auto s = this->State();
  return PoseOf(s).Rot().RotateVectorReverse(ignition::math::Vector3d(s.at(7), s.at(8), s.at(9)));
}

ignition::math::Vector3d Entity::RelativeAngularVel() const
{
  const auto s = this->State();
  return PoseOf(s).Rot().RotateVectorReverse(
      ignition::math::Vector3d(s.at(10), s.at(11), s.at(12)));
}

ModelPtr Entity::GetParentModel()
{
  if (this->HasType(MODEL))
    return boost::dynamic_pointer_cast<Model>(this->shared_from_this());
  return boost::dynamic_pointer_cast<Model>(this->GetParent());
}

// --- Link ---------------------------------------------------------------------------------
Link::Link(EntityPtr _parent) : Entity(_parent) { this->AddType(LINK); }
Link::~Link() {}
ModelPtr Link::GetModel() const { return boost::dynamic_pointer_cast<Model>(this->GetParent()); }

std::vector<double> Link::State() const
{
  return backend()->LinkState(this->GetParent()->GetName(), this->name);
}

void Link::SetPose(const ignition::math::Pose3d &)
{
  gzerr << "Link::SetWorldPose/SetRelativePose (" << this->GetScopedName()
        << ") is not provided by sim_bridge; set the model's pose" << std::endl;
}

void Link::Velocity(const ignition::math::Vector3d *_linear,
                    const ignition::math::Vector3d *_angular)
{
  backend()->SetLinkVelocity(this->GetParent()->GetName(), this->name, Twist(_linear, _angular));
}

void Link::SetLinearVel(const ignition::math::Vector3d &_vel) { this->Velocity(&_vel, nullptr); }
void Link::SetAngularVel(const ignition::math::Vector3d &_vel) { this->Velocity(nullptr, &_vel); }

void Link::Wrench(const ignition::math::Vector3d &_force, const ignition::math::Vector3d &_torque,
                  bool _inLinkFrame)
{
  backend()->AddLinkWrench(this->GetParent()->GetName(), this->name,
                           {_force.X(), _force.Y(), _force.Z(), _torque.X(), _torque.Y(),
                            _torque.Z()}, _inLinkFrame);
}

void Link::AddForce(const ignition::math::Vector3d &_force)
{
  this->Wrench(_force, ignition::math::Vector3d::Zero, false);
}
void Link::AddRelativeForce(const ignition::math::Vector3d &_force)
{
  this->Wrench(_force, ignition::math::Vector3d::Zero, true);
}
void Link::AddTorque(const ignition::math::Vector3d &_torque)
{
  this->Wrench(ignition::math::Vector3d::Zero, _torque, false);
}
void Link::AddRelativeTorque(const ignition::math::Vector3d &_torque)
{
  this->Wrench(ignition::math::Vector3d::Zero, _torque, true);
}

Joint_V Link::GetParentJoints() const
{
  Joint_V found;
  ModelPtr model = this->GetModel();
  if (model)
    for (const auto &joint : model->GetJoints())
      if (joint->GetChild() && joint->GetChild()->GetName() == this->name)
        found.push_back(joint);
  return found;
}

Joint_V Link::GetChildJoints() const
{
  Joint_V found;
  ModelPtr model = this->GetModel();
  if (model)
    for (const auto &joint : model->GetJoints())
      if (joint->GetParent() && joint->GetParent()->GetName() == this->name)
        found.push_back(joint);
  return found;
}

// --- Joint --------------------------------------------------------------------------------
Joint::Joint(BasePtr _parent, const std::string &_type) : Base(_parent)
{
  this->AddType(JOINT);
  if (_type == "revolute" || _type == "continuous")
    this->AddType(HINGE_JOINT);
  else if (_type == "prismatic")
    this->AddType(SLIDER_JOINT);
  else if (_type == "fixed")
    this->AddType(FIXED_JOINT);
  else if (_type == "floating" || _type == "ball")
    this->AddType(BALL_JOINT);
}
Joint::~Joint() {}

void Joint::Attach(LinkPtr _parent, LinkPtr _child, double _lower, double _upper,
                   double _effort, double _velocity)
{
  this->parentLink = _parent;
  this->childLink = _child;
  this->lower = _lower;
  this->upper = _upper;
  this->effortLimit = _effort;
  this->velocityLimit = _velocity;
}

LinkPtr Joint::GetChild() const { return this->childLink; }
LinkPtr Joint::GetParent() const { return this->parentLink; }
ModelPtr Joint::GetModel() const { return boost::dynamic_pointer_cast<Model>(Base::GetParent()); }
unsigned int Joint::DOF() const { return this->HasType(FIXED_JOINT) ? 0 : 1; }

bool Joint::CheckIndex(unsigned int _index, const char *_what) const
{
  if (_index < this->DOF())
    return true;
  gzerr << "Joint::" << _what << ": invalid index [" << _index << "] for joint "
        << this->GetScopedName() << " (it has " << this->DOF() << " axis)" << std::endl;
  return false;
}

double Joint::Position(const unsigned int _index) const
{
  if (!this->CheckIndex(_index, "Position"))
    return std::numeric_limits<double>::quiet_NaN();
  return backend()->JointState(Base::GetParent()->GetName(), this->name).at(0);
}

double Joint::GetVelocity(unsigned int _index) const
{
  if (!this->CheckIndex(_index, "GetVelocity"))
    return 0.0;
  return backend()->JointState(Base::GetParent()->GetName(), this->name).at(1);
}

void Joint::SetVelocity(unsigned int _index, double _vel)
{
  if (this->CheckIndex(_index, "SetVelocity"))
    backend()->SetJointVelocity(Base::GetParent()->GetName(), this->name, _vel);
}

void Joint::SetForce(unsigned int _index, double _effort)
{
  if (!this->CheckIndex(_index, "SetForce"))
    return;
  // what is set within one step adds up; the effort limit truncates the sum (Gazebo's
  // CheckAndTruncateForce; a negative limit is none)
  this->force += _effort;
  if (this->effortLimit >= 0)
    this->force = std::max(-this->effortLimit, std::min(this->effortLimit, this->force));
  backend()->SetJointForce(Base::GetParent()->GetName(), this->name, this->force);
}

double Joint::GetForce(unsigned int _index)
{
  return this->CheckIndex(_index, "GetForce") ? this->force : 0.0;
}

void Joint::ClearForce() { this->force = 0.0; }

bool Joint::SetParam(const std::string &_key, unsigned int _index, const boost::any &_value)
{
  if (!this->CheckIndex(_index, "SetParam"))
    return false;
  double value;
  try
  {
    value = boost::any_cast<double>(_value);
  }
  catch (const boost::bad_any_cast &_e)
  {
    gzerr << "SetParam(" << _key << ") boost any_cast error: " << _e.what()
          << " (give a double, e.g. 100.0 not 100)" << std::endl;
    return false;
  }
  if (_key == "fmax")
    this->fmax = value;
  else if (_key == "vel")
    this->vel = value;
  else if (_key == "friction")
  {
    this->fmax = value;
    this->vel = 0.0;
  }
  else
  {
    gzerr << "Unable to handle joint attribute[" << _key << "] (sim_bridge's joints take "
          << "fmax, vel and friction)" << std::endl;
    return false;
  }
  backend()->SetJointMotor(Base::GetParent()->GetName(), this->name, this->vel, this->fmax);
  return true;
}

double Joint::GetParam(const std::string &_key, unsigned int _index)
{
  if (!this->CheckIndex(_index, "GetParam"))
    return 0.0;
  if (_key == "fmax" || _key == "friction")
    return this->fmax;
  if (_key == "vel")
    return this->vel;
  if (_key == "lo_stop")
    return this->lower;
  if (_key == "hi_stop")
    return this->upper;
  gzerr << "GetParam: unable to get joint attribute[" << _key << "]" << std::endl;
  return 0.0;
}

double Joint::LowerLimit(unsigned int) const { return this->lower; }
double Joint::UpperLimit(const unsigned int) const { return this->upper; }
double Joint::GetEffortLimit(unsigned int) { return this->effortLimit; }
double Joint::GetVelocityLimit(unsigned int) { return this->velocityLimit; }

void Joint::Reset()
{
  // Gazebo's reset stops the joint and zeroes ODE's motor (fmax), as diff_drive expects
  this->fmax = 0.0;
  this->vel = 0.0;
  this->force = 0.0;
  if (this->DOF() > 0)
    backend()->SetJointMotor(Base::GetParent()->GetName(), this->name, 0.0, 0.0);
}

// --- JointController ----------------------------------------------------------------------
JointController::JointController(ModelPtr _model) : model(_model)
{
  for (const auto &joint : _model->GetJoints())
    this->AddJoint(joint);
}
JointController::~JointController() {}

void JointController::AddJoint(JointPtr _joint)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->joints[_joint->GetScopedName()] = _joint;
}

JointPtr JointController::Find(const std::string &_jointName) const
{
  auto found = this->joints.find(_jointName);
  return found == this->joints.end() ? JointPtr() : found->second;
}

void JointController::SetVelocityPID(const std::string &_jointName, const common::PID &_pid)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->Find(_jointName))
    this->velPids[_jointName] = _pid;
  else
    gzerr << "Unable to find joint with name[" << _jointName << "]" << std::endl;
}

bool JointController::SetVelocityTarget(const std::string &_jointName, const double _target)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->velPids.count(_jointName) == 0)
    return false;
  this->velocities[_jointName] = _target;
  return true;
}

void JointController::SetPositionPID(const std::string &_jointName, const common::PID &_pid)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->Find(_jointName))
    this->posPids[_jointName] = _pid;
  else
    gzerr << "Unable to find joint with name[" << _jointName << "]" << std::endl;
}

bool JointController::SetPositionTarget(const std::string &_jointName, const double _target)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->posPids.count(_jointName) == 0)
    return false;
  this->positions[_jointName] = _target;
  return true;
}

bool JointController::SetForce(const std::string &_jointName, const double _force)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (!this->Find(_jointName))
    return false;
  this->forces[_jointName] = _force;
  return true;
}

void JointController::Update()
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  const common::Time now = this->model->GetWorld()->SimTime();
  const common::Time dt = now - this->prevUpdateTime;
  this->prevUpdateTime = now;
  if (dt <= common::Time::Zero)
    return;
  for (const auto &entry : this->forces)
    this->Find(entry.first)->SetForce(0, entry.second);
  this->forces.clear();
  for (const auto &entry : this->positions)
  {
    JointPtr joint = this->Find(entry.first);
    joint->SetForce(0, this->posPids[entry.first].Update(joint->Position(0) - entry.second, dt));
  }
  for (const auto &entry : this->velocities)
  {
    JointPtr joint = this->Find(entry.first);
    joint->SetForce(0,
                    this->velPids[entry.first].Update(joint->GetVelocity(0) - entry.second, dt));
  }
}

void JointController::Reset()
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->forces.clear();
  this->positions.clear();
  this->velocities.clear();
  for (auto &entry : this->posPids)
    entry.second.Reset();
  for (auto &entry : this->velPids)
    entry.second.Reset();
}

std::map<std::string, JointPtr> JointController::GetJoints() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->joints;
}
std::map<std::string, common::PID> JointController::GetPositionPIDs() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->posPids;
}
std::map<std::string, common::PID> JointController::GetVelocityPIDs() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->velPids;
}
std::map<std::string, double> JointController::GetForces() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->forces;
}
std::map<std::string, double> JointController::GetPositions() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->positions;
}
std::map<std::string, double> JointController::GetVelocities() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->velocities;
}

// --- Model --------------------------------------------------------------------------------
Model::Model(BasePtr _parent) : Entity(_parent) { this->AddType(MODEL); }
Model::~Model() {}

void Model::Build(const Link_V &_links, const Joint_V &_joints)
{
  this->links = _links;
  this->joints = _joints;
}

std::vector<double> Model::State() const { return backend()->ModelState(this->name); }
void Model::SetPose(const ignition::math::Pose3d &_pose)
{
  backend()->SetModelPose(this->name, Values(_pose));
}

void Model::SetLinearVel(const ignition::math::Vector3d &_vel)
{
  backend()->SetModelVelocity(this->name, Twist(&_vel, nullptr));
}

void Model::SetAngularVel(const ignition::math::Vector3d &_vel)
{
  backend()->SetModelVelocity(this->name, Twist(nullptr, &_vel));
}

unsigned int Model::GetJointCount() const { return static_cast<unsigned int>(this->joints.size()); }
const Joint_V &Model::GetJoints() const { return this->joints; }

JointPtr Model::GetJoint(const std::string &_name)
{
  for (const auto &joint : this->joints)
    if (joint->GetName() == _name || joint->GetScopedName() == _name)
      return joint;
  return JointPtr();
}

const Link_V &Model::GetLinks() const { return this->links; }

LinkPtr Model::GetLink(const std::string &_name) const
{
  if (_name == "canonical")
    return this->links.empty() ? LinkPtr() : this->links.front();
  return this->GetChildLink(_name);
}

LinkPtr Model::GetChildLink(const std::string &_name) const
{
  for (const auto &link : this->links)
    if (link->GetName() == _name || link->GetScopedName() == _name)
      return link;
  return LinkPtr();
}

void Model::SetGravityMode(const bool &_value) { backend()->SetGravityMode(this->name, _value); }

JointControllerPtr Model::GetJointController()
{
  if (!this->jointController)
    this->jointController.reset(
        new JointController(boost::dynamic_pointer_cast<Model>(this->shared_from_this())));
  return this->jointController;
}

void Model::UpdateControllers()
{
  if (this->jointController)
    this->jointController->Update();
}

void Model::ClearForces()
{
  for (const auto &joint : this->joints)
    joint->ClearForce();
}

void Model::Reset()
{
  for (const auto &joint : this->joints)
    joint->Reset();
  if (this->jointController)
    this->jointController->Reset();
}

// --- PhysicsEngine, World -----------------------------------------------------------------
PhysicsEngine::PhysicsEngine(WorldPtr _world) : world(_world) {}
PhysicsEngine::~PhysicsEngine() {}
double PhysicsEngine::GetMaxStepSize() const { return backend()->StepSize(); }
std::string PhysicsEngine::GetType() const { return "ode"; }
WorldPtr PhysicsEngine::World() const { return this->world.lock(); }

World::World() {}
World::~World() {}
std::string World::Name() const { return backend()->WorldName(); }

PhysicsEnginePtr World::Physics() const
{
  if (!this->physics)
    this->physics.reset(
        new PhysicsEngine(boost::const_pointer_cast<World>(this->shared_from_this())));
  return this->physics;
}

common::Time World::SimTime() const
{
  const int64_t ns = gazebo_compat::Host::Instance().SimTimeNs();
  return common::Time(static_cast<int32_t>(ns / 1000000000),
                      static_cast<int32_t>(ns % 1000000000));
}

common::Time World::RealTime() const { return this->SimTime(); }
uint32_t World::Iterations() const { return gazebo_compat::Host::Instance().Iterations(); }
bool World::IsPaused() const { return false; }

Model_V World::Models() const
{
  Model_V models;
  for (const auto &name : backend()->ModelNames())
    models.push_back(gazebo_compat::Host::Instance().Model(name));
  return models;
}

unsigned int World::ModelCount() const
{
  return static_cast<unsigned int>(backend()->ModelNames().size());
}

ModelPtr World::ModelByIndex(unsigned int _index) const
{
  const auto names = backend()->ModelNames();
  return _index < names.size() ? gazebo_compat::Host::Instance().Model(names[_index])
                               : ModelPtr();
}

ModelPtr World::ModelByName(const std::string &_name) const
{
  const auto names = backend()->ModelNames();
  if (std::find(names.begin(), names.end(), _name) == names.end())
    return ModelPtr();
  return gazebo_compat::Host::Instance().Model(_name);
}

void World::InsertModelFile(const std::string &_sdfFilename)
{
  gzerr << "World::InsertModelFile(" << _sdfFilename << ") is not provided by sim_bridge; "
        << "spawn models with gazebo_ros's spawn_model" << std::endl;
}

void World::InsertModelString(const std::string &)
{
  gzerr << "World::InsertModelString is not provided by sim_bridge; spawn models with "
        << "gazebo_ros's spawn_model" << std::endl;
}

WorldPtr get_world(const std::string &_name)
{
  if (has_world(_name))
    return gazebo_compat::Host::Instance().World();
  if (_name.empty())
    gzerr << "no worlds\n";
  gzerr << "Unable to find world by name in physics::get_world[" << _name.c_str() << "]\n";
  gzthrow("Unable to find world by name in physics::get_world(world_name)");
}

bool has_world(const std::string &_name)
{
  try
  {
    std::shared_ptr<gazebo_compat::Backend> world = backend();
    return _name.empty() || world->WorldName() == _name;
  }
  catch (const std::runtime_error &)
  {
    return false;
  }
}
}  // namespace physics
}  // namespace gazebo
