#!/usr/bin/env python3
"""Domain-randomisation ranges from several fits (`motoflex spread`), measured two ways.

1. Three units with a known spread. Three "units" of the pendulum bench servo differ as
   manufacturing spreads a servo type: K_t 0.33 / 0.35 / 0.37 N·m/A and dry friction
   0.06 / 0.08 / 0.10 N·m (the other parameters as scenarios/truth/hidden/none.yaml, sensor
   noise seeded per unit). Each is recorded (`motoflex record`: the bench's slow multisine and
   chirp), fitted alone with scenarios/fit/bench_hidden.yaml (4 free from its starts: K_t,
   armature, dry and viscous friction; R held at the bench's value; CMA-ES 480 evaluations,
   then least squares with standard errors), and `motoflex spread` computes the ranges. The
   between-run spread should match the units' own (sample std 0.02 for both) and each range
   should hold all three truths.
2. Real sessions of one servo: each STS3250 log of ../shared/data/bam fitted alone with
   scenarios/fit/servo_pendulum_sts3250.yaml (M1, six free from the config's starts, CMA-ES to
   its stopping tests, standard errors at the best point); skipped when the logs are absent.

Usage: report_spread.py [--results benchmarks/spread] [--binary build/motoflex]
Writes RESULTS/spread.md, RESULTS/units.json and (with the logs) RESULTS/sts3250.json.
"""
import argparse
import glob
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from yaml_paths import with_absolute_paths  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
STS_LOGS = os.path.join(ROOT, "..", "shared", "data", "bam", "sts3250", "raw")
BENCH_TRUTH = os.path.join(ROOT, "scenarios", "truth", "hidden", "none.yaml")
BENCH_FIT = os.path.join(ROOT, "scenarios", "fit", "bench_hidden.yaml")
STS_FIT = os.path.join(ROOT, "scenarios", "fit", "servo_pendulum_sts3250.yaml")
UNITS = {"unit_a": {"bench.Kt_nm_per_a": 0.33, "joint.pendulum.friction_nm": 0.06, "seed": 21},
         "unit_b": {"bench.Kt_nm_per_a": 0.35, "joint.pendulum.friction_nm": 0.08, "seed": 22},
         "unit_c": {"bench.Kt_nm_per_a": 0.37, "joint.pendulum.friction_nm": 0.10, "seed": 23}}


def unit_truth(text, values):
    lines = []
    for line in text.splitlines(keepends=True):
        key = line.strip().split(":", 1)[0]
        if key in values and key != "seed":
            line = "  %s: %s\n" % (key, values[key])
        elif line.startswith("seed:"):
            line = "seed: %d\n" % values["seed"]
        lines.append(line)
    return "".join(lines)


def spread(binary, runs, out):
    table = subprocess.run([binary, "spread", *runs, "--k", "2", "--out", out], check=True,
                           capture_output=True, text=True).stdout
    return [line for line in table.splitlines() if line.startswith("|")]


