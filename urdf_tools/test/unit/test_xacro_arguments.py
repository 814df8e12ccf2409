"""The crafted arguments of urdf_tools.xacro_arguments can see the fault they are for: the
first runs through the pattern that pastes an argument into expression text."""
from urdf_tools.xacro_arguments import crafted_arguments, run_xacro

OLD_PATTERN = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
               '<xacro:arg name="config" default="none.yaml"/>'
               "<xacro:property name=\"c\" value=\"${load_yaml('$(arg config)')}\"/>"
               '<link name="${c}"/></robot>')


def test_the_old_pattern_runs_the_argument(tmp_path):
    marker = tmp_path / "pwned"
    old = tmp_path / "old.xacro"
    old.write_text(OLD_PATTERN)
    result = run_xacro(str(old), "config", crafted_arguments(str(marker))[0])
    assert marker.exists(), result.stderr
