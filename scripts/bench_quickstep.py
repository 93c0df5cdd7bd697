#!/usr/bin/env python3
"""The two other solvers against the exact one: `sparse` (dWorldStep's LCP solved by motoflex's
sparse block-pivoting solver; the same LCP) and `quick` (dWorldQuickStep; a different model).
Accuracy on the reference walks, reproducibility and speed of a fit with 1, 2 and 4 workers
(threads and MPI ranks).

1. Accuracy. Every recording of reference_data/nao (four walks and a kick for training; two
   walks, a squat and a held excitation for validation) simulated from the MoToFlex truth
   (`motoflex simulate scenarios/truth/nao_motoflex.yaml --recording R`) with `--solver step`,
   `--solver sparse` and `--solver quick`: joint-angle RMS and maximum of each against step,
   and each one's RMS against the recorded log (recorded with the exact solver plus sensor
   noise and quantisation).
2. Workers. The nao_quick fit (its free parameters, start, strategy and seed; `--seed 3`) for
   GENERATIONS generations with each solver, on 1 thread, 2 threads, 2 MPI ranks and 4 MPI
   ranks (1 thread each; 4 ranks oversubscribe 2 cores): whether best.json's fitness and
   parameters are bit-identical to the 1-thread run, and the wall time of the fit loop.
   Each thread draws QuickStep's row order from its own copy of ODE's generator
   (src/sim/ode_thread_random.cpp), and each sparse rollout owns its LCP solver
   (src/sim/ode_sparse_step.cpp), so threads speed them up as they do the exact solver.

    scripts/bench_quickstep.py [--binary build/motoflex] [--out benchmarks/quickstep]
                               [--generations 2] [--no-mpi]
Writes OUT/quickstep.json and OUT/report.md (two markdown tables).
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
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TRUTH = os.path.join(ROOT, "scenarios", "truth", "nao_motoflex.yaml")
RECORDINGS = ["train/walk_050mm_2s", "train/walk_100mm_1s", "train/walk_150mm_1s",
              "train/walk_200mm_1s", "train/kick", "validation/walk_050mm_1s",
              "validation/walk_100mm_2s", "validation/squat", "validation/excitation_held"]
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_btl_vader_single_copy_mechanism": "none"}


def read_log(path):
    """(joint names, rows of measured angles in rad) of a motoflex CSV log."""
    with open(path) as f:
        lines = [line.strip() for line in f if line.strip() and not line.startswith("#")]
    header = lines[0].split(",")
    columns = [i for i, name in enumerate(header) if name.endswith(".meas")]
    rows = [[float(line.split(",")[i]) for i in columns] for line in lines[1:]]
    return [header[i][:-5] for i in columns], rows


def angle_error_deg(a, b):
    """(RMS, max) in degrees over the frames and joints both logs have."""
    frames = min(len(a), len(b))
    if frames == 0:
        return float("nan"), float("nan")
    total, count, worst = 0.0, 0, 0.0
    for k in range(frames):
        for x, y in zip(a[k], b[k]):
            e = math.degrees(x - y)
            total += e * e
            count += 1
            worst = max(worst, abs(e))
    return math.sqrt(total / count), worst


def simulate(binary, recording, solver, out):
    subprocess.run([binary, "simulate", TRUTH, "--recording", recording, "--solver", solver,
                    "--out", out], check=True, capture_output=True, text=True)
    return read_log(out)[1]


SOLVERS = ("step", "sparse", "quick")


def accuracy(binary, tmp):
    rows = []
    for recording in RECORDINGS:
        recorded = read_log(os.path.join(ROOT, "reference_data", "nao", recording + ".csv"))[1]
        runs = {solver: simulate(binary, recording, solver, os.path.join(tmp, solver + ".csv"))
                for solver in SOLVERS}
        row = {"recording": recording}
        for solver in SOLVERS:
            row[f"frames_{solver}"] = len(runs[solver])
            row[f"rms_{solver}_vs_log_deg"] = angle_error_deg(runs[solver], recorded)[0]
        for solver in ("sparse", "quick"):
            rms, worst = angle_error_deg(runs["step"], runs[solver])
            row[f"rms_step_vs_{solver}_deg"] = rms
            row[f"max_step_vs_{solver}_deg"] = worst
        rows.append(row)
        print(f"  {recording}: step vs sparse {row['rms_step_vs_sparse_deg']:.2e} deg RMS, "
              f"step vs quick {row['rms_step_vs_quick_deg']:.3f}", flush=True)
    return rows


def quick_fit_config(tmp, solver):
    """nao_quick.yaml with the chosen solver, in `tmp` (absolute paths to the repo's files)."""
    fit_dir = os.path.join(ROOT, "scenarios", "fit")
    with open(os.path.join(fit_dir, "nao_base.yaml")) as f:
        scenario = f.read().replace("robot: ../robots/nao",
                                    f"robot: {os.path.join(ROOT, 'scenarios', 'robots', 'nao')}")
    scenario = re.sub(r"solver: \w+", f"solver: {solver}", scenario)
    with open(os.path.join(tmp, f"nao_base_{solver}.yaml"), "w") as f:
        f.write(scenario)
    with open(os.path.join(fit_dir, "nao_quick.yaml")) as f:
        config = f.read()
    config = config.replace("scenario: nao_base.yaml", f"scenario: nao_base_{solver}.yaml")
    config = config.replace("../../reference_data", os.path.join(ROOT, "reference_data"))
    path = os.path.join(tmp, f"nao_quick_{solver}.yaml")
    with open(path, "w") as f:
        f.write(config)
    return path


def run_fit(binary, config, out, generations, threads, ranks):
    command = [binary, "fit", config, "--seed", "3", "--max-generations", str(generations),
               "--threads", str(threads), "--out", out]
    env = dict(os.environ)
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks)] + command
        env.update(MPI_ENV)
    start = time.monotonic()
    subprocess.run(command, check=True, capture_output=True, text=True, env=env)
    wall_s = time.monotonic() - start
    with open(os.path.join(out, "best.json")) as f:
        best = json.load(f)
    return best, wall_s


