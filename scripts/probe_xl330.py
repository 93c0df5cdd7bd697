#!/usr/bin/env python3
"""What does and does not explain the XL330 gap to BAM (issue 19): one model (BAM's M3,
load-dependent friction, with K_t, R, the armature and the friction coefficients free) fitted on
BAM's split (kp 100 and 800 train, kp 400 validates) with one modelling choice changed per row,
train and held-out MAE in mrad. Also checks BAM's error gain against the raw logs' own Present
PWM register (what the firmware actually drove), which no fit reads.

Rows: the config as it is; the nominal 7.4 V supply instead of the logged input_volts; a 5 ms
physics step (BAM simulates and runs the P law at the log's 5 ms); BAM's q_offset (our
encoder offset free); the error gain free; the driver's current limit free; CMA-ES with four
IPOP restarts and a 6000-evaluation budget; and BAM's own simulation (5 ms step, nominal 7.4 V)
with three seeds, whose fitted parameters are then run through an independent implementation of
BAM's algorithm (bam_algorithm.py), log by log, to check that motoflex's bench is BAM's model.

Usage: probe_xl330.py [--binary build/motoflex] [--out runs/probe_xl330]
                      [--results benchmarks/xl330_probes] [--jobs 2] [--rows base,supply,...]
Writes RESULTS/xl330_probes.md and .json. Skips (exit 0) when ../shared/data/bam is absent.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import yaml  # python3-yaml (scripts/setup)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bam_algorithm  # noqa: E402  (BAM's Algorithm 1, written independently in numpy)
import report_real_servos as real  # noqa: E402  (the split, the M3 config and the MAE)

ROOT = real.ROOT
MODEL = 3
EVALUATIONS = 2000

# name -> (what changes, config edits)
ROWS = {
    "base": ("the config as it is (logged supply, 1 ms step, error gain fixed)", {}),
    "supply": ("nominal 7.4 V supply (bench.logged_supply 0)",
               {"fixed": {"bench.logged_supply": 0}}),
    "step_5ms": ("5 ms physics step, the P law held over it (BAM's simulation)",
                 {"dt_s": 0.005}),
    "offset": ("encoder offset free, +-0.1 rad (BAM's q_offset)",
               {"free": {"joint.pendulum.encoder_offset_rad": [-0.1, 0.1, 0.0]}}),
    "error_gain": ("error gain free, 0.0005-0.01 (BAM: 0.0028774 fixed)",
                   {"free": {"bench.error_gain": [0.0005, 0.01, 0.0028774]}}),
    "current_limit": ("driver current limit free, 0.3-4 A",
                      {"free": {"motor.current_limit_a": [0.3, 4.0, 1.5]}}),
    "restarts": ("CMA-ES with 4 IPOP restarts, 6000 evaluations",
                 {"restarts": 4, "evaluations": 6000}),
}
# BAM's simulation as bam.md §2b describes it (5 ms step, the P law held over it, the header's
# nominal supply), one fit per seed: what a BAM refit of M3 reaches and how far seeds spread.
BAM_SIMULATION = {"dt_s": 0.005, "fixed": {"bench.logged_supply": 0}}
for _seed in (1, 2, 3):
    ROWS["bam_algorithm_seed%d" % _seed] = (
        "BAM's simulation (5 ms step, nominal 7.4 V), seed %d" % _seed,
        dict(BAM_SIMULATION, seed=_seed))


LAGS_MS = (-20, -10, -5, 0, 5, 10, 20)


def interpolate(times, values, t):
    """Linear interpolation of values(times) at t (times increasing; clamped at the ends)."""
    lo, hi = 0, len(times) - 1
    if t <= times[0]:
        return values[0]
    if t >= times[-1]:
        return values[-1]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (mid, hi) if times[mid] <= t else (lo, mid)
    w = (t - times[lo]) / (times[hi] - times[lo])
    return values[lo] + w * (values[hi] - values[lo])


def pwm_check():
    """Per raw log: the ratio of the logged Present PWM to BAM's predicted PWM (least squares
    over the unsaturated torque-on samples), the share of saturated samples, and the lag of the
    logged position (goal and position read LAG ms earlier) at which the prediction matches the
    PWM best (RMS over the same samples): a firmware loop acting on an older position would show
    a positive lag."""
    folder = os.path.join(real.BAM, "xl330", "raw")
    out = []
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(folder, name)) as f:
            log = json.load(f)
        on = [e for e in log["entries"] if e["torque_enable"]]
        times = [e["timestamp"] for e in on]
        position = [e["position"] for e in on]
        goal = [e["goal_position"] for e in on]
        # the register is unsigned 16-bit
        pwm = [e["load"] - 65536 if e["load"] > 32767 else e["load"] for e in on]
        gain = 0.0028774 * log["kp"] * 885.0  # PWM counts per rad of error

        def predicted(i, lag_ms):
            t = times[i] - lag_ms / 1000.0
            return gain * (interpolate(times, goal, t) - interpolate(times, position, t))

        used = [i for i in range(len(on)) if 20.0 < abs(predicted(i, 0)) < 800.0 and
                abs(pwm[i]) < 880 and times[i] - max(LAGS_MS) / 1000.0 > times[0]]
        num = sum(pwm[i] * predicted(i, 0) for i in used)
        den = sum(predicted(i, 0) ** 2 for i in used)
        rms = {lag: (sum((pwm[i] - predicted(i, lag)) ** 2 for i in used) / len(used)) ** 0.5
               for lag in LAGS_MS} if used else {}
        out.append({"log": name, "trajectory": log["trajectory"], "kp": log["kp"],
                    "pwm_over_predicted": num / den if den else None,
                    "saturated_share": sum(abs(p) >= 880 for p in pwm) / len(pwm) if pwm else None,
                    "rms_counts_by_lag_ms": rms,
                    "best_lag_ms": min(rms, key=rms.get) if rms else None})
    return out


def write_config(row, train, val, work):
    out = os.path.join(work, row, "fit")
    shutil.rmtree(os.path.dirname(out), ignore_errors=True)
    os.makedirs(os.path.dirname(out))
    _, edits = ROWS[row]
    path, _ = real.write_model_fit("xl330", MODEL, train, val, out,
                                   edits.get("evaluations", EVALUATIONS), False)
    with open(path) as f:
        fit = yaml.safe_load(f)
    fit["fixed"].update(edits.get("fixed", {}))
    for name, (lower, upper, start) in edits.get("free", {}).items():
        fit["free"][name] = {"lower": lower, "upper": upper, "start": start}
    if "restarts" in edits:
        fit["strategy"]["restarts"] = edits["restarts"]
    if "seed" in edits:
        fit["seed"] = edits["seed"]
    if "dt_s" in edits:
        with open(fit["scenario"]) as f:
            scenario = yaml.safe_load(f)
        folder = os.path.dirname(fit["scenario"])
        scenario["robot"] = os.path.join(folder, scenario["robot"])
        scenario["motion"]["log"] = os.path.join(folder, scenario["motion"]["log"])
        scenario["physics"]["dt_s"] = edits["dt_s"]
        fit["scenario"] = os.path.join(work, row, "scenario.yaml")
        with open(fit["scenario"], "w") as f:
            yaml.safe_dump(scenario, f, sort_keys=False)
    with open(path, "w") as f:
        yaml.safe_dump(fit, f, sort_keys=False)
    return path, out


def run_row(binary, row, train, val, work):
    path, out = write_config(row, train, val, work)
    start = time.monotonic()
    subprocess.run([binary, "fit", path, "--threads", "1"], check=True,
                   stdout=subprocess.DEVNULL)
    seconds = time.monotonic() - start
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "best.json")) as f:
        best = json.load(f)
    best = best.get("parameters", best)
    imported = os.path.join(out, "imported")
    extra = [k for k in ROWS[row][1].get("free", {})]
    result = {
        "row": row, "change": ROWS[row][0], "evaluations": summary["evaluations"],
        "train_mae_mrad": real.mae_mrad(os.path.join(out, "best"), os.path.join(imported, "train")),
        "val_mae_mrad": real.mae_mrad(os.path.join(out, "best", "validation"),
                                      os.path.join(imported, "validation")),
        "fitted": {k: best[k] for k in ["bench.Kt_nm_per_a", "bench.R_ohm",
                                        "joint.pendulum.load_friction"] + extra},
        "wall_seconds": seconds,
    }
    print(json.dumps(result), flush=True)
    return result


def cross_check(row, train, val, work):
    """Per log, the MAE of motoflex's best rollout and of bam_algorithm.py at the same fitted
    parameters (both BAM's simulation: 5 ms step, nominal supply)."""
    out = os.path.join(work, row, "fit")
    with open(os.path.join(out, "best.json")) as f:
        best = json.load(f)["parameters"]
    params = bam_algorithm.from_motoflex(best)
    logs = []
    for split, folder in (("train", train), ("validation", val)):
        for name in sorted(n for n in os.listdir(folder) if n.endswith(".json")):
            logs.append((split, os.path.join(folder, name)))
    data = bam_algorithm.load_logs([path for _, path in logs])
    numpy_mrad = 1e3 * bam_algorithm.mae_rad(params, data)[0]
    rows = []
    for (split, path), log, theirs in zip(logs, data, numpy_mrad):
        stem = os.path.splitext(os.path.basename(path))[0] + ".csv"
        simulated = os.path.join(out, "best", *(["validation"] if split == "validation" else []),
                                 stem)
        total, count = real.absolute_errors(os.path.join(out, "imported", split, stem), simulated)
        ours = 1e3 * total / count
        rows.append({"log": stem[:-4], "trajectory": log["trajectory"], "kp": log["kp"],
                     "split": split, "motoflex_mae_mrad": ours,
                     "bam_algorithm_mae_mrad": float(theirs)})
    return rows


def markdown(results, pwm, git):
    lines = ["XL330, BAM's split (kp 100 and 800 train, kp 400 validates), model M3 (K_t, R, "
             "armature, Coulomb, viscous, load friction free from the config's starts), CMA-ES "
             "sigma 0.2, seed 1, %d evaluations unless the row says otherwise, one thread per fit; "
             "MAE in mrad. git %s, %s. `scripts/probe_xl330.py`." %
             (EVALUATIONS, git, time.strftime("%Y-%m-%d")), "",
             "| row | change | evaluations | train MAE | held-out MAE | fitted |",
             "|---|---|---|---|---|---|"]
    for r in results:
        fitted = ", ".join("%s %.4g" % (k.split(".")[-1], v) for k, v in r["fitted"].items())
        lines.append("| %s | %s | %d | %.1f | %.1f | %s |" % (
            r["row"], r["change"], r["evaluations"], r["train_mae_mrad"], r["val_mae_mrad"],
            fitted))
    lines += ["", "BAM's error gain against the raw logs' Present PWM register (the duty the "
              "firmware drove; unsaturated torque-on samples, least-squares ratio):", "",
              "| log | trajectory | kp | PWM / predicted | saturated share | best lag (ms) | "
              "RMS at lag 0 / best (counts) |", "|---|---|---|---|---|---|---|"]
    for p in pwm:
        rms = p["rms_counts_by_lag_ms"]
        lines.append("| %s | %s | %d | %s | %.2f | %s | %s |" % (
            p["log"], p["trajectory"], p["kp"],
            "—" if p["pwm_over_predicted"] is None else "%.3f" % p["pwm_over_predicted"],
            p["saturated_share"] or 0.0, "—" if p["best_lag_ms"] is None else p["best_lag_ms"],
            "—" if not rms else "%.1f / %.1f" % (rms[0], rms[p["best_lag_ms"]])))
    checked = [r for r in results if "cross_check" in r]
    if checked:
        lines += ["", "The bam_algorithm rows' fitted parameters run again through BAM's algorithm "
                  "written independently (`scripts/bam_algorithm.py`, bam.md §2b-2d), log by log: "
                  "MAE in mrad, motoflex / bam_algorithm.py:", "",
                  "| log | trajectory | kp | split | " +
                  " | ".join(r["row"] for r in checked) + " |",
                  "|---|---|---|---|" + "---|" * len(checked)]
        for i, log in enumerate(checked[0]["cross_check"]):
            lines.append("| %s | %s | %d | %s | %s |" % (
                log["log"], log["trajectory"], log["kp"], log["split"], " | ".join(
                    "%.1f / %.1f" % (r["cross_check"][i]["motoflex_mae_mrad"],
                                     r["cross_check"][i]["bam_algorithm_mae_mrad"])
                    for r in checked)))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "runs", "probe_xl330"))
    parser.add_argument("--results", default=os.path.join(ROOT, "benchmarks", "xl330_probes"))
    parser.add_argument("--jobs", type=int, default=2, help="fits run at once (one thread each)")
    parser.add_argument("--rows", default=",".join(ROWS))
    args = parser.parse_args()
    if not os.path.isdir(real.BAM):
        print("BAM logs absent (%s): nothing to probe" % real.BAM)
        return 0
    rows = [r for r in args.rows.split(",") if r]
    unknown = [r for r in rows if r not in ROWS]
    if unknown:
        parser.error("unknown rows %s (known: %s)" % (unknown, ", ".join(ROWS)))
    os.makedirs(args.out, exist_ok=True)
    train, val = real.split_logs("xl330", args.out)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda r: run_row(args.binary, r, train, val, args.out), rows))
    for result in results:
        if result["row"].startswith("bam_algorithm"):
            result["cross_check"] = cross_check(result["row"], train, val, args.out)
    pwm = pwm_check()
    os.makedirs(args.results, exist_ok=True)
    document = {"git": real.git_hash(), "date": time.strftime("%Y-%m-%dT%H:%M:%S"),
                "model": "M%d" % MODEL, "split": real.SERVOS["xl330"]["split"],
                "rows": results, "pwm_check": pwm}
    with open(os.path.join(args.results, "xl330_probes.json"), "w") as f:
        json.dump(document, f, indent=2)
    lines = markdown(results, pwm, document["git"])
    with open(os.path.join(args.results, "xl330_probes.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
