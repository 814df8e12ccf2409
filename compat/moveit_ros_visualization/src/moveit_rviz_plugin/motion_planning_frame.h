/* The MotionPlanning display's panel (MoveIt's MotionPlanningFrame, the part built here):
 * the Planning tab (planning group, start and goal states: <current>, <random valid>,
 * <previous> and the SRDF's named states; planning time, attempts, velocity and acceleration
 * scaling; Plan, Execute, Plan & Execute, Stop; the result) and the Scene Objects tab (a box
 * added at a pose, an object removed). The buttons' work is the display's. */
#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace moveit_rviz_plugin
{
class MotionPlanningFrame : public QWidget
{
  Q_OBJECT
public:
  explicit MotionPlanningFrame(QWidget* parent = nullptr);

  QComboBox* planning_group;
  QComboBox* start_state;
  QComboBox* goal_state;
  QDoubleSpinBox* planning_time;
  QSpinBox* planning_attempts;
  QDoubleSpinBox* velocity_scaling_factor;
  QDoubleSpinBox* acceleration_scaling_factor;
  QCheckBox* allow_external_program;
  QPushButton* plan_button;
  QPushButton* execute_button;
  QPushButton* plan_and_execute_button;
  QPushButton* stop_button;
  QLabel* result_label;

  QDoubleSpinBox* box_size[3];
  QDoubleSpinBox* box_position[3];
  QPushButton* add_box_button;
  QListWidget* scene_objects;
  QPushButton* remove_object_button;
};
}  // namespace moveit_rviz_plugin
