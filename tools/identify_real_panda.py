#!/usr/bin/env python3
"""`massprops identify` on a real robot's recording, against a paper's published parameters
(issue 51; docs/identify.md, "A real robot").

The recording: Trajectory_1 of Gaz, Cognetti, Oliva, Robuffo Giordano and De Luca, "Dynamic
Identification of the Franka Emika Panda Robot With Retrieval of Feasible Parameters Using
Penalty-Based Optimization", IEEE RA-L 4(4), 2019: joint positions, velocities and link-side
torques of a Franka Emika Panda logged at about 1 kHz for 21 s along one of their exciting
trajectories, published (GPL-3.0) in github.com/marcocognetti/FrankaEmikaPandaDynModel,
matlab/data/Exciting_Traj/Trajectory_1/rbt_log/. It is not copied here: give the folder of a
checkout of that repository. Nothing here was tuned on it.

The paper's parameters: the masses, centers of mass and inertias of its supplementary material
(tables VIII and IX), which example-robot-data's panda.urdf in ../shared/corpus carries for
panda_link1..7 (checked below, number by number, against the values typed from the tables; the
file adds a hand of 0.73 kg and two fingers). Two models are judged:
  arm.urdf       the file's links 1..7 alone (the paper's arm: no hand);
  arm_hand.urdf  the file as written, its finger joints fixed (the data has no fingers).

  tools/identify_real_panda.py TOOL REPO [--shared ../shared] [--work DIR]

REPO is a checkout (`git clone https://github.com/marcocognetti/FrankaEmikaPandaDynModel`). The
log is written as the CSV identify reads, as recorded: its stamps are irregular (0.7 to 8.8 ms
apart), so identify interpolates it onto a uniform grid at the median interval (1 ms) before it
derives the accelerations from the velocities, and says so. Prints, per model, the held-out torque
RMS per joint (the last 30% of the recording) of the file's values, of ordinary least squares and
of the consistent fit, and what `check --data` says."""
import argparse
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

LOG = "matlab/data/Exciting_Traj/Trajectory_1/rbt_log"
JOINTS = [f"panda_joint{i}" for i in range(1, 8)]

# Tables VIII and IX of the paper's supplementary material (link i: mass kg; center of mass m in
# the link frame; inertia about the center of mass, kg m^2, ixx ixy ixz iyy iyz izz).
PAPER = {
    1: (4.970684, (3.875e-03, 2.081e-03, None),
        (7.0337e-01, -1.3900e-04, 6.7720e-03, 7.0661e-01, 1.9169e-02, 9.1170e-03)),
    2: (0.646926, (-3.141e-03, -2.872e-02, 3.495e-03),
        (7.9620e-03, -3.9250e-03, 1.0254e-02, 2.8110e-02, 7.0400e-04, 2.5995e-02)),
    3: (3.228604, (2.7518e-02, 3.9252e-02, -6.6502e-02),
        (3.7242e-02, -4.7610e-03, -1.1396e-02, 3.6155e-02, -1.2805e-02, 1.0830e-02)),
    4: (3.587895, (-5.317e-02, 1.04419e-01, 2.7454e-02),
        (2.5853e-02, 7.7960e-03, -1.3320e-03, 1.9552e-02, 8.6410e-03, 2.8323e-02)),
    5: (1.225946, (-1.1953e-02, 4.1065e-02, -3.8437e-02),
        (3.5549e-02, -2.1170e-03, -4.0370e-03, 2.9474e-02, 2.2900e-04, 8.6270e-03)),
    6: (1.666555, (6.0149e-02, -1.4117e-02, -1.0517e-02),
        (1.9640e-03, 1.0900e-04, -1.1580e-03, 4.3540e-03, 3.4100e-04, 5.4330e-03)),
    7: (7.35522e-01, (1.0517e-02, -4.252e-03, 6.1597e-02),
        (1.2516e-02, -4.2800e-04, -1.1960e-03, 1.0027e-02, -7.4100e-04, 4.8150e-03)),
}
# Link 1's center of mass height (None above): the paper gives 0, the file -0.04762; along joint
# 1's axis it moves no joint torque of a fixed base, so neither value can be told from data.


def read_numbers(path):
    with open(path) as f:
        return [float(word) for word in f.read().split()]


