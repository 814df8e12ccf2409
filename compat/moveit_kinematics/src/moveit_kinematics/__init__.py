"""MoveIt's kinematics solvers: KDL's for chain groups (see kdl_solver)."""
