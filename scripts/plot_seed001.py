#!/usr/bin/env python3
"""Figures of seed 001's experiments (Section 5), from what `motoflex experiment seed001` writes
into DIR (seed001.json and series/*.csv):
  fig3_pitch_<walk>.png  torso pitch over time, every model variant (the paper's Fig. 3:
                         200 mm/s, 1 s step duration, rigid vs extended)
  fig4_roll_<walk>.png   torso roll over time (the paper's Fig. 4: 50 mm/s, 2 s step duration)
  zmp_<walk>.png         torso roll of the ZMP search's trials, per extended variant

Shaded: the steady part of the walk over which speed_mm_s is measured; x: a fall.
Usage: plot_seed001.py DIR
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402

SIGNAL = {"pitch": ("pitch_rad", "torso pitch [deg] (+: forward)"),
          "roll": ("roll_rad", "torso roll [deg] (+: right side down)")}


def read_series(path):
    return read_columns(path)[1]


def label(variant, run):
    text = variant
    speed = run.get("speed_mm_s")
    if speed is not None:
        text += ", %.0f mm/s" % speed
    if run.get("fell"):
        text += ", falls %s at %.2f s" % (run.get("fall_direction") or "", run["fall_s"])
    alternation = run.get("pitch_alternation")
    if alternation is not None:
        text += ", alternation %.2f" % alternation
    return text


def walk_figure(out, walk, runs, signal, png):
    column, ylabel = SIGNAL[signal]
    fig, ax = plt.subplots(figsize=(9, 4))
    shaded = False
    for variant, run in runs.items():
        if "pending" in run:
            ax.plot([], [], " ", label="%s: pending" % variant)
            continue
        data = read_series(os.path.join(out, run["series"]))
        degrees = [math.degrees(v) for v in data[column]]
        line, = ax.plot(data["time_s"], degrees, lw=1.0, label=label(variant, run))
        if run.get("fell") and data["time_s"]:
            ax.plot(data["time_s"][-1], degrees[-1], "x", color=line.get_color(), ms=9)
        if not shaded:
            ax.axvspan(run["steady_s"][0], run["steady_s"][1], color="grey", alpha=0.12, lw=0)
            shaded = True
    ax.axhline(0.0, color="k", lw=0.4)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(ylabel)
    ax.set_title("%s: torso %s (shaded: steady part of the plan)" % (walk, signal), fontsize=9)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(os.path.join(out, png), dpi=110)
    plt.close(fig)


def zmp_figure(out, result, png):
    zmp = result["zmp_experiment"]
    variants = zmp.get("variants", {})
    if not variants:
        return
    fig, axes = plt.subplots(len(variants), 1, figsize=(9, 3.4 * len(variants)), squeeze=False)
    defaults = zmp.get("defaults", {})
    for ax, (variant, trials_of) in zip(axes[:, 0], variants.items()):
        own = result.get(zmp["walk"], {}).get(variant)
        if own and "series" in own:
            data = read_series(os.path.join(out, own["series"]))
            ax.plot(data["time_s"], [math.degrees(v) for v in data["roll_rad"]], "k--", lw=1.0,
                    label="the walk file's options")
        chosen = trials_of["chosen"] or {}
        for trial in trials_of["trials"]:
            if "unplannable" in trial:
                ax.plot([], [], " ", label="%s = %g: cannot be planned" %
                        (trial["option"], trial["value"]))
                continue
            data = read_series(os.path.join(out, trial["series"]))
            roll = [math.degrees(v) for v in data["roll_rad"]]
            is_chosen = (chosen.get("option") == trial["option"] and
                         chosen.get("value") == trial["value"])
            text = "%s = %g" % (trial["option"], trial["value"])
            if trial["fell"]:
                text += ", falls %s at %.2f s" % (trial.get("fall_direction") or "",
                                                  trial["fall_s"])
            ax.plot(data["time_s"], roll, lw=2.0 if is_chosen else 0.8,
                    label=text + (" (chosen)" if is_chosen else ""))
        ax.axhline(0.0, color="k", lw=0.4)
        ax.set_ylabel("%s\ntorso roll [deg]" % variant)
        ax.legend(fontsize=6, ncol=2)
    axes[0, 0].set_title("%s, one option changed at a time (the file's: %s)\nchosen: no fall, "
                         "smallest peak roll" % (zmp["walk"], ", ".join(
                             "%s %g" % kv for kv in defaults.items())), fontsize=8)
    axes[-1, 0].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, png), dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir")
    args = parser.parse_args()
    with open(os.path.join(args.dir, "seed001.json")) as f:
        result = json.load(f)
    for walk, figure in result.get("figures", {}).items():
        if walk == "zmp_experiment":
            zmp_figure(args.dir, result, figure["png"])
        else:
            walk_figure(args.dir, walk, result[walk], figure["signal"], figure["png"])


if __name__ == "__main__":
    main()
