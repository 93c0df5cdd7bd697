#!/usr/bin/env python3
"""What racing within a generation saves (issue 20, item 1), measured in one run.

Each case is one fit run twice with the same seed and threads: with `racing: true` (the
default: the (mu+lambda)-ES evaluates its offspring in chunks of mu, each against the mu-th best of
the parents and of the offspring before it) and with `racing: false` (each offspring against
the parents' mu-th best alone, what early termination did before). Both must give the same
best.json and generations.csv (all but the batch median, a censored statistic); the table
gives the frames each simulated and saved (summary.json early_termination), the processor
seconds of the whole `motoflex fit` process (user + system: the work, which the machine's other
load hardly changes) and the fit loop's wall seconds (summary.json; on a shared machine a noisy
ratio, which also shows the threads waiting for the slowest rollout of a racing chunk).

Cases:
  nao_quick     the main job's fit (scenarios/fit/nao_quick.yaml: (4+16)-ES, kappa 3, 388
                evaluations of the five 10 s training logs), without its validation replay;
  paper_es      the paper's (10+800)-ES, kappa 3, for its first generation (810 evaluations) on
                the strategy benchmark's fit (scenarios/fit/nao_strategy_bench.yaml: 4 free,
                3 s windows).
--quick shrinks both (36 evaluations of nao_quick; a (10+80)-ES for one generation) to check
the script itself.

    scripts/bench_racing.py [--quick] [--threads 2] [--out runs/bench_racing]
                            [--results benchmarks/racing]

Writes RESULTS/racing.md and racing.json.
"""

import argparse
import csv
import json
import os
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

import yaml  # python3-yaml (scripts/setup)

from report_files import write_report

ROOT = Path(__file__).resolve().parent.parent
FITS = ROOT / "scenarios" / "fit"


def case_configs(quick):
    """name -> (description, base config, strategy, evaluations)."""
    quick_es = {"kind": "mu_plus_lambda", "mu": 4, "lambda": 16, "kappa": 3, "rho": 2,
                "initial_step": 0.15}
    paper_lambda = 80 if quick else 800
    paper_es = {"kind": "mu_plus_lambda", "mu": 10, "lambda": paper_lambda, "kappa": 3, "rho": 2,
                "initial_step": 0.15}
    return {
        "nao_quick": ("nao_quick's fit, (4+16)-ES, kappa 3, five 10 s logs", FITS / "nao_quick.yaml",
                      quick_es, 36 if quick else 388),
        "paper_es": (f"the paper's (10+{paper_lambda})-ES, kappa 3, its first generation, "
                     "nao_strategy_bench (3 s windows)", FITS / "nao_strategy_bench.yaml",
                     paper_es, 10 + paper_lambda),
    }


def derived(base_path, strategy, evaluations, threads, racing):
    """The base fit with absolute paths, no validation, and the given strategy and budget."""
    base = yaml.safe_load(base_path.read_text())
    config = dict(base)
    for key in ("scenario", "data"):
        config[key] = str((base_path.parent / base[key]).resolve())
    config.pop("validation", None)
    config.pop("out", None)
    config["strategy"] = {**strategy, "racing": racing}
    config["budget"] = {"evaluations": evaluations}
    config["threads"] = threads
    config["seed"] = 1
    return config


def generations_without_median(run_dir):
    """generations.csv rows without the batch median (censored by racing) and the seconds."""
    with (run_dir / "generations.csv").open() as f:
        return [{k: v for k, v in row.items() if k not in ("median", "seconds")}
                for row in csv.DictReader(f)]


def best_of(run_dir):
    best = json.loads((run_dir / "best.json").read_text())
    return {"fitness": best["fitness"], "free": best["free"]}


