"""Nodes that the robot packages' display launch files share."""
