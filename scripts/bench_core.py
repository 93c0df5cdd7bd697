#!/usr/bin/env python3
"""Simulator-core benchmark: physics steps per second of the bundled robots.

Runs `build/motoflex bench` for each configuration REPEATS times (interleaved, so machine load
affects all alike), prints the median steps/s and real-time factor per configuration, the
speed-up of 4 rollouts on 2 threads over 1 thread (each solver), and the gain of universal
joints. Solvers: step (dWorldStep, libode's dense Dantzig LCP), sparse (dWorldStep with
motoflex's sparse block-pivoting LCP solver: the same LCP) and quick (dWorldQuickStep).
Usage: scripts/bench_core.py [--repeats 3] [--seconds 5] [--json OUT.json]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINARY = os.path.join(ROOT, "build", "motoflex")
SOLVERS = ("step", "sparse", "quick")

CONFIGS = [
    ("nao rigid, ideal servos", ["--robot", "nao", "--servo", "ideal", "--flex", "1"]),
    ("nao rigid, ideal servos, no universal", ["--robot", "nao", "--servo", "ideal", "--flex", "1", "--no-universal"]),
    ("nao full pipeline (100 gear sub-steps, 2 flex sub-bodies)",
     ["--robot", "nao", "--servo", "motoflex", "--flex", "2", "--substeps", "100"]),
    ("nao full pipeline, no universal",
     ["--robot", "nao", "--servo", "motoflex", "--flex", "2", "--substeps", "100", "--no-universal"]),
    ("titan8 velocity servos", ["--robot", "titan8"]),
]


def bench(args, seconds, solver, extra=()):
    out = subprocess.run([BINARY, "bench", *args, "--seconds", str(seconds), "--solver", solver, *extra],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--json")
    parser.add_argument("--md", help="also write the table as Markdown (README's speed table)")
    a = parser.parse_args()
    if not os.path.exists(BINARY):
        sys.exit("build/motoflex is missing: run scripts/build first")

    samples = {}
    for _ in range(a.repeats):
        for name, args in CONFIGS:
            for solver in SOLVERS:
                r = bench(args, a.seconds, solver)
                samples.setdefault((name, solver), []).append(r)
        for solver in SOLVERS:
            one = bench(CONFIGS[2][1], a.seconds, solver, ["--rollouts", "4", "--threads", "1"])
            two = bench(CONFIGS[2][1], a.seconds, solver, ["--rollouts", "4", "--threads", "2"])
            samples.setdefault(("threads", solver), []).append(one["wall_s"] / two["wall_s"])

    rows = []
    print(f"{'configuration':62s} {'solver':6s} {'steps/s':>9s} {'x realtime':>10s}  end")
    for name, _ in CONFIGS:
        for solver in SOLVERS:
            runs = samples[(name, solver)]
            sps = statistics.median(r["steps_per_s"] for r in runs)
            rows.append({"configuration": name, "solver": solver, "steps_per_s": sps,
                         "realtime_factor": sps / 1000.0, "end": runs[0]["end"]})
            print(f"{name:62s} {solver:6s} {sps:9.0f} {sps / 1000.0:10.1f}  {runs[0]['end']}")
    speedup = {solver: statistics.median(samples[("threads", solver)]) for solver in SOLVERS}
    print(f"4 rollouts of the full nao pipeline on 2 threads vs 1 thread: speed-up "
          f"{speedup['step']:.2f}x exact, {speedup['sparse']:.2f}x sparse, "
          f"{speedup['quick']:.2f}x quick (median of {a.repeats})")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"rows": rows, "speedup_4_rollouts_2_threads": speedup["step"],
                       "speedup_4_rollouts_2_threads_sparse": speedup["sparse"],
                       "speedup_4_rollouts_2_threads_quick": speedup["quick"]}, f, indent=2)
    if a.md:
        write_markdown(a.md, rows, speedup, a.repeats, a.seconds)


def write_markdown(path, rows, speedup, repeats, seconds):
    """Steps/s per configuration, one column per solver, as the README shows them."""
    lines = [f"Physics steps per second of one rollout on one core, median of {repeats} runs "
             f"of {seconds:g} s; load average at the end {os.getloadavg()[0]:.1f}.", "",
             "| model | dWorldStep | dWorldStep, sparse LCP | sparse / step | dWorldQuickStep |",
             "|---|---|---|---|---|"]
    for name, _ in CONFIGS:
        sps = {r["solver"]: r["steps_per_s"] for r in rows if r["configuration"] == name}
        step, sparse, quick = (f"{sps[k]:,.0f}".replace(",", " ") for k in SOLVERS)
        lines.append(f"| {name} | {step} | {sparse} | {sps['sparse'] / sps['step']:.2f}× | "
                     f"{quick} |")
    lines += ["", f"4 rollouts of the full Nao pipeline on 2 threads vs 1 thread: speed-up "
              f"{speedup['step']:.2f}x with dWorldStep, {speedup['sparse']:.2f}x with the sparse "
              f"LCP, {speedup['quick']:.2f}x with dWorldQuickStep."]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
