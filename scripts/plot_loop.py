#!/usr/bin/env python3
"""Plots of `motoflex loop`: validation residuals of the base and the final model, and the
ranking of the first iteration.

Usage: plot_loop.py LOOP_DIR   (holds loop.json, before_series.csv, after_series.csv)
Writes LOOP_DIR/residuals_before_after.png and LOOP_DIR/ranking.png.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_residuals import plot_ranking, read_series  # noqa: E402

DEG = 180.0 / math.pi


def main(directory):
    before, joints = read_series(os.path.join(directory, "before_series.csv"))
    after, _ = read_series(os.path.join(directory, "after_series.csv"))
    joints = [j for j in joints if j + ".residual_rad" in after]
    rows = len(joints)
    fig, axes = plt.subplots(rows, 1, figsize=(10, 2.4 * rows), squeeze=False)
    for ax, joint in zip(axes[:, 0], joints):
        for series, label in ((before, "base model"), (after, "final model")):
            ax.plot(range(len(series["time_s"])),
                    [r * DEG for r in series[joint + ".residual_rad"]], lw=0.8, label=label)
        ax.set_title(joint + " (validation logs, frames in order)", fontsize=9)
        ax.set_ylabel("residual (deg)")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "residuals_before_after.png"), dpi=90)
    plt.close(fig)

    with open(os.path.join(directory, "loop.json")) as f:
        loop = json.load(f)
    if loop["iterations"]:
        plot_ranking(loop["iterations"][0]["ranking"], "residual of the base fit explained (%)",
                     os.path.join(directory, "ranking.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
