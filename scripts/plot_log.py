#!/usr/bin/env python3
"""Plot a motoflex joint log: commanded vs measured angle per joint (and IMU roll/pitch).

Usage: plot_log.py LOG.csv --out PNG [--compare OTHER.csv]
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402


def read_log(path):
    return read_columns(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("log")
    parser.add_argument("--out", required=True)
    parser.add_argument("--compare", help="second log whose .meas columns are overlaid")
    args = parser.parse_args()

    header, cols = read_log(args.log)
    other = read_log(args.compare)[1] if args.compare else None
    joints = []
    for name in header:
        if name.endswith(".cmd") or name.endswith(".meas"):
            joint = name.rsplit(".", 1)[0]
            if joint not in joints:
                joints.append(joint)
    has_imu = "imu.roll" in cols
    panels = len(joints) + (1 if has_imu else 0)
    ncols = 2
    nrows = math.ceil(panels / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(12, 2.2 * nrows), sharex=True, squeeze=False)
    t = cols["time_s"]
    deg = 180.0 / math.pi
    for i, joint in enumerate(joints):
        ax = axes[i // ncols][i % ncols]
        if joint + ".cmd" in cols:
            ax.plot(t, [v * deg for v in cols[joint + ".cmd"]], "k--", lw=1, label="commanded")
        if joint + ".meas" in cols:
            ax.plot(t, [v * deg for v in cols[joint + ".meas"]], "C0", lw=1.2, label="measured")
        if other and joint + ".meas" in other:
            ax.plot(other["time_s"], [v * deg for v in other[joint + ".meas"]], "C3", lw=1,
                    label="simulated (" + args.compare.rsplit("/", 1)[-1] + ")")
        ax.set_ylabel(joint + " [°]", fontsize=8)
        ax.grid(alpha=0.3)
        if i == 0:
            ax.legend(fontsize=7, loc="best")
    if has_imu:
        ax = axes[len(joints) // ncols][len(joints) % ncols]
        ax.plot(t, [v * deg for v in cols["imu.roll"]], label="roll")
        ax.plot(t, [v * deg for v in cols["imu.pitch"]], label="pitch")
        ax.set_ylabel("torso IMU [°]", fontsize=8)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    for j in range(panels, nrows * ncols):
        axes[j // ncols][j % ncols].axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    fig.suptitle(args.log.rsplit("/", 1)[-1], fontsize=10)
    fig.tight_layout()
    fig.savefig(args.out, dpi=90)
    return 0


if __name__ == "__main__":
    sys.exit(main())
