#!/usr/bin/env python3
"""Plots of a motoflex fit run: fitness over generations, and for every training log the
measured angles (the log) against the best parameter set's simulated angles.

Usage: plot_fit.py RUN_DIR [TRAIN_LOG.csv ...]
Writes RUN_DIR/fitness.png and RUN_DIR/best_<log>.png.
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def plot_fitness(run_dir):
    rows = []
    with open(os.path.join(run_dir, "generations.csv"), newline="") as f:
        for row in csv.DictReader(f):
            rows.append({k: float(v) for k, v in row.items()})
    if not rows:
        return
    evals = [r["evaluations"] for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].semilogy(evals, [r["best"] for r in rows], label="best so far")
    medians = [r["median"] for r in rows if r["median"] < float("inf")]
    if len(medians) == len(rows):
        ax[0].semilogy(evals, medians, alpha=0.6, label="median of generation")
    ax[0].set_xlabel("evaluations")
    ax[0].set_ylabel("fitness F")
    ax[0].grid(alpha=0.3, which="both")
    ax[0].legend()
    ax[1].semilogy(evals, [max(r["mean_sigma"], 1e-300) for r in rows])
    ax[1].set_xlabel("evaluations")
    ax[1].set_ylabel("mean step size (relative)")
    ax[1].grid(alpha=0.3, which="both")
    fig.suptitle(os.path.basename(os.path.normpath(run_dir)))
    fig.tight_layout()
    fig.savefig(os.path.join(run_dir, "fitness.png"), dpi=90)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    run_dir = sys.argv[1]
    plot_fitness(run_dir)
    for log in sys.argv[2:]:
        stem = os.path.splitext(os.path.basename(log))[0]
        simulated = os.path.join(run_dir, "best", stem + ".csv")
        if os.path.exists(simulated):
            subprocess.run([sys.executable, os.path.join(HERE, "plot_log.py"), log, "--compare",
                            simulated, "--out", os.path.join(run_dir, "best_" + stem + ".png")],
                           check=False)


if __name__ == "__main__":
    main()
