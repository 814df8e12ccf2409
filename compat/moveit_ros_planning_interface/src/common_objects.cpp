// MoveIt's shared planning-interface objects (common_objects.cpp, noetic-devel 7c0343f0): one TF buffer and one robot
// model per description for the process (with its groups' kinematics plugins), shared while in use.
#include <moveit/common_planning_interface_objects/common_objects.h>

#include <map>
#include <mutex>

#include <moveit/robot_model_loader/robot_model_loader.h>
#include <tf2_ros/transform_listener.h>

namespace moveit
{
namespace planning_interface
{
std::shared_ptr<tf2_ros::Buffer> getSharedTF()
{
  // the listener lives exactly as long as the buffer it fills
  struct BufferAndListener
  {
    tf2_ros::Buffer buffer;
    tf2_ros::TransformListener listener{ buffer };
  };
  static std::mutex mutex;
  static std::weak_ptr<tf2_ros::Buffer> shared;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<tf2_ros::Buffer> buffer = shared.lock();
  if (!buffer)
  {
    auto both = std::make_shared<BufferAndListener>();
    buffer = std::shared_ptr<tf2_ros::Buffer>(both, &both->buffer);
    shared = buffer;
  }
  return buffer;
}

moveit::core::RobotModelConstPtr getSharedRobotModel(const std::string& robot_description)
{
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const moveit::core::RobotModel>> models;
  std::lock_guard<std::mutex> lock(mutex);
  moveit::core::RobotModelConstPtr model = models[robot_description].lock();
  if (!model)
  {
    // the groups' kinematics plugins loaded too, and the loader kept as long as the model is (an aliasing pointer,
    // common_objects.cpp l. 116-132)
    robot_model_loader::RobotModelLoader::Options options(robot_description);
    options.load_kinematics_solvers_ = true;
    auto loader = std::make_shared<robot_model_loader::RobotModelLoader>(options);
    if (loader->getModel())
      model = moveit::core::RobotModelConstPtr(loader, loader->getModel().get());
    models[robot_description] = model;
  }
  return model;
}
}  // namespace planning_interface
}  // namespace moveit
