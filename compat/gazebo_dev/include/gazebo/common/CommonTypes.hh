// Pointer types of gazebo::common and gazebo::event (boost::shared_ptr, as Gazebo 11's).
#ifndef GAZEBO_COMPAT_COMMON_COMMONTYPES_HH
#define GAZEBO_COMPAT_COMMON_COMMONTYPES_HH
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>

namespace gazebo
{
  namespace common
  {
    class Time;
    class PID;
    class UpdateInfo;
  }
  namespace event
  {
    class Connection;
    typedef boost::shared_ptr<Connection> ConnectionPtr;
    typedef std::vector<ConnectionPtr> Connection_V;
  }
}
#endif
