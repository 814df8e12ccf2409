// gazebo::msgs: a few of Gazebo's message types, hand-written with the protobuf-style
// accessors plugins use (x(), set_x(...), repeated fields' _size(), (i) and add_...()), so
// that code holding them compiles. Gazebo's transport is not provided (see
// transport/transport.hh), so nothing carries them; ContactSensor::Contacts() fills Contacts.
#ifndef GAZEBO_COMPAT_MSGS_MSGS_HH
#define GAZEBO_COMPAT_MSGS_MSGS_HH
#include <cstdint>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>

namespace gazebo
{
  namespace msgs
  {
    class Vector3d
    {
      public: double x() const { return this->x_; }
      public: double y() const { return this->y_; }
      public: double z() const { return this->z_; }
      public: void set_x(double _v) { this->x_ = _v; }
      public: void set_y(double _v) { this->y_ = _v; }
      public: void set_z(double _v) { this->z_ = _v; }
      private: double x_ = 0.0, y_ = 0.0, z_ = 0.0;
    };

    class Quaternion
    {
      public: double x() const { return this->x_; }
      public: double y() const { return this->y_; }
      public: double z() const { return this->z_; }
      public: double w() const { return this->w_; }
      public: void set_x(double _v) { this->x_ = _v; }
      public: void set_y(double _v) { this->y_ = _v; }
      public: void set_z(double _v) { this->z_ = _v; }
      public: void set_w(double _v) { this->w_ = _v; }
      private: double x_ = 0.0, y_ = 0.0, z_ = 0.0, w_ = 1.0;
    };

    class Pose
    {
      public: const Vector3d &position() const { return this->position_; }
      public: const Quaternion &orientation() const { return this->orientation_; }
      public: Vector3d *mutable_position() { return &this->position_; }
      public: Quaternion *mutable_orientation() { return &this->orientation_; }
      private: Vector3d position_;
      private: Quaternion orientation_;
    };

    class Time
    {
      public: int32_t sec() const { return this->sec_; }
      public: int32_t nsec() const { return this->nsec_; }
      public: void set_sec(int32_t _v) { this->sec_ = _v; }
      public: void set_nsec(int32_t _v) { this->nsec_ = _v; }
      private: int32_t sec_ = 0, nsec_ = 0;
    };

    class Wrench
    {
      public: const Vector3d &force() const { return this->force_; }
      public: const Vector3d &torque() const { return this->torque_; }
      public: const Vector3d &force_offset() const { return this->forceOffset_; }
      public: Vector3d *mutable_force() { return &this->force_; }
      public: Vector3d *mutable_torque() { return &this->torque_; }
      public: Vector3d *mutable_force_offset() { return &this->forceOffset_; }
      private: Vector3d force_, torque_, forceOffset_;
    };

    class JointWrench
    {
      public: const std::string &body_1_name() const { return this->body1Name_; }
      public: const std::string &body_2_name() const { return this->body2Name_; }
      public: uint32_t body_1_id() const { return this->body1Id_; }
      public: uint32_t body_2_id() const { return this->body2Id_; }
      public: const Wrench &body_1_wrench() const { return this->body1Wrench_; }
      public: const Wrench &body_2_wrench() const { return this->body2Wrench_; }
      public: void set_body_1_name(const std::string &_v) { this->body1Name_ = _v; }
      public: void set_body_2_name(const std::string &_v) { this->body2Name_ = _v; }
      public: void set_body_1_id(uint32_t _v) { this->body1Id_ = _v; }
      public: void set_body_2_id(uint32_t _v) { this->body2Id_ = _v; }
      public: Wrench *mutable_body_1_wrench() { return &this->body1Wrench_; }
      public: Wrench *mutable_body_2_wrench() { return &this->body2Wrench_; }
      private: std::string body1Name_, body2Name_;
      private: uint32_t body1Id_ = 0, body2Id_ = 0;
      private: Wrench body1Wrench_, body2Wrench_;
    };

    // one pair of collisions touching: per contact point its position and normal (world
    // axes; the normal points at collision1), depth and wrench
    class Contact
    {
      public: const std::string &collision1() const { return this->collision1_; }
      public: const std::string &collision2() const { return this->collision2_; }
      public: void set_collision1(const std::string &_v) { this->collision1_ = _v; }
      public: void set_collision2(const std::string &_v) { this->collision2_ = _v; }
      public: int position_size() const { return static_cast<int>(this->position_.size()); }
      public: const Vector3d &position(int _i) const { return this->position_.at(_i); }
      public: Vector3d *add_position() { this->position_.emplace_back(); return &this->position_.back(); }
      public: int normal_size() const { return static_cast<int>(this->normal_.size()); }
      public: const Vector3d &normal(int _i) const { return this->normal_.at(_i); }
      public: Vector3d *add_normal() { this->normal_.emplace_back(); return &this->normal_.back(); }
      public: int depth_size() const { return static_cast<int>(this->depth_.size()); }
      public: double depth(int _i) const { return this->depth_.at(_i); }
      public: void add_depth(double _v) { this->depth_.push_back(_v); }
      public: int wrench_size() const { return static_cast<int>(this->wrench_.size()); }
      public: const JointWrench &wrench(int _i) const { return this->wrench_.at(_i); }
      public: JointWrench *add_wrench() { this->wrench_.emplace_back(); return &this->wrench_.back(); }
      public: const Time &time() const { return this->time_; }
      public: Time *mutable_time() { return &this->time_; }
      public: const std::string &world() const { return this->world_; }
      public: void set_world(const std::string &_v) { this->world_ = _v; }
      private: std::string collision1_, collision2_, world_;
      private: std::vector<Vector3d> position_, normal_;
      private: std::vector<double> depth_;
      private: std::vector<JointWrench> wrench_;
      private: Time time_;
    };

    class Contacts
    {
      public: int contact_size() const { return static_cast<int>(this->contact_.size()); }
      public: const Contact &contact(int _i) const { return this->contact_.at(_i); }
      public: Contact *add_contact() { this->contact_.emplace_back(); return &this->contact_.back(); }
      public: void clear_contact() { this->contact_.clear(); }
      public: const Time &time() const { return this->time_; }
      public: Time *mutable_time() { return &this->time_; }
      private: std::vector<Contact> contact_;
      private: Time time_;
    };

    typedef const boost::shared_ptr<const Vector3d> ConstVector3dPtr;
    typedef const boost::shared_ptr<const Quaternion> ConstQuaternionPtr;
    typedef const boost::shared_ptr<const Pose> ConstPosePtr;
    typedef const boost::shared_ptr<const Time> ConstTimePtr;
    typedef const boost::shared_ptr<const Contacts> ConstContactsPtr;
  }
}
#endif
