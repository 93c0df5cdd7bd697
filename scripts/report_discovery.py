#!/usr/bin/env python3
"""Runs `motoflex loop scenarios/fit/bench_discovery.yaml` (open-ended discovery on) on every
log set whose truth has a torque no library effect models (reference_data/hidden/cogging,
quadratic_drag, load_saturation) and writes the table: residual -> term found -> validation
error before/after, with the truth next to it.

Usage: report_discovery.py [--binary build/motoflex] [--out benchmarks/discovery]
                           [--runs DIR] [--threads 2] [--effects a,b] [--reuse]
Each loop runs in RUNS/<effect>/ (default OUT/runs); --reuse reads loops already there.
Writes OUT/discovery_report.md and OUT/discovery_report.json.
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
EFFECTS = ["cogging", "quadratic_drag", "load_saturation"]
TRUTH = {
    "cogging": "0.04·sin(6·θ + 0.7) = 0.0306·sin(6·θ) + 0.0258·cos(6·θ)",
    "quadratic_drag": "−0.003·ω·|ω|",
    "load_saturation": "−0.06·tanh(τ_g / 0.1 N·m)",
}


def run(binary, effect, out, threads):
    hidden = os.path.join(ROOT, "reference_data", "hidden", effect)
    shutil.rmtree(out, ignore_errors=True)
    command = [binary, "loop", os.path.join(ROOT, "scenarios", "fit", "bench_discovery.yaml"),
               "--data", os.path.join(hidden, "train"),
               "--validation", os.path.join(hidden, "validation"),
               "--out", out, "--threads", str(threads), "--force"]
    start = time.monotonic()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


def cell(text):
    """Markdown table cell: |ω| must not end the cell."""
    return text.replace("|", "\\|")


def row_of(effect, out, seconds):
    with open(os.path.join(out, "loop.json")) as f:
        loop = json.load(f)
    its = loop["iterations"]
    found = [it.get("discovered_formula") for it in its if it.get("discovered_formula")]
    return {
        "data": "hidden/" + effect,
        "truth": TRUTH[effect],
        "added": [it["added_effect"] for it in its if it["added_effect"]],
        "term_found": found,
        "val_rms_before_deg": its[0]["val_rms_before"],
        "val_rms_after_deg": its[-1]["val_rms_after"],
        "val_mae_before_mrad": 1e3 * its[0]["val_mae_before_rad"],
        "val_mae_after_mrad": 1e3 * its[-1]["val_mae_after_rad"],
        "evaluations": loop["evaluations"],
        "wall_seconds": seconds if seconds is not None else loop["wall_seconds"],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "benchmarks", "discovery"))
    parser.add_argument("--runs", help="where the loops run (default OUT/runs)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--effects", default=",".join(EFFECTS))
    parser.add_argument("--reuse", action="store_true", help="read the loops already in OUT")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for effect in [e for e in args.effects.split(",") if e]:
        out = os.path.join(args.runs or os.path.join(args.out, "runs"), effect)
        seconds = None if args.reuse else run(args.binary, effect, out, args.threads)
        rows.append(row_of(effect, out, seconds))
        print(rows[-1], flush=True)
    lines = ["| residual of (truth, not in the library) | added | term found (fitted) | "
             "val RMS before → after (deg) | change | val MAE before → after (mrad) | "
             "evaluations | wall (s) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        change = 100.0 * (r["val_rms_after_deg"] - r["val_rms_before_deg"]) / r["val_rms_before_deg"]
        lines.append("| %s: %s | %s | %s | %.4f → %.4f | %+.1f %% | %.2f → %.2f | %d | %.0f |" % (
            r["data"], cell(r["truth"]), " + ".join(r["added"]) or "nothing",
            cell("; ".join(r["term_found"])) or "–", r["val_rms_before_deg"], r["val_rms_after_deg"],
            change, r["val_mae_before_mrad"], r["val_mae_after_mrad"], r["evaluations"],
            r["wall_seconds"]))
    write_report(args.out, "discovery_report", lines, rows)


if __name__ == "__main__":
    sys.exit(main())
