// The host of Gazebo plugins inside sim_bridge: the one World, its Models (made when first
// asked, from Backend::Describe), the plugins loaded, and the step's events.
//
// Plugin files are found as Gazebo 11 finds them (common::SystemPaths, PluginT::Create):
// each folder of GAZEBO_PLUGIN_PATH, then the lib folders of catkin's CMAKE_PREFIX_PATH (the
// devel and install spaces), then dlopen's own search (LD_LIBRARY_PATH); opened with
// RTLD_LAZY | RTLD_GLOBAL. A plugin that cannot be opened, is not of the expected kind, or
// throws in its constructor, Load or Init is dropped and the reason returned; the rest runs.
#ifndef GAZEBO_COMPAT_HOST_HH
#define GAZEBO_COMPAT_HOST_HH
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo_compat/Backend.hh"

namespace gazebo_compat
{
  class GZ_VISIBLE Host
  {
    public: static Host &Instance();
    public: void SetBackend(std::shared_ptr<Backend> _backend);
    // the backend; throws std::runtime_error when there is none (no world)
    public: std::shared_ptr<Backend> GetBackend() const;
    public: gazebo::physics::WorldPtr World();
    public: gazebo::physics::ModelPtr Model(const std::string &_name);
    public: std::vector<gazebo::physics::ModelPtr> KnownModels() const;

    // "" when loaded, else why not
    public: std::string LoadModelPlugin(const std::string &_model, const std::string &_filename,
                                        const std::string &_name, sdf::ElementPtr _sdf);
    // a plugin of the model's sensor (a <plugin> inside its <sensor>)
    public: std::string LoadSensorPlugin(const std::string &_model, const std::string &_sensor,
                                         const std::string &_filename,
                                         const std::string &_name, sdf::ElementPtr _sdf);
    public: std::string LoadWorldPlugin(const std::string &_filename, const std::string &_name,
                                        sdf::ElementPtr _sdf);
    // a system plugin (gzserver -s): made and Load(argc, argv) now, Init() by InitSystemPlugins
    public: std::string LoadSystemPlugin(const std::string &_filename,
                                         const std::vector<std::string> &_argv);
    // every system plugin's Init(); why each that failed did (those are dropped)
    public: std::vector<std::string> InitSystemPlugins();
    // the world has loaded: Events::worldCreated with its name
    public: void WorldCreated();
    // the model's plugins destroyed, the model forgotten (it was deleted)
    public: void RemoveModel(const std::string &_name);
    public: std::vector<std::string> PluginNames(const std::string &_model) const;

    // one physics step: Begin before it (time already one step on), End after it
    public: void WorldUpdateBegin(int64_t _simTimeNs);
    public: void WorldUpdateEnd();
    public: void SetSimTime(int64_t _simTimeNs);
    public: int64_t SimTimeNs() const;
    public: uint32_t Iterations() const;
    public: void Reset();
    // every plugin destroyed, the world forgotten
    public: void Close();

    public: static std::vector<std::string> PluginPath();

    private: Host() = default;
    private: mutable std::recursive_mutex mutex;
    private: std::shared_ptr<Backend> backend;
    private: gazebo::physics::WorldPtr world;
    private: std::map<std::string, gazebo::physics::ModelPtr> models;
    private: std::vector<std::pair<std::string, gazebo::ModelPlugin::TPtr>> modelPlugins;
    private: std::vector<gazebo::WorldPlugin::TPtr> worldPlugins;
    private: std::vector<std::pair<std::string, gazebo::SystemPlugin::TPtr>> systemPlugins;
    // the command line system plugins are given, kept for as long as they may read it
    private: std::vector<std::string> systemArguments;
    private: std::vector<char *> systemArgv;
    private: std::vector<std::pair<std::string, gazebo::SensorPlugin::TPtr>> sensorPlugins;
    private: int64_t simTimeNs = 0;
    private: uint32_t iterations = 0;
    // the world's name as the backend gave it when the last model was added
    private: std::string worldName;
  };
}
#endif
