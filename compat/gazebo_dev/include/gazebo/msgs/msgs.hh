// gazebo::msgs: a few of Gazebo's message types, hand-written with the protobuf-style
// accessors plugins use (x(), set_x(...)), so that code holding them compiles. Gazebo's
// transport is not provided (see transport/transport.hh), so nothing carries them.
#ifndef GAZEBO_COMPAT_MSGS_MSGS_HH
#define GAZEBO_COMPAT_MSGS_MSGS_HH
#include <cstdint>
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

    typedef const boost::shared_ptr<const Vector3d> ConstVector3dPtr;
    typedef const boost::shared_ptr<const Quaternion> ConstQuaternionPtr;
    typedef const boost::shared_ptr<const Pose> ConstPosePtr;
    typedef const boost::shared_ptr<const Time> ConstTimePtr;
  }
}
#endif
