#!/usr/bin/env python3
"""Where one physics step's time goes: instructions per stage, counted by callgrind.

Runs `motoflex bench` under `valgrind --tool=callgrind` for two simulated durations and takes
the difference of each function's inclusive instruction count, so model loading (and
sdformat's regex set-up at program start) cancels and what remains is the cost of the extra
steps. Instructions are not seconds (a cache miss costs more than an add), but they are the
same whatever else runs on a shared machine, and the shares agree with `perf record` to a few
percent on this code (dense arithmetic in both ODE and motoflex).

Stages, as shares of motoflex::Rollout::step (everything a physics step does):
  ODE step (dWorldStep / dWorldQuickStep), and within it the LCP solver
  (dxSolveLCP for dWorldStep: libode's, or motoflex's with --solver sparse; QuickStep's SOR
  iterations are inlined in Debian's ODE, so no share is given there) and the rest (Jacobians, the
  system matrix and its factorisation, integration);
  collision (Rollout::Impl::collide_feet: ODE's dCollide per foot shape and the contact joints);
  servo pipeline (Rollout::Impl::apply_servos: PID, motor, gear, friction), and within it the
  sub-stepped gear train (GearTrain::update);
  the rest of motoflex's step (sensors, joint feedback, bookkeeping).

    scripts/profile_step.py [--binary build/motoflex] [--out benchmarks/profile]
                            [--short 0.2] [--long 0.6] [--case NAME ...]
Writes OUT/profile.json and OUT/report.md (a markdown table; README 'Solvers and
reproducibility' is generated from it by scripts/readme_tables.py).
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FULL = ["--robot", "nao", "--servo", "motoflex", "--flex", "2", "--substeps", "100"]
CASES = {
    "nao full pipeline, dWorldStep": FULL + ["--solver", "step"],
    "nao full pipeline, dWorldStep, sparse LCP": FULL + ["--solver", "sparse"],
    "nao full pipeline, dWorldQuickStep": FULL + ["--solver", "quick"],
    "nao rigid, ideal servos, dWorldStep": ["--robot", "nao", "--servo", "ideal", "--solver",
                                            "step"],
}
# Stage -> regular expressions matched against the function names of callgrind_annotate; the
# stage's cost is the largest inclusive count among its matches (the outermost function).
STAGES = {
    "step": [r"^motoflex::Rollout::step\("],
    "ode": [r"^dWorldStep$", r"^dWorldQuickStep$"],
    # Debian's ODE inlines QuickStep's SOR iterations into dxQuickStepIsland: no LCP share there.
    "lcp": [r"^dxSolveLCP\("],
    "collision": [r"^motoflex::Rollout::Impl::collide_feet\(", r"^dSpaceCollide$"],
    "servos": [r"^motoflex::Rollout::Impl::apply_servos\("],
    "gear": [r"^motoflex::GearTrain::update\("],
}
LINE = re.compile(r"^\s*([\d,]+)\s+\([^)]*\)\s+(?:[^:]*):(.*?)(?:\s+\[[^\]]*\])?\s*$")


def inclusive_counts(binary, options, seconds):
    """{function name: inclusive instructions} of one bench run."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "callgrind.out")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", binary,
                        "bench", *options, "--seconds", str(seconds)],
                       capture_output=True, text=True, check=True)
        text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                              capture_output=True, text=True, check=True).stdout
    counts = {}
    for line in text.splitlines():
        match = LINE.match(line)
        if match:
            name = match.group(2).strip()
            counts[name] = max(counts.get(name, 0), int(match.group(1).replace(",", "")))
    return counts


def stage_cost(counts, patterns):
    best = 0
    for name, value in counts.items():
        if any(re.search(p, name) for p in patterns):
            best = max(best, value)
    return best


def profile(binary, options, short_s, long_s):
    a = inclusive_counts(binary, options, short_s)
    b = inclusive_counts(binary, options, long_s)
    steps = round((long_s - short_s) / 0.001)
    per_step = {stage: (stage_cost(b, p) - stage_cost(a, p)) / steps for stage, p in STAGES.items()}
    if options[options.index("--solver") + 1] == "step":
        # With --solver step, motoflex's dxSolveLCP (src/sim/ode_sparse_step.cpp) forwards to
        # libode's of the same name; callgrind takes the two for one recursive function and
        # counts the solve once per activation, twice. The wrapper itself costs a few
        # instructions, so half the count is libode's solver.
        per_step["lcp"] /= 2.0
    total = per_step["step"]
    if total <= 0:
        raise RuntimeError("no motoflex::Rollout::step in the profile (a stripped binary?)")
    share = {stage: value / total for stage, value in per_step.items()}
    if per_step["lcp"] <= 0:
        share["lcp"] = None
    return {"options": options, "steps": steps, "instructions_per_step": per_step,
            "share_of_step": share,
            "motoflex_own_share": 1.0 - share["ode"] - share["collision"]}


def percent(x):
    return f"{100.0 * x:.1f} %"


def markdown(results):
    rows = ["| case | instructions per step | ODE step | of which LCP | collision | servo "
            "pipeline | of which gear | rest of motoflex |",
            "|---|---|---|---|---|---|---|---|"]
    for name, r in results.items():
        s = r["share_of_step"]
        rest = 1.0 - s["ode"] - s["collision"] - s["servos"]
        rows.append(f"| {name} | {r['instructions_per_step']['step']:,.0f} | {percent(s['ode'])} | "
                    f"{percent(s['lcp']) if s['lcp'] is not None else '–'} | {percent(s['collision'])} | {percent(s['servos'])} | "
                    f"{percent(s['gear'])} | {percent(rest)} |")
    return "\n".join(rows) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "benchmarks", "profile"))
    parser.add_argument("--short", type=float, default=0.2, help="shorter simulated duration, s")
    parser.add_argument("--long", type=float, default=0.6, help="longer simulated duration, s")
    parser.add_argument("--case", action="append", choices=sorted(CASES),
                        help="profile only this case (repeatable)")
    args = parser.parse_args()
    if not args.long > args.short > 0.0:
        parser.error("--long must exceed --short, both > 0")
    results = {}
    for name in args.case or CASES:
        print(f"profiling {name} ...", flush=True)
        results[name] = profile(args.binary, CASES[name], args.short, args.long)
    os.makedirs(args.out, exist_ok=True)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    with open(os.path.join(args.out, "profile.json"), "w") as f:
        json.dump({"commit": commit, "date": datetime.date.today().isoformat(),
                   "method": "callgrind inclusive instructions, difference of "
                             f"{args.long} s and {args.short} s runs", "cases": results}, f,
                  indent=2)
    table = markdown(results)
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write("# Instructions per physics step, by stage\n\n" + table)
    print(table, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
