#!/usr/bin/env python3
"""Runs `motoflex loop` on every log set with an undeclared effect (reference_data/hidden/) and,
when ../shared/data/bam is present, on the real XL330 servo logs (kp 400 held out for
validation, as BAM does), then writes a before/after table.

Usage: report_loop.py [--binary build/motoflex] [--out runs/loop_report] [--threads 2]
                      [--effects a,b] [--no-nao] [--no-bam]
Writes OUT/loop_report.md and OUT/loop_report.json; each loop's run dir is OUT/<name>/.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

from report_files import write_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH_EFFECTS = ["none", "encoder_offset", "sensor_delay", "stribeck", "load_friction",
                 "resistance_drift", "torque_saturation"]


def run_loop(binary, fit, out, threads, data=None, validation=None):
    # The bench configs' base fits stop at their budget: --force goes on (rankings marked
    # unreliable in loop.json) as the README's loop table always did.
    command = [binary, "loop", fit, "--out", out, "--threads", str(threads), "--force"]
    if data:
        command += ["--data", data]
    if validation:
        command += ["--validation", validation]
    start = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    seconds = time.monotonic() - start
    with open(os.path.join(out, "loop.json")) as f:
        loop = json.load(f)
    its = loop["iterations"]
    return {
        "ranked_first": its[0]["ranking"][0]["effect"] if its and its[0]["ranking"] else None,
        "added": [it["added_effect"] for it in its if it["added_effect"]],
        "val_rms_before_deg": its[0]["val_rms_before"] if its else None,
        "val_rms_after_deg": its[-1]["val_rms_after"] if its else None,
        "val_mae_before_mrad": 1e3 * its[0]["val_mae_before_rad"] if its else None,
        "val_mae_after_mrad": 1e3 * its[-1]["val_mae_after_rad"] if its else None,
        "evaluations": loop["evaluations"],
        "probe_rollouts": loop["probe_rollouts"],
        "wall_seconds": seconds,
    }


def split_bam(folder, out):
    """BAM's split: the logs of one kp (400) validate, the others train."""
    train, val = os.path.join(out, "bam_train"), os.path.join(out, "bam_validation")
    for d in (train, val):
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(folder, name)) as f:
            kp = json.load(f).get("kp")
        shutil.copy(os.path.join(folder, name), val if kp == 400 else train)
    return train, val


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "runs", "loop_report"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--effects", default=",".join(BENCH_EFFECTS))
    parser.add_argument("--no-nao", action="store_true", help="skip link_flexibility (Nao)")
    parser.add_argument("--no-bam", action="store_true", help="skip the real servo logs")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    bench_fit = os.path.join(ROOT, "scenarios", "fit", "bench_hidden.yaml")
    for effect in [e for e in args.effects.split(",") if e]:
        hidden = os.path.join(ROOT, "reference_data", "hidden", effect)
        out = os.path.join(args.out, effect)
        shutil.rmtree(out, ignore_errors=True)
        row = run_loop(args.binary, bench_fit, out, args.threads, os.path.join(hidden, "train"),
                       os.path.join(hidden, "validation"))
        row["data"] = "hidden/" + effect
        rows.append(row)
        print(row, flush=True)
    if not args.no_nao:
        out = os.path.join(args.out, "link_flexibility")
        shutil.rmtree(out, ignore_errors=True)
        row = run_loop(args.binary, os.path.join(ROOT, "scenarios", "fit", "nao_hidden_flex.yaml"),
                       out, args.threads)
        row["data"] = "hidden/link_flexibility"
        rows.append(row)
        print(row, flush=True)
    bam = os.path.join(ROOT, "..", "shared", "data", "bam", "xl330", "processed")
    if not args.no_bam and os.path.isdir(bam):
        train, val = split_bam(bam, args.out)
        out = os.path.join(args.out, "bam_xl330")
        shutil.rmtree(out, ignore_errors=True)
        row = run_loop(args.binary, os.path.join(ROOT, "scenarios", "fit",
                                                 "servo_pendulum_bam.yaml"),
                       out, args.threads, train, val)
        row["data"] = "BAM XL330 (real; kp 400 validates)"
        rows.append(row)
        print(row, flush=True)
    elif not args.no_bam:
        print("BAM logs absent (%s): real-data loop skipped" % bam)

    lines = ["| data | ranked first | added | val RMS before → after (deg) | change | "
             "val MAE before → after (mrad) | evaluations (+probes) | wall (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        change = 100.0 * (r["val_rms_after_deg"] - r["val_rms_before_deg"]) / r["val_rms_before_deg"]
        lines.append("| %s | %s | %s | %.4f → %.4f | %+.1f %% | %.3f → %.3f | %d (+%d) | %.0f |" % (
            r["data"], r["ranked_first"], " + ".join(r["added"]) or "nothing",
            r["val_rms_before_deg"], r["val_rms_after_deg"], change, r["val_mae_before_mrad"],
            r["val_mae_after_mrad"], r["evaluations"], r["probe_rollouts"], r["wall_seconds"]))
    write_report(args.out, "loop_report", lines, rows)


if __name__ == "__main__":
    sys.exit(main())
