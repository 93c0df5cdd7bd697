#!/usr/bin/env python3
"""Write scenarios/robots/nao_motoflex_2011/nao_motoflex_2011.urdf: the box robot of the 2011
MoToFlex program (seed 001), from the body table of ../shared/reference/nao.md §3.2.

The original builds the Nao from ODE boxes (`Nao::create`): torso, head and two rigid arms, per
leg a thigh, a tibia and a foot, each box with its total mass spread uniformly
(`dMassSetBoxTotal`, centre of mass at the box centre). The table gives every box's mass, size and
centre in world coordinates at the zero pose (legs straight, ground z = 0); the joint anchors are
hip (0, +-0.05, 0.246), knee (0, +-0.05, 0.146), ankle (0, +-0.05, 0.046). This script converts
those numbers into link frames at the joints (the Aldebaran convention our `nao` robot uses: torso
frame 85 mm above the hip-joint line, x forward, y left, z up) and computes each box's inertia.
The joint limits are the real Nao's (nao.md §1.2, the same numbers as scenarios/robots/nao), for
the walk planner's inverse kinematics; robot.yaml's `joint_stops: false` keeps them out of the
simulation (and of SDF/MJCF exports), as in the original, which has no joint stops
(motoflex_2011.md §2.10). The limits' effort and velocity are placeholders motoflex does not read.

Deterministic: the same bytes every run. Usage: make_nao_motoflex_2011_urdf.py [--out FILE]
"""
import argparse
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_OUT = os.path.join(ROOT, "scenarios", "robots", "nao_motoflex_2011",
                           "nao_motoflex_2011.urdf")

# World heights at the zero pose (nao.md §3.2).
TORSO_ORIGIN_Z = 0.331  # torso frame: bodyToRightHip (0, -0.05, -0.085) from here
HIP_Z = 0.246
KNEE_Z = 0.146
ANKLE_Z = 0.046
HIP_Y = 0.05
SHOULDER_Y = 0.098
SHOULDER_Z = 0.431
ARM_TILT_RAD = 0.35  # arms tilted outward about x
ARM_HALF_LENGTH = 0.0966

# name: (mass kg, size x y z m, centre in world at the zero pose, left side for legs/arms)
BOXES = {
    "torso": (1.217, (0.10, 0.11, 0.108), (-0.007829, 0.0, 0.331 + 0.046466)),
    "Head": (0.401, (0.08, 0.13, 0.087), (-0.000247, 0.0, 0.331 + 0.170899)),
    "Thigh": (0.533, (0.05, 0.05, 0.076), (-0.005579, HIP_Y, 0.046 + 0.100 + 0.062)),
    "Tibia": (0.423, (0.05, 0.05, 0.0618), (-0.000511, HIP_Y, 0.046 + 0.0309)),
    "Foot": (0.158, (0.157, 0.087, 0.032), (0.025, HIP_Y, 0.016)),
    "Arm": (0.25, (0.045, 0.045, 0.1932), None),  # centre: along the tilted arm, see below
}

# Aldebaran joint limits (rad), left leg; the right leg mirrors the rolls and has its own ankle
# pitch range (nao.md §1.2).
LEFT_LIMITS = {
    "HipRoll": (-0.379435, 0.79046),
    "HipPitch": (-1.53589, 0.48398),
    "KneePitch": (-0.0923279, 2.11255),
    "AnklePitch": (-1.18944, 0.922581),
    "AnkleRoll": (-0.397761, 0.768992),
}
RIGHT_LIMITS = {
    "HipRoll": (-0.79046, 0.379435),
    "HipPitch": (-1.53589, 0.48398),
    "KneePitch": (-0.0923279, 2.11255),
    "AnklePitch": (-1.1863, 0.932006),
    "AnkleRoll": (-0.768992, 0.397761),
}


def num(x):
    """Shortest text that keeps 9 significant digits, no '-0'."""
    text = "%.9g" % x
    return "0" if text in ("0", "-0") else text


def vec(v):
    return " ".join(num(x) for x in v)


def box_inertia(mass, size):
    x, y, z = size
    return (mass / 12.0 * (y * y + z * z), mass / 12.0 * (x * x + z * z),
            mass / 12.0 * (x * x + y * y))


def link(name, mass=None, size=None, centre=(0.0, 0.0, 0.0), comment=None, foot=False):
    lines = []
    if comment:
        lines.append("  <!-- %s -->" % comment)
    lines.append('  <link name="%s">' % name)
    if mass is not None:
        ixx, iyy, izz = box_inertia(mass, size)
        lines += [
            "    <inertial>",
            '      <origin xyz="%s" rpy="0 0 0"/>' % vec(centre),
            '      <mass value="%s"/>' % num(mass),
            '      <inertia ixx="%s" ixy="0" ixz="0" iyy="%s" iyz="0" izz="%s"/>' %
            (num(ixx), num(iyy), num(izz)),
            "    </inertial>",
            "    <collision>",
            '      <origin xyz="%s" rpy="0 0 0"/>' % vec(centre),
            '      <geometry><box size="%s"/></geometry>' % vec(size),
            "    </collision>",
        ]
    lines.append("  </link>")
    return lines


def joint(name, kind, parent, child, origin, rpy=(0.0, 0.0, 0.0), axis=None, limits=None):
    lines = ['  <joint name="%s" type="%s">' % (name, kind),
             '    <parent link="%s"/>' % parent, '    <child link="%s"/>' % child,
             '    <origin xyz="%s" rpy="%s"/>' % (vec(origin), vec(rpy))]
    if axis is not None:
        lines.append('    <axis xyz="%s"/>' % vec(axis))
    if limits is not None:
        lines.append('    <limit lower="%s" upper="%s" effort="100" velocity="10"/>' %
                     (num(limits[0]), num(limits[1])))
    lines.append("  </joint>")
    return lines


