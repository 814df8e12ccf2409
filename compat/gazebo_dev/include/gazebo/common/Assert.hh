// GZ_ASSERT as Gazebo has it (Boost's assertion with a message).
#ifndef GAZEBO_COMPAT_COMMON_ASSERT_HH
#define GAZEBO_COMPAT_COMMON_ASSERT_HH
#include <boost/assert.hpp>
#define GZ_ASSERT(_expr, _msg) BOOST_ASSERT_MSG(_expr, _msg)
#endif