def workers(binary, tmp, generations, use_mpi):
    setups = [("1 thread", 1, 1), ("2 threads", 2, 1)]
    if use_mpi:
        setups += [("2 MPI ranks", 1, 2), ("4 MPI ranks", 1, 4)]
    rows = []
    for solver in SOLVERS:
        config = quick_fit_config(tmp, solver)
        reference = None
        for name, threads, ranks in setups:
            out = os.path.join(tmp, f"fit_{solver}_{threads}_{ranks}")
            shutil.rmtree(out, ignore_errors=True)
            best, wall_s = run_fit(binary, config, out, generations, threads, ranks)
            key = (best["fitness"], json.dumps(best["parameters"], sort_keys=True))
            reference = reference or key
            rows.append({"solver": solver, "workers": name, "wall_s": wall_s,
                         "fitness": best["fitness"], "identical_to_1_thread": key == reference})
            print(f"  {solver}, {name}: {wall_s:.1f} s, fitness {best['fitness']!r}", flush=True)
    return rows


def markdown(acc, work):
    out = ["| recording | step vs sparse: RMS (deg) | max (deg) | step vs quick: RMS (deg) | "
           "max (deg) | step vs log RMS (deg) | sparse vs log RMS (deg) | quick vs log RMS (deg) |",
           "|---|---|---|---|---|---|---|---|"]
    for r in acc:
        out.append(f"| {r['recording']} | {r['rms_step_vs_sparse_deg']:.2g} | "
                   f"{r['max_step_vs_sparse_deg']:.2g} | {r['rms_step_vs_quick_deg']:.3f} | "
                   f"{r['max_step_vs_quick_deg']:.2f} | {r['rms_step_vs_log_deg']:.3f} | "
                   f"{r['rms_sparse_vs_log_deg']:.3f} | {r['rms_quick_vs_log_deg']:.3f} |")
    out += ["", "| solver | workers | fit wall s | speed-up vs 1 thread | best.json bit-identical "
            "to 1 thread |", "|---|---|---|---|---|"]
    one = {r["solver"]: r["wall_s"] for r in work if r["workers"] == "1 thread"}
    for r in work:
        out.append(f"| {r['solver']} | {r['workers']} | {r['wall_s']:.1f} | "
                   f"{one[r['solver']] / r['wall_s']:.2f}× | "
                   f"{'yes' if r['identical_to_1_thread'] else 'NO'} |")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "benchmarks", "quickstep"))
    parser.add_argument("--generations", type=int, default=2)
    parser.add_argument("--no-mpi", action="store_true", help="threads only")
    args = parser.parse_args()
    use_mpi = not args.no_mpi and shutil.which("mpirun") is not None
    with tempfile.TemporaryDirectory() as tmp:
        print("accuracy: sparse and quick against the exact solver on the reference recordings",
              flush=True)
        acc = accuracy(args.binary, tmp)
        print(f"workers: nao_quick fit, {args.generations} generations", flush=True)
        work = workers(args.binary, tmp, args.generations, use_mpi)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "quickstep.json"), "w") as f:
        json.dump({"generations": args.generations, "accuracy": acc, "workers": work}, f,
                  indent=2)
    table = markdown(acc, work)
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write("# The sparse and quick solvers vs dWorldStep\n\n" + table)
    print(table, end="")
    identical = all(r["identical_to_1_thread"] for r in work)
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())
