// Gazebo's rendering is not provided by sim_bridge (no cameras, visuals or GUI plugins in
// C++): only the namespace exists, because common/Plugin.hh includes this header.
#ifndef GAZEBO_COMPAT_RENDERING_RENDERTYPES_HH
#define GAZEBO_COMPAT_RENDERING_RENDERTYPES_HH
namespace gazebo { namespace rendering {} }
#endif