def local(world_centre, frame_z, side_y=0.0):
    """A world point at the zero pose in a link frame at (0, side_y, frame_z), axes = world."""
    return (world_centre[0], world_centre[1] - side_y if side_y else world_centre[1],
            world_centre[2] - frame_z)


def leg(side):
    s = 1.0 if side == "L" else -1.0
    low = side.lower()
    limits = LEFT_LIMITS if side == "L" else RIGHT_LIMITS
    y = s * HIP_Y
    out = []
    out += joint(side + "HipRoll", "revolute", "torso", side + "Hip",
                 (0.0, y, HIP_Z - TORSO_ORIGIN_Z), axis=(1, 0, 0), limits=limits["HipRoll"])
    out += link(side + "Hip", comment="massless: lumped into the thigh (hip universal joint)")
    out += joint(side + "HipPitch", "revolute", side + "Hip", side + "Thigh", (0.0, 0.0, 0.0),
                 axis=(0, 1, 0), limits=limits["HipPitch"])
    m, size, c = BOXES["Thigh"]
    out += link(side + "Thigh", m, size, local((c[0], s * c[1], c[2]), HIP_Z, y),
                comment="thigh box: centre (%s, %s, %s) m at the zero pose; flexible, split at "
                "half the hip-knee span" % (num(c[0]), num(s * c[1]), num(c[2])))
    out += joint(side + "KneePitch", "revolute", side + "Thigh", side + "Tibia",
                 (0.0, 0.0, KNEE_Z - HIP_Z), axis=(0, 1, 0), limits=limits["KneePitch"])
    m, size, c = BOXES["Tibia"]
    out += link(side + "Tibia", m, size, local((c[0], s * c[1], c[2]), KNEE_Z, y),
                comment="tibia box: centre (%s, %s, %s) m at the zero pose; flexible" %
                (num(c[0]), num(s * c[1]), num(c[2])))
    out += joint(side + "AnklePitch", "revolute", side + "Tibia", side + "Ankle",
                 (0.0, 0.0, ANKLE_Z - KNEE_Z), axis=(0, 1, 0), limits=limits["AnklePitch"])
    out += link(side + "Ankle", comment="massless: lumped into the foot (ankle universal joint)")
    out += joint(side + "AnkleRoll", "revolute", side + "Ankle", low + "_foot", (0.0, 0.0, 0.0),
                 axis=(1, 0, 0), limits=limits["AnkleRoll"])
    m, size, c = BOXES["Foot"]
    out += link(low + "_foot", m, size, local((c[0], s * c[1], c[2]), ANKLE_Z, y),
                comment="foot box (\"correct foot size\"), bottom face on the ground (z = 0) at "
                "the zero pose; the only box that may touch the ground")
    return out


def arm(side):
    s = 1.0 if side == "L" else -1.0
    tilt = s * ARM_TILT_RAD
    m, size, _ = BOXES["Arm"]
    out = joint(side + "Shoulder", "fixed", "torso", side + "Arm",
                (0.0, s * SHOULDER_Y, SHOULDER_Z - TORSO_ORIGIN_Z), rpy=(tilt, 0.0, 0.0))
    # Rotating the arm frame by +-0.35 rad about x puts the box centre, 0.0966 m down the arm,
    # at (0, +-(0.098 + sin 0.35 * 0.0966), 0.431 - cos 0.35 * 0.0966), the table's value.
    out += link(side + "Arm", m, size, (0.0, 0.0, -ARM_HALF_LENGTH),
                comment="rigid arm, tilted %s rad about x" % num(tilt))
    return out


def urdf():
    m, size, c = BOXES["torso"]
    lines = [
        '<?xml version="1.0"?>',
        "<!-- The box robot of the 2011 MoToFlex program (seed 001) for motoflex, written by",
        "     scripts/make_nao_motoflex_2011_urdf.py from the body table of",
        "     shared/reference/nao.md section 3.2 (masses, box sizes, box centres at the zero",
        "     pose). Each box carries its mass uniformly (CoM at the box centre). Frames: x forward,",
        "     y left, z up; every joint frame parallel to the torso frame at the zero pose (legs",
        "     straight, feet flat, box bottoms at z = 0 when the torso frame is 0.331 m up).",
        "     Total mass 4.346 kg. Do not edit: regenerate. -->",
        '<robot name="nao_motoflex_2011">',
    ]
    lines += link("torso", m, size, local(c, TORSO_ORIGIN_Z),
                  comment="root link; frame origin 0.085 m above the hip-joint line "
                  "(bodyToRightHip), torso box centre (%s, 0, %s) m at the zero pose" %
                  (num(c[0]), num(c[2])))
    m, size, c = BOXES["Head"]
    lines += joint("HeadFixed", "fixed", "torso", "Head", (0.0, 0.0, 0.0))
    lines += link("Head", m, size, local(c, TORSO_ORIGIN_Z), comment="rigid head")
    lines += arm("L") + arm("R")
    lines += ["  <!-- left leg: hip universal (roll x, then pitch y), knee hinge (y), ankle "
              "universal (pitch y, then roll x) -->"]
    lines += leg("L")
    lines += ["  <!-- right leg -->"]
    lines += leg("R")
    lines.append("</robot>")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=DEFAULT_OUT)
    args = parser.parse_args()
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(urdf())
    total = sum(BOXES[k][0] for k in ("torso", "Head")) + 2 * sum(
        BOXES[k][0] for k in ("Thigh", "Tibia", "Foot", "Arm"))
    print("wrote %s (%.3f kg)" % (args.out, total))


if __name__ == "__main__":
    main()
