#!/usr/bin/env python3
"""Plots of `motoflex residuals`: the residual (measured - simulated angle) of every joint
against time, commanded velocity and load torque, its correlation with the commanded velocity
at lags, and the ranking of candidate effects.

Usage: plot_residuals.py DIR   (DIR holds residuals.json and train_series.csv)
Writes DIR/residual_time.png, residual_vs_velocity.png, residual_vs_torque.png,
residual_lag.png and ranking.png.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402

DEG = 180.0 / math.pi


def read_series(path):
    header, columns = read_columns(path)
    # Every residual channel: the joints, then imu.roll and imu.pitch when the fit scores them.
    channels = [h[: -len(".residual_rad")] for h in header if h.endswith(".residual_rad")]
    return columns, channels


def grid(n):
    cols = min(n, 2)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6 * cols, 2.6 * rows), squeeze=False)
    return fig, [ax for row in axes for ax in row]


def scatter_plot(columns, joints, suffix, xlabel, out):
    fig, axes = grid(len(joints))
    for ax, joint in zip(axes, joints):
        ax.scatter(columns[joint + suffix], [r * DEG for r in columns[joint + ".residual_rad"]],
                   s=2, alpha=0.4)
        ax.set_title(joint, fontsize=9)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("residual (deg)")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def main(directory):
    columns, joints = read_series(os.path.join(directory, "train_series.csv"))
    fig, axes = grid(len(joints))
    cases = columns["case"]
    for ax, joint in zip(axes, joints):
        residual = [r * DEG for r in columns[joint + ".residual_rad"]]
        for case in sorted(set(cases)):
            idx = [i for i, c in enumerate(cases) if c == case]
            ax.plot([columns["time_s"][i] for i in idx], [residual[i] for i in idx], lw=0.8,
                    label="log %d" % case)
        ax.set_title(joint, fontsize=9)
        ax.set_xlabel("time (s)")
        ax.set_ylabel("residual (deg)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "residual_time.png"), dpi=90)
    plt.close(fig)
    joints = [j for j in joints if j + ".command_velocity_rad_s" in columns]  # not the IMU
    scatter_plot(columns, joints, ".command_velocity_rad_s", "commanded velocity (rad/s)",
                 os.path.join(directory, "residual_vs_velocity.png"))
    scatter_plot(columns, joints, ".load_torque_nm", "actuator torque (N·m)",
                 os.path.join(directory, "residual_vs_torque.png"))

    with open(os.path.join(directory, "residuals.json")) as f:
        report = json.load(f)
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for joint in report["train"]["joints"]:
        ax.plot([1e3 * t for t in joint["lag_s"]], joint["lag_correlation_with_command_velocity"],
                marker=".", label=joint["joint"])
    ax.set_xlabel("lag (ms)")
    ax.set_ylabel("corr(residual, commanded velocity)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "residual_lag.png"), dpi=90)
    plt.close(fig)

    plot_ranking([r for r in report["ranking"] if r["status"] == "scored"],
                 "residual explained by the effect's signature (%)",
                 os.path.join(directory, "ranking.png"))


def plot_ranking(scored, xlabel, out):
    """Horizontal bars of the share of the residual each ranked effect explains."""
    if not scored:
        return
    fig, ax = plt.subplots(figsize=(7, 0.35 * len(scored) + 1.2))
    ax.barh([r["effect"] for r in scored][::-1], [100 * r["score"] for r in scored][::-1])
    ax.set_xlabel(xlabel)
    ax.grid(alpha=0.3, axis="x")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
