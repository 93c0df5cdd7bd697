#!/usr/bin/env python3
"""Designed excitation: which motion to record next so that a fit pins its parameters best.

For a fit config whose scenario moves the robot with an excitation (`motion: excitation:`,
Schroeder-phased multisines or chirps around the base pose, kept 0.02 rad inside the joint
limits), every candidate of a grid (kind × band × amplitude) is
1. simulated at the current estimate of the parameters (`--params`, e.g. a first fit's
   best.json) with the sensor's noise (`--noise-rad`), as `motoflex simulate` does, and
   rejected when its commanded speed exceeds `--max-velocity` (what the hardware may do);
2. scored by the fit's own covariance at that estimate (`motoflex fit` from the estimate, one
   evaluation, `polish: {method: none}`: κσ²(JᵀJ)⁻¹ with the residual's noise and
   autocorrelation): the predicted standard error of every free parameter, relative to its
   value (or to 1 % of its bounds' width where the value is near zero).
The score is the mean log10 of the relative errors (a D-optimality in the log of each
parameter; lower is better); the worst parameter is listed beside it. The best candidate's
scenario and command log are written for the robot to play. With --check, the best and the
worst candidate's simulated data are also fitted from the config's starts, to see the predicted
errors hold.

Usage: design_excitation.py FIT.yaml --params BEST.json --out DIR [--noise-rad 0.0005]
           [--duration 6] [--max-velocity 8] [--kinds multisine,chirp]
           [--bands 0.2-1,0.25-1.5,0.5-3,1-6] [--amplitudes 0.3,0.6,1.2] [--baseline FILE.yaml...]
Writes DIR/design.md (every candidate), DIR/excitation_scenario.yaml (the best candidate's
scenario) and DIR/excitation.csv with its sidecar (its commands, simulated at the estimate).
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_columns import read_columns  # noqa: E402
from yaml_paths import top_level_path, with_absolute_paths, with_relative_paths  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
EXCITATION = re.compile(r"^(\s*excitation:\s*)\{.*\}\s*$")


def excitation_line(text):
    for line in text.splitlines():
        match = EXCITATION.match(line)
        if match:
            return line
    return None


def candidate_scenario(base_text, spec):
    """The scenario text with its excitation replaced by `spec` (a dict)."""
    flow = ", ".join("%s: %s" % (k, v) for k, v in spec.items())
    out = []
    for line in base_text.splitlines(keepends=True):
        match = EXCITATION.match(line.rstrip("\n"))
        out.append(match.group(1) + "{" + flow + "}\n" if match else line)
    return "".join(out)


def peak_command_speed(path):
    """The largest commanded joint speed (rad/s) of a log, from its .cmd columns."""
    header, columns = read_columns(path)
    t = columns["time_s"]
    peak = 0.0
    for name in (n for n in header if n.endswith(".cmd")):
        q = columns[name]
        peak = max([peak] + [abs(q[i + 1] - q[i]) / (t[i + 1] - t[i]) for i in range(len(t) - 1)])
    return peak


def run(binary, *args):
    result = subprocess.run([binary, *args], capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit("motoflex %s failed: %s" % (args[0], result.stderr.strip()))
    return result


def evaluate(args, config, scenario_text, params_file, folder):
    """Simulates the candidate and fits one evaluation from the estimate. Returns (peak speed,
    None) when too fast, else (peak speed, {name: (value, standard error, relative error)}):
    the error relative to the value, or to 1 % of the bounds' width where the value is near 0
    (the bounds as the fit recorded them in its inputs.json)."""
    os.makedirs(os.path.join(folder, "data"), exist_ok=True)
    scenario = os.path.join(folder, "scenario.yaml")
    with open(scenario, "w", encoding="utf-8") as f:
        f.write(scenario_text)
    log = os.path.join(folder, "data", "excitation.csv")
    run(args.binary, "simulate", scenario, "--params", params_file, "--out", log)
    speed = peak_command_speed(log)
    if speed > args.max_velocity:
        return speed, None
    out = os.path.join(folder, "run")
    run(args.binary, "fit", config, "--data", os.path.join(folder, "data"), "--start-from",
        args.params, "--max-evaluations", "1", "--threads", str(args.threads), "--out", out)
    files = {}
    for name in ("summary", "best", "inputs"):
        with open(os.path.join(out, name + ".json"), encoding="utf-8") as f:
            files[name] = json.load(f)
    intervals = files["summary"].get("confidence_intervals", {})
    width = {p["name"]: p["upper"] - p["lower"] for p in files["inputs"]["free"]}
    errors = {}
    for name, value in files["best"]["free"].items():
        se = intervals.get(name, {}).get("standard_error", math.nan)
        scale = max(abs(value), 0.01 * width.get(name, 0.0), 1e-300)
        errors[name] = (value, se, se / scale if math.isfinite(se) else math.inf)
    return speed, errors


def check_lines(args, scored, estimate, names):
    """Fits the best and the worst scored candidate's data from the config's starts (its budget,
    then LM); per parameter |fitted − estimate| over the predicted standard error."""
    config = os.path.join(os.path.dirname(scored[0][4]), "fit_check.yaml")  # the work folder
    with open(config, "w", encoding="utf-8") as f:
        f.write(with_absolute_paths(args.fit, {"polish": "{method: lm, max_iterations: 10}"}))
    lines = ["", "Check: each candidate's data fitted from the config's starts (its budget, then "
             "LM): |fitted − estimate| in predicted standard errors, the estimate being the "
             "parameters the data were simulated with (about 1 or less where the prediction "
             "holds).", "",
             "| candidate | " + " | ".join(names) + " |", "|---|" + "---|" * len(names)]
    for score, label, _, errors, folder in (scored[0], scored[-1]):
        out = os.path.join(folder, "check")
        run(args.binary, "fit", config, "--data", os.path.join(folder, "data"), "--threads",
            str(args.threads), "--out", out)
        with open(os.path.join(out, "best.json"), encoding="utf-8") as f:
            fitted = json.load(f)["free"]
        cells = ["%.2f" % (abs(fitted[n] - estimate[n]) / errors[n][1]) for n in names]
        lines.append("| %s (score %.3f) | %s |" % (label, score, " | ".join(cells)))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fit")
    parser.add_argument("--params", required=True, help="the current estimate (best.json)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--noise-rad", type=float, default=0.0005)
    parser.add_argument("--duration", type=float, default=6.0)
    parser.add_argument("--max-velocity", type=float, default=8.0, help="rad/s")
    parser.add_argument("--kinds", default="multisine,chirp")
    parser.add_argument("--bands", default="0.2-1,0.25-1.5,0.5-3,1-6")
    parser.add_argument("--amplitudes", default="0.3,0.6,1.2")
    parser.add_argument("--keep-candidates", action="store_true",
                        help="keep every candidate's scenario, log and fit in OUT/candidates")
    parser.add_argument("--check", action="store_true",
                        help="also fit the best and the worst scored candidate's data from the "
                             "config's starts and compare the errors with the predicted ones "
                             "(meaningful when --params is the truth behind the simulation)")
    parser.add_argument("--baseline", nargs="*", default=[],
                        help="scenario files to score beside the grid (e.g. the motions "
                             "recorded so far)")
    args = parser.parse_args()

    scenario_path = top_level_path(args.fit, "scenario")
    base_text = with_absolute_paths(scenario_path)
    if excitation_line(base_text) is None:
        raise SystemExit("%s: the scenario has no `excitation: {...}` motion to design" %
                         scenario_path)
    with open(args.params, encoding="utf-8") as f:
        estimate = json.load(f)
    values = dict(estimate.get("free", estimate))
    values["sensor.noise_rad"] = args.noise_rad
    os.makedirs(args.out, exist_ok=True)
    work = (os.path.join(args.out, "candidates") if args.keep_candidates else
            tempfile.mkdtemp(prefix="motoflex_excitation_"))
    os.makedirs(work, exist_ok=True)
    try:
        return prepare_and_design(args, base_text, values, work)
    finally:
        if not args.keep_candidates:
            shutil.rmtree(work, ignore_errors=True)


def prepare_and_design(args, base_text, values, work):
    params_file = os.path.join(work, "simulate_params.json")
    with open(params_file, "w", encoding="utf-8") as f:
        json.dump(values, f, indent=2)
    config = os.path.join(work, "fit_covariance.yaml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(with_absolute_paths(args.fit, {"polish": "{method: none}"}))

    candidates = []
    for kind in args.kinds.split(","):
        for band in args.bands.split(","):
            f0, f1 = (float(x) for x in band.split("-"))
            for amplitude in (float(a) for a in args.amplitudes.split(",")):
                spec = {"kind": kind, "amplitude_rad": amplitude, "f0_hz": f0, "f1_hz": f1,
                        "duration_s": args.duration, "rate_hz": 100, "ramp_s": 0.5}
                candidates.append(("%s %g-%g Hz, %g rad" % (kind, f0, f1, amplitude),
                                   candidate_scenario(base_text, spec)))
    for path in args.baseline:
        candidates.append(("baseline: " + os.path.basename(path), with_absolute_paths(path)))

    return design(args, candidates, work, config, params_file, values)


def design(args, candidates, work, config, params_file, values):
    rows = []
    for index, (label, text) in enumerate(candidates):
        folder = os.path.join(work, "%02d" % index)
        speed, errors = evaluate(args, config, text, params_file, folder)
        if errors is None:
            rows.append((math.inf, label, speed, None, folder))
            print("%-40s peak %.2f rad/s: faster than --max-velocity" % (label, speed))
            continue
        score = sum(math.log10(e[2]) for e in errors.values()) / len(errors)
        rows.append((score, label, speed, errors, folder))
        print("%-40s peak %.2f rad/s  score %.3f" % (label, speed, score))
    rows.sort(key=lambda r: r[0])
    names = next(r[3] for r in rows if r[3] is not None).keys()
    lines = ["Designed excitation for `%s` at the estimate `%s` (sensor noise %g rad, at most "
             "%g rad/s): predicted standard error of each free parameter relative to its value "
             "(the fit's covariance at the estimate, one evaluation, `polish: {method: none}`); "
             "score = mean log10 of them, lower is better. `scripts/design_excitation.py`." % (
                 os.path.relpath(args.fit, ROOT), os.path.relpath(args.params, ROOT),
                 args.noise_rad, args.max_velocity), "",
             "| candidate | peak speed (rad/s) | score | " + " | ".join(names) + " |",
             "|---|---|---|" + "---|" * len(names)]
    for score, label, speed, errors, _ in rows:
        if errors is None:
            lines.append("| %s | %.2f | too fast |%s" % (label, speed, " – |" * len(names)))
        else:
            lines.append("| %s | %.2f | %.3f | %s |" % (label, speed, score, " | ".join(
                "%.2g" % errors[n][2] for n in names)))
    if args.check:
        lines += check_lines(args, [r for r in rows if r[3] is not None], values, names)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "design.md"), "w", encoding="utf-8") as f:
        f.write(text)
    best = rows[0][4]
    # The scenario to play, and its simulated log with the log's own sidecar (excitation.yaml).
    with open(os.path.join(best, "scenario.yaml"), encoding="utf-8") as f:
        scenario = f.read()
    with open(os.path.join(args.out, "excitation_scenario.yaml"), "w", encoding="utf-8") as f:
        f.write(with_relative_paths(scenario, args.out))
    for name in ("excitation.csv", "excitation.yaml"):
        shutil.copy(os.path.join(best, "data", name), os.path.join(args.out, name))
    print(text)
    print("best: %s -> %s" % (rows[0][1], os.path.join(args.out, "excitation_scenario.yaml")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
