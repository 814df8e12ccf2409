// What WorldUpdateBegin's subscribers receive.
#ifndef GAZEBO_COMPAT_COMMON_UPDATEINFO_HH
#define GAZEBO_COMPAT_COMMON_UPDATEINFO_HH
#include <string>
#include "gazebo/common/Time.hh"
namespace gazebo
{
  namespace common
  {
    class GZ_COMMON_VISIBLE UpdateInfo
    {
      public: std::string worldName;
      public: common::Time simTime;
      public: common::Time realTime;
    };
  }
}
#endif
