"""Reading robot descriptions: URDF parsing, xacro expansion, kinematics, inertia formulas."""
from urdf_tools.model import (Geometry, Inertial, Joint, Link, Mimic, Origin, RobotModel,
                              UrdfError, load_urdf, parse_urdf)

__all__ = ["Geometry", "Inertial", "Joint", "Link", "Mimic", "Origin", "RobotModel",
           "UrdfError", "load_urdf", "parse_urdf"]
