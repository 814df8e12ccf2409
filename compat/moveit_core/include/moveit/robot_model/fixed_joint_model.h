// MoveIt's FixedJointModel subclass is not provided here: compat/moveit_core has one concrete moveit::core::JointModel
// for every joint type (getType() == JointModel::FIXED; getAxis() and isContinuous() on it).
#error "moveit/robot_model/fixed_joint_model.h (FixedJointModel) is not provided by compat/moveit_core: use moveit::core::JointModel from moveit/robot_model/joint_model.h and its getType()"
