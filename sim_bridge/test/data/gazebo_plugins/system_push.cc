// A Gazebo system plugin (gzserver -s), in the shape system plugins take: Load(argc, argv)
// keeps the command line, Init() waits for the world, and once Events::worldCreated names it
// the world is looked up with physics::get_world and the model "box" is pushed along x
// before every step, at 0.1 m/s for each word of the command line (a check that it was
// given). SYSTEM_PUSH_FAIL=init makes Init throw, as a plugin missing its setup would.
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/common/common.hh>
#include <ignition/math/Vector3.hh>

namespace gazebo
{
  class SystemPush : public SystemPlugin
  {
    public: void Load(int _argc, char **_argv) override
    {
      this->words = _argc;
      for (int i = 0; i < _argc; ++i)
        gzmsg << "system_push: argv[" << i << "] = " << _argv[i] << std::endl;
    }

    public: void Init() override
    {
      const char *fail = std::getenv("SYSTEM_PUSH_FAIL");
      if (fail && std::strcmp(fail, "init") == 0)
        gzthrow("system_push was told to fail in Init");
      this->created = event::Events::ConnectWorldCreated(
          std::bind(&SystemPush::OnWorldCreated, this, std::placeholders::_1));
    }

    private: void OnWorldCreated(const std::string &_name)
    {
      if (!physics::has_world(_name))
        return;
      this->world = physics::get_world(_name);
      this->update = event::Events::ConnectWorldUpdateBegin(
          std::bind(&SystemPush::OnUpdate, this));
    }

    private: void OnUpdate()
    {
      physics::ModelPtr box = this->world->ModelByName("box");
      if (box)
        box->SetLinearVel(ignition::math::Vector3d(0.1 * this->words, 0, 0));
    }

    private: int words = 0;
    private: physics::WorldPtr world;
    private: event::ConnectionPtr created;
    private: event::ConnectionPtr update;
  };

  GZ_REGISTER_SYSTEM_PLUGIN(SystemPush)
}
