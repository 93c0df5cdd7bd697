#!/usr/bin/env python3
"""Before/after plot of one real servo log: the goal, the measured angle, and the angle the
loop's base fit and final fit simulate (their best/<log>.csv), with the tracking error below.

Usage: plot_stall.py LOOP_DIR LOG_STEM --out PNG [--measured CSV]
Prints the log's mean absolute error before and after the loop.
LOG_STEM is the log's file stem in the fits' best/ folders (training logs) or best/validation/;
the measured angle is read from --measured, or from LOOP_DIR/imported/.../<LOG_STEM>.csv.
"""
import argparse
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402


def read(path):
    return read_columns(path)[1]


def series(run_dir, stem):
    for sub in ("", "validation"):
        path = os.path.join(run_dir, "best", sub, stem + ".csv")
        if os.path.exists(path):
            return read(path)
    raise SystemExit("no best/%s.csv in %s" % (stem, run_dir))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("loop_dir")
    parser.add_argument("stem")
    parser.add_argument("--out", required=True)
    parser.add_argument("--measured")
    args = parser.parse_args()
    with open(os.path.join(args.loop_dir, "loop.json")) as f:
        loop = json.load(f)
    # The measured log is the imported one: every fit's best/ folder holds a simulated file of
    # the same name, which must never be taken for the measurement.
    measured_path = args.measured or next(iter(sorted(glob.glob(
        os.path.join(args.loop_dir, "**", "imported", "**", args.stem + ".csv"),
        recursive=True))), None)
    base = series(loop["base_run_dir"], args.stem)
    final = series(loop["final_run_dir"], args.stem)
    measured = read(measured_path) if measured_path else None
    joint = [h for h in base if h.endswith(".meas")][0]
    cmd = joint.replace(".meas", ".cmd")
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    t = base["time_s"]
    top.plot(t, base[cmd], "k--", lw=1, label="goal")
    if measured:
        top.plot(measured["time_s"], measured[joint], "k", lw=1.5, label="measured")
    top.plot(t, base[joint], "C0", label="base fit (%s)" % " + ".join(loop["base_model"]))
    added = [it["added_effect"] for it in loop["iterations"] if it["added_effect"]]
    top.plot(final["time_s"], final[joint], "C3", label="after the loop (+ %s)" %
             (" + ".join(added) or "nothing"))
    top.set_ylabel("angle (rad)")
    top.legend(fontsize=8)
    top.set_title(args.stem)
    if measured:
        bottom.plot(measured["time_s"], [g - m for g, m in zip(measured[cmd], measured[joint])],
                    "k", lw=1.5, label="measured")
    bottom.plot(t, [g - m for g, m in zip(base[cmd], base[joint])], "C0", label="base fit")
    bottom.plot(final["time_s"], [g - m for g, m in zip(final[cmd], final[joint])], "C3",
                label="after the loop")
    bottom.axhline(0.0, color="grey", lw=0.5)
    bottom.set_ylabel("goal − angle (rad)")
    bottom.set_xlabel("time (s)")
    bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(args.out)
    if measured:
        # The log's mean absolute error (mrad) before and after, as the README quotes it.
        for name, run in (("base fit", base), ("after the loop", final)):
            errors = [abs(a - b) for a, b in zip(measured[joint], run[joint])]
            print("%s: MAE %.1f mrad, max angle %.3f rad (measured %.3f)" % (
                name, 1e3 * sum(errors) / len(errors), max(run[joint]), max(measured[joint])))


if __name__ == "__main__":
    sys.exit(main())
