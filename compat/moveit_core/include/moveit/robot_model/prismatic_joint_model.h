// MoveIt's PrismaticJointModel subclass is not provided here: compat/moveit_core has one concrete moveit::core::JointModel
// for every joint type (getType() == JointModel::PRISMATIC; getAxis() and isContinuous() on it).
#error "moveit/robot_model/prismatic_joint_model.h (PrismaticJointModel) is not provided by compat/moveit_core: use moveit::core::JointModel from moveit/robot_model/joint_model.h and its getType()"
