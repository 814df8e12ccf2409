"""The crafted arguments of urdf_tools.xacro_arguments against the pattern that pastes an
argument into expression text. xacro 1.13 ran the first (the marker file appeared); Noetic's
language (xacro 1.14 and the 2.x the workspace runs) refuses names with double underscores,
which that argument needs to reach os.system, and says so."""
from urdf_tools.xacro_arguments import crafted_arguments, run_xacro

OLD_PATTERN = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
               '<xacro:arg name="config" default="none.yaml"/>'
               "<xacro:property name=\"c\" value=\"${load_yaml('$(arg config)')}\"/>"
               '<link name="${c}"/></robot>')


def test_the_old_pattern_is_refused_naming_the_double_underscore_names(tmp_path):
    marker = tmp_path / "pwned"
    old = tmp_path / "old.xacro"
    old.write_text(OLD_PATTERN)
    result = run_xacro(str(old), "config", crafted_arguments(str(marker))[0])
    assert result.returncode != 0
    assert "Use of invalid name(s):  __class__, __base__" in result.stderr
    assert not marker.exists()
