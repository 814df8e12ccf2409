// Symbol visibility macros under Gazebo's names (everything here is visible).
#ifndef GAZEBO_COMPAT_UTIL_SYSTEM_HH
#define GAZEBO_COMPAT_UTIL_SYSTEM_HH
#define GZ_VISIBLE __attribute__((visibility("default")))
#define GAZEBO_VISIBLE GZ_VISIBLE
#define GZ_PLUGIN_VISIBLE GZ_VISIBLE
#define GZ_COMMON_VISIBLE GZ_VISIBLE
#define GZ_PHYSICS_VISIBLE GZ_VISIBLE
#define GZ_SENSORS_VISIBLE GZ_VISIBLE
#define GZ_TRANSPORT_VISIBLE GZ_VISIBLE
#define GZ_MSGS_VISIBLE GZ_VISIBLE
#define GZ_UTIL_VISIBLE GZ_VISIBLE
#define GZ_RENDERING_VISIBLE GZ_VISIBLE
#define GAZEBO_DEPRECATED(version) __attribute__((deprecated))
#endif
