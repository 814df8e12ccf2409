"""Expected link poses for test_robot_model_cpp, by urdf_tools' forward kinematics (independent of the C++ model).

argv: URDF path, base link, states file (one state a line: "joint=value joint=value ..."), links file (one name a
line). Prints, for each state and each link, the 12 numbers of the link's pose in the base link's frame (3x4, rows)."""
import sys

from urdf_tools.kinematics import link_transform
from urdf_tools.model import load_urdf


def main():
    urdf_path, base, states_path, links_path = sys.argv[1:5]
    model = load_urdf(urdf_path)
    with open(links_path, encoding="utf-8") as stream:
        links = [line.strip() for line in stream if line.strip()]
    with open(states_path, encoding="utf-8") as stream:
        for line in stream:
            positions = dict((k, float(v)) for k, v in (item.split("=") for item in line.split()))
            for link in links:
                pose = link_transform(model, base, link, positions)
                print(" ".join(repr(float(x)) for x in pose[:3, :].flatten()))


if __name__ == "__main__":
    main()
