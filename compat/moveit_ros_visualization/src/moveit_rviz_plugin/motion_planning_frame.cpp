/* The panel's widgets, with the ranges and defaults of MoveIt's
 * motion_planning_rviz_plugin_frame.ui (noetic-devel): planning time 5 s (up to 300),
 * 10 attempts (up to 1000), scaling factors 1.0 in steps of 0.1. */
#include "motion_planning_frame.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

namespace moveit_rviz_plugin
{
namespace
{
QDoubleSpinBox* spin(double low, double high, double step, double value, int decimals)
{
  auto* box = new QDoubleSpinBox;
  box->setRange(low, high);
  box->setSingleStep(step);
  box->setDecimals(decimals);
  box->setValue(value);
  return box;
}
}  // namespace

MotionPlanningFrame::MotionPlanningFrame(QWidget* parent) : QWidget(parent)
{
  auto* tabs = new QTabWidget;

  auto* planning = new QWidget;
  auto* form = new QFormLayout;
  planning_group = new QComboBox;
  start_state = new QComboBox;
  goal_state = new QComboBox;
  form->addRow("Planning Group:", planning_group);
  form->addRow("Start State:", start_state);
  form->addRow("Goal State:", goal_state);
  planning_time = spin(0.0, 300.0, 1.0, 5.0, 2);
  planning_attempts = new QSpinBox;
  planning_attempts->setRange(1, 1000);
  planning_attempts->setValue(10);
  velocity_scaling_factor = spin(0.0, 1.0, 0.1, 1.0, 2);
  acceleration_scaling_factor = spin(0.0, 1.0, 0.1, 1.0, 2);
  form->addRow("Planning Time (s):", planning_time);
  form->addRow("Planning Attempts:", planning_attempts);
  form->addRow("Velocity Scaling:", velocity_scaling_factor);
  form->addRow("Accel. Scaling:", acceleration_scaling_factor);
  allow_external_program = new QCheckBox("Allow External Comm.");
  form->addRow(allow_external_program);
  auto* buttons = new QGridLayout;
  plan_button = new QPushButton("Plan");
  execute_button = new QPushButton("Execute");
  execute_button->setEnabled(false);
  plan_and_execute_button = new QPushButton("Plan && Execute");
  stop_button = new QPushButton("Stop");
  buttons->addWidget(plan_button, 0, 0);
  buttons->addWidget(execute_button, 0, 1);
  buttons->addWidget(plan_and_execute_button, 1, 0);
  buttons->addWidget(stop_button, 1, 1);
  form->addRow(buttons);
  result_label = new QLabel;
  result_label->setWordWrap(true);
  form->addRow("Result:", result_label);
  planning->setLayout(form);
  tabs->addTab(planning, "Planning");

  auto* objects = new QWidget;
  auto* objects_layout = new QVBoxLayout;
  auto* box_form = new QGridLayout;
  const char* axes[3] = { "x", "y", "z" };
  box_form->addWidget(new QLabel("Box size (m):"), 0, 0);
  box_form->addWidget(new QLabel("Position (m):"), 1, 0);
  for (int i = 0; i < 3; ++i)
  {
    box_size[i] = spin(0.001, 10.0, 0.01, 0.1, 3);
    box_size[i]->setPrefix(QString(axes[i]) + " ");
    box_position[i] = spin(-100.0, 100.0, 0.05, i == 0 ? 0.3 : (i == 2 ? 0.05 : 0.0), 3);
    box_position[i]->setPrefix(QString(axes[i]) + " ");
    box_form->addWidget(box_size[i], 0, i + 1);
    box_form->addWidget(box_position[i], 1, i + 1);
  }
  objects_layout->addLayout(box_form);
  add_box_button = new QPushButton("Add Box");
  objects_layout->addWidget(add_box_button);
  scene_objects = new QListWidget;
  objects_layout->addWidget(scene_objects);
  remove_object_button = new QPushButton("Remove");
  objects_layout->addWidget(remove_object_button);
  objects->setLayout(objects_layout);
  tabs->addTab(objects, "Scene Objects");

  auto* layout = new QVBoxLayout;
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(tabs);
  setLayout(layout);
  setWindowTitle("MotionPlanning");
}
}  // namespace moveit_rviz_plugin
