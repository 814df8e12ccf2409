// Plugins: WorldPlugin, ModelPlugin, SensorPlugin, SystemPlugin and the GZ_REGISTER_*
// macros, as Gazebo 11 declares them. sim_bridge loads model and world plugins (see
// gazebo_compat/Host.hh); sensor and system plugins compile, and sim_bridge does not load
// them yet.
#ifndef GAZEBO_COMPAT_COMMON_PLUGIN_HH
#define GAZEBO_COMPAT_COMMON_PLUGIN_HH

#include <dlfcn.h>
#include <string>

#include <boost/shared_ptr.hpp>
#include <sdf/sdf.hh>

#include "gazebo/gazebo_config.h"
#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo_compat
{
  // The RegisterPlugin function of a plugin library, found as Gazebo finds it (see
  // Host.hh); null with the reason in _error. _fullname is the file that was opened.
  GZ_VISIBLE void *OpenPluginLibrary(const std::string &_filename, std::string &_fullname,
                                     std::string &_error);
}

namespace gazebo
{
  enum PluginType
  {
    WORLD_PLUGIN,
    MODEL_PLUGIN,
    SENSOR_PLUGIN,
    SYSTEM_PLUGIN,
    VISUAL_PLUGIN,
    GUI_PLUGIN
  };

  template<class T>
  class PluginT
  {
    public: typedef boost::shared_ptr<T> TPtr;

    public: PluginT() = default;
    public: virtual ~PluginT() = default;
    public: std::string GetFilename() const { return this->filename; }
    public: std::string GetHandle() const { return this->handleName; }
    public: PluginType GetType() const { return this->type; }

    // Loads _filename (searched as Gazebo searches it) and constructs its plugin; null
    // after a gzerr naming the file and the loader's error.
    public: static TPtr Create(const std::string &_filename, const std::string &_name)
    {
      std::string fullname, error;
      void *symbol = gazebo_compat::OpenPluginLibrary(_filename, fullname, error);
      if (!symbol)
      {
        gzerr << "Failed to load plugin " << _filename << ": " << error << std::endl;
        return TPtr();
      }
      typedef T *(*Register)();
      TPtr result(reinterpret_cast<Register>(symbol)());
      if (result)
      {
        result->handleName = _name;
        result->filename = fullname;
      }
      return result;
    }

    protected: template<typename V>
               void LoadParam(const sdf::ElementPtr &_sdf, const std::string &_name,
                              V &_target, V _defaultValue = V()) const
    {
      auto result = _sdf->Get<V>(_name, _defaultValue);
      if (!result.second)
      {
        gzmsg << this->handleName.c_str() << " Plugin missing <" << _name.c_str()
              << ">, defaults to " << result.first << std::endl;
      }
      _target = result.first;
    }

    protected: void LoadParam(sdf::ElementPtr &_sdf, const std::string &_name,
                              std::string &_target, const char *_defaultValue)
    {
      this->LoadParam<std::string>(_sdf, _name, _target, _defaultValue);
    }

    protected: PluginType type;
    protected: std::string filename;
    protected: std::string handleName;
  };

  class WorldPlugin : public PluginT<WorldPlugin>
  {
    public: WorldPlugin() { this->type = WORLD_PLUGIN; }
    public: virtual ~WorldPlugin() {}
    public: virtual void Load(physics::WorldPtr _world, sdf::ElementPtr _sdf) = 0;
    public: virtual void Init() {}
    public: virtual void Reset() {}
  };

  class ModelPlugin : public PluginT<ModelPlugin>
  {
    public: ModelPlugin() { this->type = MODEL_PLUGIN; }
    public: virtual ~ModelPlugin() {}
    public: virtual void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) = 0;
    public: virtual void Init() {}
    public: virtual void Reset() {}
  };

  class SensorPlugin : public PluginT<SensorPlugin>
  {
    public: SensorPlugin() { this->type = SENSOR_PLUGIN; }
    public: virtual ~SensorPlugin() {}
    public: virtual void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf) = 0;
    public: virtual void Init() {}
    public: virtual void Reset() {}
  };

  class SystemPlugin : public PluginT<SystemPlugin>
  {
    public: SystemPlugin() { this->type = SYSTEM_PLUGIN; }
    public: virtual ~SystemPlugin() {}
    public: virtual void Load(int _argc = 0, char **_argv = nullptr) = 0;
    public: virtual void Init() {}
    public: virtual void Reset() {}
  };
}

// One RegisterPlugin per library, as in Gazebo; a ';' after the macro is an empty
// declaration, so both spellings compile.
#define GZ_REGISTER_MODEL_PLUGIN(classname) \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::ModelPlugin *RegisterPlugin(); \
  gazebo::ModelPlugin *RegisterPlugin() \
  { \
    return new classname(); \
  }

#define GZ_REGISTER_WORLD_PLUGIN(classname) \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::WorldPlugin *RegisterPlugin(); \
  gazebo::WorldPlugin *RegisterPlugin() \
  { \
    return new classname(); \
  }

#define GZ_REGISTER_SENSOR_PLUGIN(classname) \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::SensorPlugin *RegisterPlugin(); \
  gazebo::SensorPlugin *RegisterPlugin() \
  { \
    return new classname(); \
  }

#define GZ_REGISTER_SYSTEM_PLUGIN(classname) \
  extern "C" GZ_PLUGIN_VISIBLE gazebo::SystemPlugin *RegisterPlugin(); \
  gazebo::SystemPlugin *RegisterPlugin() \
  { \
    return new classname(); \
  }
#endif
