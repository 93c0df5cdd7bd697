#!/usr/bin/env python3
"""The README's two walk tables, from the tests that measure them.

Table 1: the eight walks of scenarios/walks/ on the rigid Nao with ideal servos (test
NaoWalk.RigidNaoWalksAtTheCommandedSpeed, fast tier). Table 2: the recorded walks (and the two
long-step walks not recorded) on ideal servos and on the MoToFlex truth model (test
NaoWalkDistance.ReferenceWalksOnIdealServosAndOnTheTruthModel, slow tier). Both tests print one
line per walk; this script runs them, reads those lines and writes OUT/report.md (the tables)
and OUT/walks.json. A walk that went more sideways than forward shows its sideways travel
instead of a speed; a walk that fell shows when.

    scripts/walk_tables.py [--build build] [--out benchmarks/walks]
"""
import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WALK = re.compile(r"^\[ walk\s*\]\s*(\d+) mm/s, (\d) s( toe/heel)?:\s*(\d+) steps of ([\d.]+) m, "
                  r"total ([-\d.]+) m, steady ([-\d.]+) mm/s \((\d+) %\), whole walking phase "
                  r"([-\d.]+) mm/s")
DISTANCE = re.compile(r"^\[ distance \]\s*(\S+)\s+Nao walk (\d+) mm/s, step duration (\d) s\s+"
                      r"([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-+\d.]+)\s+(.*)$")
FELL = re.compile(r"fell at ([\d.]+) s")


def minus(text):
    """Typographic minus, as the README writes negative numbers."""
    return text.replace("-", "\u2212")


def run_test(binary, test_filter):
    run = subprocess.run([binary, f"--gtest_filter={test_filter}"], capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"walk_tables: {binary} --gtest_filter={test_filter} failed:\n{run.stdout[-2000:]}")
    return run.stdout.splitlines()


def walk_label(speed, duration, toe_heel):
    return f"{speed} mm/s, {duration} s" + (", toe-off + heel strike" if toe_heel else "")


def ideal_rows(lines):
    rows = []
    for line in lines:
        m = WALK.match(line)
        if m:
            rows.append({"walk": walk_label(m[1], m[2], m[3]), "step_m": float(m[5]),
                         "distance_m": float(m[6]), "steady_mm_s": float(m[7]),
                         "steady_percent": int(m[8]), "mean_mm_s": float(m[9])})
    return rows


def distance_rows(lines):
    rows = []
    for line in lines:
        m = DISTANCE.match(line)
        if m:
            fell = FELL.search(m[9])
            rows.append({"recording": m[1], "speed_mm_s": int(m[2]), "step_s": int(m[3]),
                         "ideal_m": float(m[4]), "ideal_mm_s": float(m[5]),
                         "truth_m": float(m[6]), "truth_mm_s": float(m[7]),
                         "truth_sideways_m": float(m[8]),
                         "truth_fell_s": float(fell[1]) if fell else None})
    return rows


def truth_cell(r):
    metres = minus(f"{r['truth_m']:.3f}")
    if r["truth_fell_s"] is not None:
        return f"falls at {r['truth_fell_s']:.2f} s after {metres} m"
    if abs(r["truth_sideways_m"]) > abs(r["truth_m"]):
        return f"{metres} m ({abs(r['truth_sideways_m']):.3f} m sideways)"
    return f"{metres} m, " + minus(f"{r['truth_mm_s']:.1f}") + " mm/s"


def recording_label(r):
    name = r["recording"]
    if name.endswith(".yaml"):
        return f"not recorded: {r['speed_mm_s']} mm/s, {r['step_s']} s, toe-off + heel strike"
    return name


def markdown(ideal, distance):
    out = ["| walk | step | distance in 10 s | steady speed | mean speed, 1 s to end of steps |",
           "|---|---|---|---|---|"]
    for r in ideal:
        out.append(f"| {r['walk']} | {r['step_m']:.3f} m | {r['distance_m']:.3f} m | "
                   f"{r['steady_mm_s']:.1f} mm/s ({r['steady_percent']} %) | "
                   f"{r['mean_mm_s']:.1f} mm/s |")
    out += ["", "| recording | ideal servos | truth model |", "|---|---|---|"]
    for r in distance:
        out.append(f"| {recording_label(r)} | {r['ideal_m']:.3f} m, {r['ideal_mm_s']:.1f} mm/s | "
                   f"{truth_cell(r)} |")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "benchmarks", "walks"))
    args = parser.parse_args()
    tests = os.path.join(args.build, "tests")
    ideal = ideal_rows(run_test(os.path.join(tests, "motoflex_motion_tests"),
                                "NaoWalk.RigidNaoWalksAtTheCommandedSpeed"))
    distance = distance_rows(run_test(os.path.join(tests, "motoflex_motion_slow_tests"),
                                      "NaoWalkDistance.ReferenceWalksOnIdealServosAndOnTheTruthModel"))
    if len(ideal) != 8 or not distance:
        sys.exit(f"walk_tables: expected 8 walks and the distance table, read {len(ideal)} and "
                 f"{len(distance)} (did the tests' printed lines change?)")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "walks.json"), "w") as f:
        json.dump({"ideal_servos": ideal, "recordings": distance}, f, indent=2)
    table = markdown(ideal, distance)
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write("# Nao walks: ideal servos and the truth model\n\n" + table)
    print(table, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
