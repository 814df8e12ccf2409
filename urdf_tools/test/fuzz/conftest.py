"""The fuzz tier's set-up for urdf_tools: the shared strategies and Hypothesis' profiles
(see description_fuzz.py)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from description_fuzz import register_profiles  # noqa: E402

register_profiles()
