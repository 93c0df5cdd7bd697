#!/usr/bin/env python3
"""How finely the nao_paper fitness resolves the truth (issue 20): F along one direction
through the truth, at relative steps from 1e-10 to 1e-3, and where the perturbed walk first
parts from the truth's.

The point: every free parameter of scenarios/fit/nao_paper.yaml at its truth value
(scenarios/truth/nao_motoflex.yaml) times 1 + s*d, d = +-1 per free entry (a tied pattern moves
as one, an `each: true` pattern per group; signs from a seeded generator), for s and -s. Each
point is one evaluation of the fit (the held parameters as the config holds them), with F per
training log; for one log the perturbed replay (`motoflex simulate`) is compared with the
truth's, joint by joint: the largest angle difference over the log and the first time it
exceeds 1e-5 rad (0.0006 deg, a fiftieth of the logs' 12-bit resolution).

A smooth F would change in proportion to s (and s^2) at every step; a walking robot with
contacts is smooth only up to the first foot touchdown whose timing the perturbation moves, after
which the walk continues on a neighbouring trajectory. Where that happens is where a gradient
stops helping and the 5 % target turns into a draw.

    scripts/fitness_resolution.py [--scales 1e-10,1e-8,1e-6,1e-5,1e-4,1e-3] [--log walk_150mm_1s]
                                  [--threads 2] [--out runs/fitness_resolution]
                                  [--results benchmarks/fitness_resolution]

Writes RESULTS/fitness_resolution.md and .json.
"""

import argparse
import csv
import fnmatch
import json
import random
import subprocess
import sys
import time
from pathlib import Path

import yaml  # python3-yaml (scripts/setup)

from bench_fit_speed import FIT, TRUTH, summary_at
from bench_strategies import truth_point
from report_files import write_report

ROOT = Path(__file__).resolve().parent.parent
BASE = ROOT / "scenarios" / "fit" / "nao_paper_base.yaml"
DIVERGED_RAD = 1e-5


def direction(point, seed):
    """A sign per free entry of the fit (groups as the fit ties them)."""
    free = yaml.safe_load(FIT.read_text())["free"]
    rng = random.Random(seed)
    signs = {}
    for pattern, spec in free.items():
        names = [n for n in point if fnmatch.fnmatchcase(n, pattern)]
        for group in ([[n] for n in names] if spec.get("each") else [names]):
            sign = rng.choice((-1.0, 1.0))
            for name in group:
                signs[name] = sign
    return signs


def moved(point, signs, step):
    return {name: value * (1.0 + step * signs[name]) for name, value in point.items()}


def evaluate(binary, work, name, point, threads):
    """F and F per training log at `point` (one evaluation of the fit)."""
    summary = summary_at(binary, work, threads, point, name)
    return summary["best_fitness"], {r["name"]: r["fitness"] for r in summary["robots"]}


def replay(binary, work, name, point, log):
    params = work / f"{name}.json"
    params.write_text(json.dumps(point))
    out = work / f"{name}_{log}.csv"
    subprocess.run([str(binary), "simulate", str(BASE), "--params", str(params), "--motion",
                    str(ROOT / "reference_data" / "nao" / "train" / f"{log}.csv"), "--out",
                    str(out)], check=True, stdout=subprocess.DEVNULL)
    with out.open() as f:
        rows = list(csv.reader(f))
    header, values = rows[0], [[float(x) for x in row] for row in rows[1:]]
    joints = [i for i, column in enumerate(header) if column.endswith(".meas")]
    return [row[0] for row in values], [[row[i] for i in joints] for row in values]


def parting(times, truth, other):
    """Largest joint-angle difference (rad) and the first time any joint differs by more than
    DIVERGED_RAD (None if never)."""
    largest, first = 0.0, None
    for t, a, b in zip(times, truth, other):
        difference = max(abs(x - y) for x, y in zip(a, b))
        largest = max(largest, difference)
        if first is None and difference > DIVERGED_RAD:
            first = t
    return largest, first


def first_time(side):
    return f"{side['first_s']:.2f}" if side["first_s"] is not None else "never"


def markdown(result):
    truth = result["truth_fitness"]
    lines = [
        f"F of the nao_paper fit (19 free parameters, the five 10 s training logs) along one "
        f"direction through the truth (signs seed {result['seed']}), each step in both signs, "
        f"F(truth) = {truth:.6g}; the replay of {result['log']} compared with the truth's "
        f"({time.strftime('%Y-%m-%d')}, `scripts/fitness_resolution.py`, {result['threads']} "
        "threads).",
        "",
        "| relative step | F / F(truth), + | F / F(truth), − | logs whose F moved by > 1 % | "
        f"{result['log']}: largest angle difference (rad), + / − | first time over 1e-5 rad "
        "(s), + / − |",
        "|---|---|---|---|---|---|"]
    for row in result["rows"]:
        plus, minus = row["+"], row["-"]
        movers = sorted({log for side in (plus, minus) for log, f in side["logs"].items()
                         if abs(f / result["truth_logs"][log] - 1.0) > 0.01})
        lines.append(
            f"| {row['step']:g} | {plus['fitness'] / truth:.6f} | {minus['fitness'] / truth:.6f} | "
            f"{', '.join(movers) or 'none'} | {plus['largest_rad']:.2g} / "
            f"{minus['largest_rad']:.2g} | {first_time(plus)} / {first_time(minus)} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "motoflex"))
    parser.add_argument("--out", default=str(ROOT / "runs" / "fitness_resolution"))
    parser.add_argument("--results", default=str(ROOT / "benchmarks" / "fitness_resolution"))
    parser.add_argument("--scales", default="1e-10,1e-8,1e-6,1e-5,1e-4,1e-3")
    parser.add_argument("--log", default="walk_150mm_1s")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    binary, work = Path(args.binary), Path(args.out)
    work.mkdir(parents=True, exist_ok=True)
    point = truth_point(FIT, TRUTH)
    signs = direction(point, args.seed)
    truth_fitness, truth_logs = evaluate(binary, work, "truth", point, args.threads)
    times, truth_angles = replay(binary, work, "truth", point, args.log)
    rows = []
    for step in [float(s) for s in args.scales.split(",") if s]:
        row = {"step": step}
        for sign, label in ((1.0, "+"), (-1.0, "-")):
            name = f"step_{step:g}_{'plus' if sign > 0 else 'minus'}"
            here = moved(point, signs, sign * step)
            fitness, logs = evaluate(binary, work, name, here, args.threads)
            _, angles = replay(binary, work, name, here, args.log)
            largest, first = parting(times, truth_angles, angles)
            row[label] = {"fitness": fitness, "logs": logs, "largest_rad": largest,
                          "first_s": first}
        rows.append(row)
        print(json.dumps(row), flush=True)
    result = {"truth_fitness": truth_fitness, "truth_logs": truth_logs, "seed": args.seed,
              "log": args.log, "threads": args.threads, "rows": rows}
    Path(args.results).mkdir(parents=True, exist_ok=True)
    write_report(args.results, "fitness_resolution", markdown(result), result)
    return 0


if __name__ == "__main__":
    sys.exit(main())