def run_fit(binary, work, name, config):
    path = work / f"{name}.yaml"
    path.write_text(yaml.safe_dump(config, sort_keys=False, default_flow_style=None))
    run_dir = work / name
    shutil.rmtree(run_dir, ignore_errors=True)
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.monotonic()
    subprocess.run([str(binary), "fit", str(path), "--out", str(run_dir)], check=True,
                   stdout=subprocess.DEVNULL)
    wall = time.monotonic() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - usage.ru_utime) + (after.ru_stime - usage.ru_stime)
    summary = json.loads((run_dir / "summary.json").read_text())
    early = summary["early_termination"]
    frames = early["frames_simulated"] + early["frames_saved"]
    return run_dir, {
        "evaluations": summary["evaluations"], "best_fitness": summary["best_fitness"],
        "stopped": early["individuals_stopped_early"], "frames_simulated": early["frames_simulated"],
        "frames_saved": early["frames_saved"], "saved_share": early["frames_saved"] / frames,
        "fit_seconds": summary["seconds"], "wall_seconds": wall, "cpu_seconds": cpu}


def measure(binary, work, name, description, base, strategy, evaluations, threads):
    work.mkdir(parents=True, exist_ok=True)
    raced_dir, raced = run_fit(binary, work, name + "_racing",
                               derived(base, strategy, evaluations, threads, True))
    parents_dir, parents = run_fit(binary, work, name + "_parents",
                                   derived(base, strategy, evaluations, threads, False))
    identical = (best_of(raced_dir) == best_of(parents_dir) and
                 generations_without_median(raced_dir) == generations_without_median(parents_dir))
    row = {"case": name, "description": description, "threads": threads, "racing": raced,
           "parents_only": parents, "identical": identical,
           "frames_ratio": raced["frames_simulated"] / parents["frames_simulated"],
           "cpu_ratio": raced["cpu_seconds"] / parents["cpu_seconds"],
           "seconds_ratio": raced["fit_seconds"] / parents["fit_seconds"]}
    print(json.dumps(row), flush=True)
    return row


def markdown(rows, args):
    lines = [
        f"Racing within a generation against the parents' threshold alone: each case is one fit "
        f"run twice, seed 1, {args.threads} threads, one after the other "
        f"({time.strftime('%Y-%m-%d')}, `scripts/bench_racing.py"
        f"{' --quick' if args.quick else ''}`). Frames are physics frames of the fit's rollouts "
        "(summary.json early_termination); processor seconds are the whole `motoflex fit` "
        "process's (user + system); wall seconds the fit loop's (summary.json; a noisy ratio on a "
        "shared machine).",
        "",
        "| case | evaluations | stopped early: racing / parents only | frames saved: racing / "
        "parents only | frames simulated, racing / parents only | processor s, racing / parents "
        "only | fit wall s, racing / parents only | same best.json and generations |",
        "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        a, b = r["racing"], r["parents_only"]
        lines.append(
            f"| {r['description']} | {a['evaluations']} | {a['stopped']} / {b['stopped']} | "
            f"{100 * a['saved_share']:.1f} % / {100 * b['saved_share']:.1f} % | "
            f"{r['frames_ratio']:.2f} | {a['cpu_seconds']:.0f} / {b['cpu_seconds']:.0f} "
            f"({r['cpu_ratio']:.2f}) | {a['fit_seconds']:.0f} / {b['fit_seconds']:.0f} "
            f"({r['seconds_ratio']:.2f}) | {'yes' if r['identical'] else 'NO'} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "motoflex"))
    parser.add_argument("--out", default=str(ROOT / "runs" / "bench_racing"))
    parser.add_argument("--results", default=str(ROOT / "benchmarks" / "racing"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--cases", default="nao_quick,paper_es")
    args = parser.parse_args()
    cases = case_configs(args.quick)
    rows = []
    for name in [c for c in args.cases.split(",") if c]:
        if name not in cases:
            sys.exit(f"bench_racing: unknown case {name} (known: {', '.join(cases)})")
        description, base, strategy, evaluations = cases[name]
        rows.append(measure(Path(args.binary), Path(args.out), name, description, base, strategy,
                            evaluations, args.threads))
    os.makedirs(args.results, exist_ok=True)
    write_report(args.results, "racing", markdown(rows, args), rows)
    return 0 if all(r["identical"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