def rename_runs(path, names):
    with open(path) as f:
        result = json.load(f)
    result["runs"] = names
    with open(path, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    return result


def fit(binary, config, data, run, threads):
    start = time.time()
    subprocess.run([binary, "fit", config, "--data", data, "--out", run, "--threads",
                    str(threads)], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    return summary, time.time() - start


def units_section(args, work):
    truth_text = with_absolute_paths(BENCH_TRUTH, drop_recordings=("validation/",))
    config = os.path.join(work, "bench_units.yaml")
    with open(config, "w") as f:
        f.write(with_absolute_paths(BENCH_FIT, {"polish": "{method: lm, max_iterations: 10}"}))
    runs, rows = [], []
    for name, values in UNITS.items():
        truth = os.path.join(work, name + ".yaml")
        with open(truth, "w") as f:
            f.write(unit_truth(truth_text, values))
        logs = os.path.join(work, name + "_logs")
        subprocess.run([args.binary, "record", truth, "--out", logs, "--blind"], check=True,
                       stdout=subprocess.DEVNULL)
        run = os.path.join(work, "run_" + name)
        summary, seconds = fit(args.binary, config, os.path.join(logs, "train"), run,
                               args.threads)
        with open(os.path.join(run, "best.json")) as f:
            best = json.load(f)["free"]
        rows.append("| %s | %g | %.4f | %g | %.4f | %d | %.1f |" % (
            name, values["bench.Kt_nm_per_a"], best["bench.Kt_nm_per_a"],
            values["joint.pendulum.friction_nm"], best["joint.pendulum.friction_nm"],
            summary["evaluations"], seconds))
        runs.append(run)
    out = os.path.join(args.results, "units.json")
    table = spread(args.binary, runs, out)
    result = rename_runs(out, list(UNITS))
    checks = []
    for key in ("bench.Kt_nm_per_a", "joint.pendulum.friction_nm"):
        truths = [u[key] for u in UNITS.values()]
        p = next(q for q in result["parameters"] if q["name"] == key)
        inside = all(p["lower"] <= t <= p["upper"] for t in truths)
        between = p["between_runs"]
        if p["log"]:  # a factor: compare in ln
            truth_spread = "×%.4f" % math.exp(statistics.stdev([math.log(t) for t in truths]))
            between = "×%.4f" % between
        else:
            truth_spread = "%.4f" % statistics.stdev(truths)
            between = "%.4f" % between
        checks.append("| %s | %s | %s | %.4g – %.4g | %s |" % (
            key, truth_spread, between, p["lower"], p["upper"], "yes" if inside else "no"))
    return ["Three units with a known spread (recorded from scenarios/truth/hidden/none.yaml "
            "with K_t and dry friction changed per unit), each fitted alone with "
            "`scenarios/fit/bench_hidden.yaml` (4 free from its starts, R held; CMA-ES 480 "
            "evaluations, then `polish: {method: lm, max_iterations: 10}`):", "",
            "| unit | K_t truth | K_t fitted | friction truth | friction fitted | evaluations | "
            "wall (s) |", "|---|---|---|---|---|---|---|", *rows, "",
            "`motoflex spread` over the three fits (k = 2; × marks a factor, for log-scale "
            "parameters):", "", *table, "",
            "| parameter | units' own spread | between-run spread | range | holds every truth |",
            "|---|---|---|---|---|", *checks, ""]


def sts_section(args, work):
    logs = sorted(glob.glob(os.path.join(STS_LOGS, "*.json")))
    if not logs:
        return ["STS3250 logs absent (%s): no real-session table." % STS_LOGS, ""]
    config = os.path.join(work, "sts3250.yaml")
    with open(config, "w") as f:
        f.write(with_absolute_paths(STS_FIT, {"polish": "{method: none}"}))
    runs, rows, names = [], [], []
    for log in logs:
        with open(log) as f:
            name = json.load(f).get("trajectory", os.path.basename(log))
        data = os.path.join(work, "sts_" + name)
        os.makedirs(data)
        os.symlink(log, os.path.join(data, os.path.basename(log)))
        run = os.path.join(work, "run_sts_" + name)
        summary, seconds = fit(args.binary, config, data, run, args.threads)
        rows.append("| %s | %d | %.3g | %.1f |" % (name, summary["evaluations"],
                                                   summary["best_fitness"], seconds))
        runs.append(run)
        names.append(name)
    out = os.path.join(args.results, "sts3250.json")
    table = spread(args.binary, runs, out)
    rename_runs(out, names)
    return ["Real sessions of one servo: each STS3250 log fitted alone with "
            "`scenarios/fit/servo_pendulum_sts3250.yaml` (M1, 6 free from the config's starts, "
            "standard errors at the best point, `polish: {method: none}`):", "",
            "| log | evaluations | best fitness | wall (s) |", "|---|---|---|---|", *rows, "",
            "`motoflex spread` over the three fits (k = 2):", "", *table, ""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "benchmarks", "spread"))
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    os.makedirs(args.results, exist_ok=True)
    with tempfile.TemporaryDirectory() as work:
        lines = ["`scripts/report_spread.py`, %s, %d threads, seed 1." % (
            time.strftime("%Y-%m-%d"), args.threads), ""]
        lines += units_section(args, work)
        lines += sts_section(args, work)
    text = "\n".join(lines)
    with open(os.path.join(args.results, "spread.md"), "w") as f:
        f.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