def write_csv(repo, path):
    folder = os.path.join(repo, LOG)
    times = read_numbers(os.path.join(folder, "exciting_traj_time.txt"))
    series = [read_numbers(os.path.join(folder, f"exciting_traj_{name}.txt"))
              for name in ("positions", "velocity", "torques")]
    n = len(times)
    if any(len(s) != 7 * n for s in series):
        sys.exit("the log's files do not hold 7 values per time stamp")
    with open(path, "w") as f:
        header = ["time"] + [f"{j}.{c}" for c in ("q", "dq", "tau") for j in JOINTS]
        f.write(",".join(header) + "\n")
        for i, t in enumerate(times):
            row = sum((s[7 * i:7 * i + 7] for s in series), [])
            f.write(",".join([repr(t)] + [repr(v) for v in row]) + "\n")
    return n, times[-1] - times[0]


def check_paper_values(robot):
    """The file's links 1..7 carry the paper's numbers (to their printed digits)."""
    for i, (mass, com, inertia) in PAPER.items():
        inertial = robot.find(f"link[@name='panda_link{i}']/inertial")
        if abs(float(inertial.find("mass").get("value")) - mass) > 1e-9:
            sys.exit(f"panda_link{i}: the file's mass is not the paper's")
        xyz = [float(v) for v in inertial.find("origin").get("xyz").split()]
        for got, want in zip(xyz, com):
            if want is not None and abs(got - want) > 1e-9:
                sys.exit(f"panda_link{i}: the file's center of mass is not the paper's")
        tensor = inertial.find("inertia")
        names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
        if any(abs(float(tensor.get(k)) - v) > 1e-9 for k, v in zip(names, inertia)):
            sys.exit(f"panda_link{i}: the file's inertia is not the paper's")


def write_models(shared, work):
    source = os.path.join(shared, "corpus/example-robot-data/robots/panda_description/urdf/"
                          "panda.urdf")
    tree = ET.parse(source)
    robot = tree.getroot()
    check_paper_values(robot)
    for link in robot.findall("link"):  # the meshes are not needed (no geometry rule is asked)
        for tag in ("visual", "collision"):
            for element in link.findall(tag):
                link.remove(element)
    for joint in robot.findall("joint"):
        if joint.get("name").startswith("panda_finger_joint"):
            joint.set("type", "fixed")
            for tag in ("limit", "axis", "dynamics", "mimic"):
                for element in joint.findall(tag):
                    joint.remove(element)
    hand = os.path.join(work, "arm_hand.urdf")
    tree.write(hand)
    keep = {f"panda_link{i}" for i in range(0, 8)}
    for link in list(robot.findall("link")):
        if link.get("name") not in keep:
            robot.remove(link)
    for joint in list(robot.findall("joint")):
        if joint.find("child").get("link") not in keep:
            robot.remove(joint)
    arm = os.path.join(work, "arm.urdf")
    tree.write(arm)
    return [("arm (the paper's links 1..7)", arm), ("arm + hand (the file)", hand)]


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tool")
    parser.add_argument("repo", help="a checkout of marcocognetti/FrankaEmikaPandaDynModel")
    parser.add_argument("--shared", default=os.path.join(os.path.dirname(__file__),
                                                         "../../shared"))
    parser.add_argument("--work", default="panda_real")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    data = os.path.join(args.work, "trajectory_1.csv")
    samples, seconds = write_csv(args.repo, data)
    print(f"recording: {samples} samples over {seconds:.2f} s")
    for label, model in write_models(args.shared, args.work):
        code, out, err = run([args.tool, "identify", model, data, "--format", "json"])
        if code != 0:
            print(f"{label}: identify exited {code}: {err.strip()}")
            continue
        report = json.loads(out)
        print(f"\n{label}: {model}")
        ident = report["identifiability"]
        print(f"  rank {ident['rank']} of {ident['parameters']}, condition number "
              f"{ident['condition_number']:.3g}, unexcited: {ident['unexcited_links']}")
        print("  | joint | RMS file | RMS least squares | RMS identified |")
        print("  |---|---:|---:|---:|")
        for joint in report["joints"]:
            print(f"  | {joint['joint']} | {joint['rms_file']:.3f} | "
                  f"{joint['rms_least_squares']:.3f} | {joint['rms_identified']:.3f} |")
        print(f"  least squares: {report['inconsistent_least_squares_links']} inconsistent links")
        for link in report["links"]:
            print(f"  {link['link']}: mass {link['file']['mass']:.4g} -> "
                  f"{link['identified']['mass']:.4g} kg")
        code, out, _ = run([args.tool, "check", "--quiet", "--no-geometry", "--data", data,
                            model])
        findings = [line for line in out.splitlines() if "inertia-contradicts-data" in line]
        print(f"  check --data: exit {code}; {findings[0] if findings else 'no finding'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
