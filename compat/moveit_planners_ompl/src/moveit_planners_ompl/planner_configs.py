"""The ``ompl_planning.yaml`` a config package loads: ``planner_configs`` (a name, an OMPL
``type`` such as ``geometric::RRTConnect`` and its parameters) and, per group,
``default_planner_config``, ``planner_configs``, ``longest_valid_segment_fraction``,
``projection_evaluator``. PyPI's OMPL 2.0 has RRTConnect, RRT, RRTstar, PRM, PRMstar,
KPIECE1, BKPIECE1, LBKPIECE1, FMT and BFMT (and a few newer ones), and sets a parameter
only through the planner's setter (``range`` through ``setRange``). A planner type it
lacks, or a parameter it has no setter for, is logged once and RRTConnect (or the
planner's default value) used instead."""
from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Dict, Mapping

from ompl import geometric as og

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.move_group")

DEFAULT_PLANNER = "geometric::RRTConnect"
LONGEST_VALID_SEGMENT_FRACTION = 0.005   # MoveIt's default: of the space's extent
# OMPL class names where Setup-Assistant configs use other names
PLANNER_CLASSES = {"KPIECE": "KPIECE1", "BKPIECE": "BKPIECE1", "LBKPIECE": "LBKPIECE1"}


@dataclass
class GroupPlanning:
    planner: str = DEFAULT_PLANNER                     # an OMPL type, geometric::<Name>
    parameters: Dict[str, str] = field(default_factory=dict)
    longest_valid_segment_fraction: float = LONGEST_VALID_SEGMENT_FRACTION
    planner_ids: tuple = ()                            # the names the group offers


class PlannerConfigs:
    """``ompl_planning.yaml`` as loaded under move_group's namespace."""

    def __init__(self, values: Mapping):
        self.values = values or {}
        self.configs: Mapping = self.values.get("planner_configs", {}) or {}
        self._said = set()

    def group(self, group: str, planner_id: str = "") -> GroupPlanning:
        """The group's planner: ``planner_id`` (a config name, ``group[name]`` or an OMPL
        type) or the group's ``default_planner_config``, else RRTConnect."""
        entry = self.values.get(group, {}) or {}
        fraction = float(entry.get("longest_valid_segment_fraction",
                                   LONGEST_VALID_SEGMENT_FRACTION))
        offered = tuple(entry.get("planner_configs", []) or ())
        name = planner_id.split("[")[-1].rstrip("]") if planner_id else \
            entry.get("default_planner_config", "")
        if not name:
            return GroupPlanning(longest_valid_segment_fraction=fraction, planner_ids=offered)
        config = self.configs.get(name)
        if config is None:
            if name.startswith("geometric::"):
                return GroupPlanning(name, {}, fraction, offered)
            self._say(f"group '{group}': no planner config '{name}' in planner_configs; "
                      f"planning with {DEFAULT_PLANNER}")
            return GroupPlanning(longest_valid_segment_fraction=fraction, planner_ids=offered)
        parameters = {k: str(v) for k, v in config.items() if k != "type"}
        return GroupPlanning(config.get("type", DEFAULT_PLANNER), parameters, fraction, offered)

    def planner_ids(self):
        return sorted(self.configs)

    def make(self, choice: GroupPlanning, information):
        """The OMPL planner object of ``choice`` for ``information``."""
        name = choice.planner.split("::")[-1]
        cls = getattr(og, PLANNER_CLASSES.get(name, name), None)
        if cls is None:
            self._say(f"OMPL here has no planner '{choice.planner}'; planning with "
                      f"{DEFAULT_PLANNER}")
            cls = og.RRTConnect
        planner = cls(information)
        for key, value in choice.parameters.items():
            setter = getattr(planner, "set" + "".join(w.capitalize() for w in key.split("_")),
                             None)
            if setter is None:
                self._say(f"planner '{choice.planner}': parameter '{key}' cannot be set in "
                          "this OMPL: its default kept")
                continue
            try:
                setter(float(value))
            except (TypeError, ValueError) as error:
                self._say(f"planner '{choice.planner}': parameter '{key}' = '{value}' was "
                          f"refused ({error}): its default kept")
        return planner

    def _say(self, message: str) -> None:
        if message not in self._said:
            self._said.add(message)
            LOG.warning(message)
