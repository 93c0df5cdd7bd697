#!/usr/bin/env python3
"""Writes the small meshes motoflex's tests and bundled example robot use (no dependencies).

Shapes: a box (any size), a cone, an icosphere (many vertices: tests the hull decimation), a
concave U block (tests trimeshes), as binary STL, ASCII STL, OBJ or COLLADA (DAE, with a
<unit meter> and <up_axis> to test that the unit is applied and the up axis is not). Every file is
written deterministically, so regenerating leaves git clean.

Usage:
  scripts/make_meshes.py --tests    # tests/data/meshes/, tests/data/robots/quadruped/meshes/
  scripts/make_meshes.py --example  # scenarios/robots/mini_arm/meshes/
  scripts/make_meshes.py --third-party  # tests/data/robots/third_party/*_description/meshes/
  scripts/make_meshes.py --all
"""
import argparse
import math
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def box(sx, sy, sz, center=(0.0, 0.0, 0.0)):
    """Vertices and outward counter-clockwise triangles of a box of full edge lengths sx, sy, sz."""
    cx, cy, cz = center
    v = [(cx + (sx / 2 if i & 1 else -sx / 2), cy + (sy / 2 if i & 2 else -sy / 2),
          cz + (sz / 2 if i & 4 else -sz / 2)) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for a, b, c, d in quads:
        tris += [(a, b, c), (a, c, d)]
    return v, tris


def cone(radius, height, segments=24):
    """A cone standing on its base disc (z = 0) with the apex at z = height."""
    v = [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    for k in range(segments):
        a = 2 * math.pi * k / segments
        v.append((radius * math.cos(a), radius * math.sin(a), 0.0))
    tris = []
    for k in range(segments):
        i, j = 2 + k, 2 + (k + 1) % segments
        tris.append((0, j, i))  # base, seen from below
        tris.append((1, i, j))  # side
    return v, tris


def icosphere(radius, subdivisions):
    t = (1 + math.sqrt(5)) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
         (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
            (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
            (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                p = [(x + y) / 2 for x, y in zip(v[a], v[b])]
                n = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / n for x in p))
                cache[key] = len(v) - 1
            return cache[key]

        new = []
        for a, b, c in tris:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = new
    # Exact poles and equator points so the extremes are known to the last bit.
    v = [tuple(radius * c for c in p) for p in v]
    return v, tris


def u_block(width, depth, height, wall):
    """A U-shaped block (concave): two walls of thickness `wall` on a base slab, open on top."""
    parts = [box(width, depth, wall, (0, 0, wall / 2)),
             box(wall, depth, height - wall, (-(width - wall) / 2, 0, wall + (height - wall) / 2)),
             box(wall, depth, height - wall, ((width - wall) / 2, 0, wall + (height - wall) / 2))]
    v, tris = [], []
    for pv, pt in parts:
        base = len(v)
        v += pv
        tris += [(a + base, b + base, c + base) for a, b, c in pt]
    return v, tris


def normal(v, t):
    a, b, c = (v[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return tuple(x / length for x in n)


def write_stl_binary(path, v, tris):
    with open(path, "wb") as f:
        f.write(b"motoflex make_meshes.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(v, t)))
            for i in t:
                f.write(struct.pack("<3f", *v[i]))
            f.write(struct.pack("<H", 0))


def write_stl_ascii(path, v, tris):
    with open(path, "w", encoding="ascii") as f:
        f.write("solid motoflex\n")
        for t in tris:
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % normal(v, t))
            for i in t:
                f.write("      vertex %.9g %.9g %.9g\n" % v[i])
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid motoflex\n")


def write_obj(path, v, tris):
    with open(path, "w", encoding="ascii") as f:
        f.write("# motoflex make_meshes.py\n")
        for p in v:
            f.write("v %.9g %.9g %.9g\n" % p)
        for a, b, c in tris:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def write_dae(path, v, tris, unit_m, up_axis):
    """COLLADA 1.4 with one triangle mesh; coordinates in units of `unit_m` metres."""
    positions = " ".join("%.9g %.9g %.9g" % p for p in v)
    indices = " ".join("%d %d %d" % t for t in tris)
    with open(path, "w", encoding="ascii") as f:
        f.write(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="unit" meter="{unit_m}"/><up_axis>{up_axis}</up_axis></asset>
  <library_geometries>
    <geometry id="shape" name="shape">
      <mesh>
        <source id="shape-positions">
          <float_array id="shape-positions-array" count="{3 * len(v)}">{positions}</float_array>
          <technique_common>
            <accessor source="#shape-positions-array" count="{len(v)}" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="shape-vertices"><input semantic="POSITION" source="#shape-positions"/></vertices>
        <triangles count="{len(tris)}">
          <input semantic="VERTEX" source="#shape-vertices" offset="0"/>
          <p>{indices}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="node" name="node"><instance_geometry url="#shape"/></node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
""")


def scaled(v, s):
    return [tuple(s * c for c in p) for p in v]


def make_tests(out):
    os.makedirs(out, exist_ok=True)
    v, t = box(0.1, 0.1, 0.1)
    write_stl_binary(os.path.join(out, "cube_100mm.stl"), v, t)
    write_obj(os.path.join(out, "cube_100mm.obj"), v, t)
    # The same cube in millimetres, Z up: the unit must be applied, the up axis not.
    write_dae(os.path.join(out, "cube_100mm_in_mm.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    # A cube in millimetres for a URDF <mesh scale="0.001 0.001 0.001">.
    write_stl_ascii(os.path.join(out, "cube_mm_ascii.stl"), scaled(v, 1000.0), t)
    v, t = cone(0.05, 0.08)
    write_stl_binary(os.path.join(out, "cone.stl"), v, t)
    # The cone in millimetres with its apex up +z, declared Z_UP: read as the URDF means it,
    # the apex stays on +z (converting to Y up would lay it along y).
    write_dae(os.path.join(out, "cone_in_mm.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = icosphere(0.05, 3)  # 642 vertices
    write_stl_binary(os.path.join(out, "icosphere_642.stl"), v, t)
    v, t = u_block(0.12, 0.06, 0.06, 0.02)
    write_stl_binary(os.path.join(out, "u_block.stl"), v, t)
    # The quadruped's feet and trunk (tests/data/robots/quadruped, found through package://).
    quad = os.path.join(os.path.dirname(out), "robots", "quadruped", "meshes")
    os.makedirs(quad, exist_ok=True)
    v, t = icosphere(0.02, 2)  # 162 vertices
    write_stl_binary(os.path.join(quad, "foot.stl"), v, t)
    v, t = box(0.3, 0.2, 0.1)
    write_stl_binary(os.path.join(quad, "trunk_visual.stl"), v, t)
    # A flat square (no volume): no convex hull.
    write_obj(os.path.join(out, "flat_square.obj"),
              [(-0.05, -0.05, 0), (0.05, -0.05, 0), (0.05, 0.05, 0), (-0.05, 0.05, 0)],
              [(0, 1, 2), (0, 2, 3)])


def make_example(out):
    """The mini_arm's links: a base plate, a turntable, two links and a gripper block."""
    os.makedirs(out, exist_ok=True)
    v, t = box(0.12, 0.12, 0.03, (0, 0, 0.015))
    write_stl_binary(os.path.join(out, "base.stl"), v, t)
    v, t = cone(0.04, 0.05)
    write_stl_binary(os.path.join(out, "turntable.stl"), v, t)
    v, t = box(0.03, 0.04, 0.12, (0, 0, 0.06))
    write_stl_binary(os.path.join(out, "upper_arm.stl"), v, t)
    v, t = box(0.025, 0.035, 0.10, (0, 0, 0.05))
    write_stl_binary(os.path.join(out, "forearm.stl"), v, t)
    v, t = u_block(0.05, 0.03, 0.04, 0.01)
    write_stl_binary(os.path.join(out, "gripper.stl"), v, t)


def make_third_party(out):
    """Meshes of the two third-party-style robots (tests/data/robots/third_party): a desk arm
    and a quadruped, each a ROS-style package whose URDF finds them through package://. As CAD
    exporters write them: some STL in metres, some COLLADA in millimetres (<unit meter=0.001>),
    each in its link's frame."""
    arm = os.path.join(out, "desk_arm_description", "meshes")
    os.makedirs(os.path.join(arm, "visual"), exist_ok=True)
    v, t = box(0.10, 0.10, 0.04, (0, 0, 0.02))
    write_stl_binary(os.path.join(arm, "base_link.stl"), v, t)
    v, t = box(0.05, 0.045, 0.04, (0, 0, 0.02))
    write_dae(os.path.join(arm, "shoulder_link.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = box(0.03, 0.035, 0.11, (0, 0, 0.055))
    write_stl_binary(os.path.join(arm, "upper_arm_link.stl"), v, t)
    v, t = box(0.025, 0.03, 0.10, (0, 0, 0.05))
    write_dae(os.path.join(arm, "lower_arm_link.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = cone(0.018, 0.04)
    write_stl_ascii(os.path.join(arm, "wrist_link.stl"), v, t)
    v, t = u_block(0.05, 0.03, 0.04, 0.01)
    write_dae(os.path.join(arm, "gripper_link.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = box(0.008, 0.02, 0.04, (0, 0, 0.02))
    write_stl_binary(os.path.join(arm, "jaw_link.stl"), v, t)
    v, t = icosphere(0.012, 2)
    write_stl_binary(os.path.join(arm, "visual", "camera.stl"), v, t)

    quad = os.path.join(out, "quad12_description", "meshes")
    os.makedirs(quad, exist_ok=True)
    v, t = box(0.40, 0.20, 0.10)
    write_dae(os.path.join(quad, "trunk.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = box(0.06, 0.05, 0.05)
    write_stl_binary(os.path.join(quad, "hip.stl"), v, t)
    v, t = box(0.035, 0.03, 0.16, (0, 0, -0.08))
    write_dae(os.path.join(quad, "thigh.dae"), scaled(v, 1000.0), t, 0.001, "Z_UP")
    v, t = box(0.02, 0.02, 0.15, (0, 0, -0.075))
    write_stl_binary(os.path.join(quad, "shank.stl"), v, t)
    v, t = icosphere(0.02, 2)  # 162 vertices: decimated to the hull limit
    write_stl_binary(os.path.join(quad, "foot.stl"), v, t)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tests", action="store_true")
    parser.add_argument("--example", action="store_true")
    parser.add_argument("--third-party", action="store_true")
    parser.add_argument("--all", action="store_true")
    args = parser.parse_args()
    if args.tests or args.all:
        make_tests(os.path.join(ROOT, "tests", "data", "meshes"))
    if args.example or args.all:
        make_example(os.path.join(ROOT, "scenarios", "robots", "mini_arm", "meshes"))
    if args.third_party or args.all:
        make_third_party(os.path.join(ROOT, "tests", "data", "robots", "third_party"))


if __name__ == "__main__":
    main()
