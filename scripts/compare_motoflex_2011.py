#!/usr/bin/env python3
"""Joint angles of a motoflex replay against the 2011 MoToFlex program's own output.

The original writes one row per 1 ms physics frame (`;`-separated, a header of joint names, the
angle after that frame's step, in its file signs: Aldebaran's, with LHipRoll and LAnkleRoll
mirrored; ../shared/reference/motoflex_2011.md §2.1). motoflex writes the simulated angles
(`<joint>.meas`) in Aldebaran's signs at the command file's rate:

    motoflex simulate scenarios/truth/nao_motoflex_2011.yaml --motion UncompensatedTarget.csv \\
        --out out/50.csv
    scripts/compare_motoflex_2011.py out/50.csv 50.csv-UncompensatedTarget-Output.csv

Prints the RMS over every joint and every sample both runs have (whole run from t = 0; the
original's row i is the state at (i + 1) ms), per time window and per joint, and where each run
ends (the original's output stops at its fall; motoflex's sidecar notes say why it ended).
`--json` writes the same numbers to a file.
"""

import argparse
import csv
import json
import math
import os
import re
import sys

JOINTS = ["LHipRoll", "LHipPitch", "LKneePitch", "LAnklePitch", "LAnkleRoll",
          "RHipRoll", "RHipPitch", "RKneePitch", "RAnklePitch", "RAnkleRoll"]
MIRRORED = {"LHipRoll", "LAnkleRoll"}
WINDOWS_S = [(0.0, 0.82), (0.82, 2.0), (2.0, 4.0), (4.0, 6.0), (6.0, 10.0), (10.0, 1e9)]


def read_motoflex(path):
    with open(path, encoding="utf-8") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header = rows[0]
    try:
        columns = [header.index(j + ".meas") for j in JOINTS]
        time_column = header.index("time_s")
    except ValueError as error:
        sys.exit(f"compare_motoflex_2011: {path}:1: header: {error}")
    times = [float(r[time_column]) for r in rows[1:]]
    angles = [[float(r[c]) for c in columns] for r in rows[1:]]
    return times, angles


def read_original(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = [line.strip() for line in f if line.strip()]
    header = [h.strip() for h in lines[0].split(";") if h.strip()]
    if sorted(header) != sorted(JOINTS):
        sys.exit(f"compare_motoflex_2011: {path}:1: header: expected the ten leg joints")
    order = [header.index(j) for j in JOINTS]
    frames = []
    for number, line in enumerate(lines[1:], start=2):
        fields = [x for x in line.split(";") if x.strip()]
        if len(fields) != len(header):
            sys.exit(f"compare_motoflex_2011: {path}:{number}: expected {len(header)} fields")
        values = [float(fields[k]) for k in order]
        frames.append([-v if j in MIRRORED else v for j, v in zip(JOINTS, values)])
    return frames


def end_note(path):
    sidecar = os.path.splitext(path)[0] + ".yaml"
    if not os.path.exists(sidecar):
        return None
    with open(sidecar, encoding="utf-8") as f:
        match = re.search(r"rollout fell at ([0-9.]+) s", f.read())
    return float(match.group(1)) if match else None


def compare(times, ours, original):
    squares = [0.0] * len(JOINTS)
    windows = {w: [0.0, 0] for w in WINDOWS_S}
    count = 0
    for t, angles in zip(times, ours):
        row = int(round(t * 1000.0)) - 1  # the original's row i is the state at (i + 1) ms
        if row < 0 or row >= len(original):
            continue
        errors = [math.degrees(a - b) ** 2 for a, b in zip(angles, original[row])]
        for j, e in enumerate(errors):
            squares[j] += e
        for w in WINDOWS_S:
            if w[0] <= t < w[1]:
                windows[w][0] += sum(errors)
                windows[w][1] += len(errors)
        count += 1
    if count == 0:
        sys.exit("compare_motoflex_2011: no common samples")
    result = {
        "samples": count,
        "rms_deg": math.sqrt(sum(squares) / (count * len(JOINTS))),
        "per_joint_rms_deg": {j: math.sqrt(s / count) for j, s in zip(JOINTS, squares)},
        "windows": [{"from_s": a, "to_s": min(b, times[-1]), "rms_deg": math.sqrt(s / n)}
                    for (a, b), (s, n) in windows.items() if n],
    }
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("motoflex_log", help="motoflex simulate's output CSV")
    parser.add_argument("original_output", help="the 2011 program's per-frame output")
    parser.add_argument("--json", help="also write the numbers to this JSON file")
    args = parser.parse_args()
    times, ours = read_motoflex(args.motoflex_log)
    original = read_original(args.original_output)
    result = compare(times, ours, original)
    result["original_end_s"] = len(original) / 1000.0
    result["motoflex_fall_s"] = end_note(args.motoflex_log)
    print(f"{result['samples']} samples, joint angle RMS {result['rms_deg']:.3f} deg "
          f"(original ends at {result['original_end_s']:.3f} s, motoflex "
          + (f"falls at {result['motoflex_fall_s']:.3f} s)" if result["motoflex_fall_s"]
             else "does not fall)"))
    for w in result["windows"]:
        print(f"  {w['from_s']:5.2f}-{w['to_s']:5.2f} s: {w['rms_deg']:.3f} deg")
    print("  per joint: " + ", ".join(f"{j} {v:.2f}" for j, v in
                                      result["per_joint_rms_deg"].items()))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
