#!/usr/bin/env python3
"""Fit speed on the paper's real problem (issue 20), measured in one run on this machine.

1. Physics steps/s per core of the Nao's full MoToFlex pipeline (100 gear sub-steps, 2 flexible
   sub-bodies per thigh and tibia), exact (dWorldStep with libode's LCP solver), sparse
   (dWorldStep with motoflex's: the same LCP) and quick (dWorldQuickStep, seeded per rollout),
   `motoflex bench`, REPEATS interleaved runs, medians: one rollout on one thread, and
   THREADS rollouts on THREADS threads (per core: the total over THREADS).
2. motoflex against MuJoCo 2.2.2 on the same exported Nao and motion (the Nao walking on the
   ground with the full servo, the validation walk, 1 ms steps), `motoflex export --check-mujoco`:
   steps/s of the three ODE solvers and of MuJoCo, ratios taken within each run, and the angle
   RMS of the sparse replay against the exact one.
3. The `nao_paper` fit (scenarios/fit/nao_paper.yaml: the paper's 22 genes as 19 free
   parameters, the five 10 s training logs, from the nominal defaults) on 2 threads: evaluations
   and wall time until the best fitness first reaches (1 + TOLERANCE)·F(truth), F(truth) being
   the fitness at the truth's values of the free parameters (one evaluation, the held ones as the
   config holds them), read from the run's generations.csv; the final best, the parameters it
   recovers within 5 % of the truth and the ones the data do not identify (summary.json's
   sensitivities and, with the LM polish, its intervals).
4. The share of physics frames racing saved in that fit (summary.json's early_termination).
5. The same problem in stages (--fit chain or both; scripts/report_paper_chain.py's stages: LM
   with its covariance on the first 2 s of the logs, then CMA-ES over the parameters that did not
   identify, on the first 4 s and then on the whole logs): per stage and in total, evaluations,
   wall time and the best fitness against F(truth) on the whole 10 s logs, and the parameters
   within 5 % of the truth at the end.

    scripts/bench_fit_speed.py                       # parts 1, 2 and the CMA-ES fit (its budget)
    scripts/bench_fit_speed.py --fit both            # ... and the staged chain
    scripts/bench_fit_speed.py --fit chain           # parts 1, 2 and the chain only
    scripts/bench_fit_speed.py --fit-seconds 600     # a shorter CMA-ES fit
    scripts/bench_fit_speed.py --skip-fit            # parts 1 and 2 only

Writes OUT/fit_speed.md and OUT/fit_speed.json (default benchmarks/fit_speed/).
"""

import argparse
import concurrent.futures
import fnmatch
import json
import random
import shutil
import statistics
import subprocess
from pathlib import Path

import yaml  # python3-yaml (scripts/setup)

from bench_strategies import derived_config, first_reach, read_generations, truth_point, \
    write_config
from report_files import write_report

ROOT = Path(__file__).resolve().parent.parent
FIT = ROOT / "scenarios" / "fit" / "nao_paper.yaml"
TRUTH = ROOT / "scenarios" / "truth" / "nao_motoflex.yaml"
PIPELINE = ["--robot", "nao", "--servo", "motoflex", "--flex", "2", "--substeps", "100"]


def run_json(command):
    out = subprocess.run([str(c) for c in command], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


SOLVERS = ("step", "sparse", "quick")


def steps_per_core(binary, repeats, seconds, threads):
    """Medians of steps/s per core: one rollout on one thread (per solver), and THREADS
    rollouts on THREADS threads divided by THREADS ("<solver>_parallel")."""
    def rate(solver, workers):
        line = run_json([binary, "bench", *PIPELINE, "--seconds", seconds, "--solver", solver,
                         "--rollouts", workers, "--threads", workers])
        return line["steps_per_s"] / workers

    rates = {key: [] for solver in SOLVERS for key in (solver, solver + "_parallel")}
    for _ in range(repeats):
        for solver in SOLVERS:
            rates[solver].append(rate(solver, 1))
            rates[solver + "_parallel"].append(rate(solver, threads))
    return {key: statistics.median(values) for key, values in rates.items()}


def against_mujoco(binary, repeats, out):
    truth = json.loads((ROOT / "reference_data/nao/truth/validation/walk_050mm_1s.json")
                       .read_text())["parameters"]
    truth["sensor.noise_rad"] = 0.0  # MuJoCo's angles are exact: compare exact encoders
    truth["sensor.resolution_bits"] = 0
    params = out / "walk_truth.json"
    params.write_text(json.dumps(truth))
    runs = [run_json([binary, "export", params, "--robot", ROOT / "scenarios/robots/nao",
                      "--servo", "motoflex", "--format", "mjcf", "--out", out / "nao.xml",
                      "--check-mujoco", ROOT / "reference_data/nao/validation/walk_050mm_1s.csv",
                      "--settle", "0.5"]) for _ in range(repeats)]
    return {
        "model": "Nao walking on the ground, full MoToFlex servo (validation walk, 10 s)",
        "mujoco_steps_per_s": statistics.median(r["mujoco_steps_per_s"] for r in runs),
        "exact_steps_per_s": statistics.median(r["motoflex_steps_per_s"] for r in runs),
        "quick_steps_per_s": statistics.median(r["motoflex_quick_steps_per_s"] for r in runs),
        "sparse_steps_per_s": statistics.median(r["motoflex_sparse_steps_per_s"] for r in runs),
        "sparse_over_mujoco": statistics.median(
            r["motoflex_sparse_steps_per_s"] / r["mujoco_steps_per_s"] for r in runs),
        "rms_deg_sparse_vs_exact": runs[0]["rms_deg_sparse_vs_step"],
        "exact_over_mujoco": statistics.median(
            r["motoflex_steps_per_s"] / r["mujoco_steps_per_s"] for r in runs),
        "quick_over_mujoco": statistics.median(
            r["motoflex_quick_steps_per_s"] / r["mujoco_steps_per_s"] for r in runs),
        "rms_deg_exact_vs_mujoco": runs[0]["rms_deg"],
        "rms_deg_quick_vs_mujoco": runs[0]["rms_deg_quick"],
    }


def summary_at(binary, out, threads, point, name):
    """summary.json of one evaluation of nao_paper at `point` (values of its free parameters;
    the free set is the ideal servo's torque limit, which the motoflex law never reads; the point
    is `fixed:`)."""
    config = derived_config(FIT, {"kind": "nlopt", "algorithm": "sbplx"}, 1, threads, 1)
    config["free"] = {"ideal.torque_max_nm": {"lower": 1.0, "upper": 100.0, "start": 20.0}}
    config["fixed"] = {**(config.get("fixed") or {}), **point}
    path = out / f"{name}.yaml"
    write_config(path, config)
    run_dir = out / "runs" / name
    shutil.rmtree(run_dir, ignore_errors=True)  # a fit refuses a folder that holds one
    subprocess.run([binary, "fit", path, "--out", run_dir], check=True, stdout=subprocess.DEVNULL)
    return json.loads((run_dir / "summary.json").read_text())


def fitness_at(binary, out, threads, point, name):
    """F at `point` (values of nao_paper's free parameters): one evaluation (summary_at)."""
    return summary_at(binary, out, threads, point, name)["best_fitness"]


def truth_fitness(binary, out, threads):
    point = truth_point(FIT, TRUTH)
    return fitness_at(binary, out, threads, point, "truth_fitness"), point


def perturbed_truths(point, count, scale, seed=1):
    """`count` points near the truth: every free entry of nao_paper.yaml multiplied by
    1 ± scale (random sign; a tied pattern such as joint.*Roll.friction_nm moves as one, an
    `each: true` pattern per group), so each point stays in the fit's search space."""
    free = yaml.safe_load(FIT.read_text())["free"]
    rng = random.Random(seed)
    points = []
    for _ in range(count):
        moved = dict(point)
        for pattern, spec in free.items():
            names = [n for n in point if fnmatch.fnmatchcase(n, pattern)]
            groups = [[n] for n in names] if spec.get("each") else [names]
            for group in groups:
                factor = 1.0 + scale * rng.choice((-1.0, 1.0))
                for n in group:
                    moved[n] = point[n] * factor
        points.append(moved)
    return points


def fitness_floor(binary, out, threads, point, f_truth, count, scale):
    """How finely F resolves the truth: F at `count` points `scale` (relative) from it, each
    parameter moved far less than any fit can locate it. A walking robot with contacts is
    chaotic, so these values scatter around F(truth) instead of matching it; a target inside that
    scatter is reached by chance, not by search."""
    points = perturbed_truths(point, count, scale)
    with concurrent.futures.ThreadPoolExecutor(max(1, threads)) as pool:
        values = list(pool.map(lambda ip: fitness_at(binary, out, 1, ip[1],
                                                            f"floor/{scale:g}_{ip[0]}"),
                               enumerate(points)))
    ratios = sorted(v / f_truth for v in values)
    return {"scale": scale, "count": count, "fitness": values,
            "ratio_min": ratios[0], "ratio_median": statistics.median(ratios),
            "ratio_max": ratios[-1]}


def recovered(summary, point, within=0.05):
    """Per free parameter of the fit (a tied pattern such as joint.*Roll.friction_nm compared
    with the truth of the joints it matches, which share one value): fitted, truth, relative
    error, its sensitivity and whether the data determine it (summary.json's sensitivity)."""
    sensitivity = summary.get("sensitivity", {}).get("parameters", {})
    unidentified = set(summary.get("sensitivity", {}).get("undetermined", []))
    unidentified |= set(summary.get("uncertainty", {}).get("unidentified", []))
    rows = []
    for name, value in summary.get("free", {}).items():
        matches = [v for key, v in point.items() if fnmatch.fnmatchcase(key, name)]
        if not matches:
            continue
        truth = matches[0]
        error = abs(value - truth) / abs(truth) if truth != 0 else abs(value)
        rows.append({"name": name, "fitted": value, "truth": truth, "relative_error": error,
                     "within": error <= within,
                     "sensitivity": sensitivity.get(name, {}).get(
                         "relative_fitness_change_per_bound_width"),
                     "unidentified": name in unidentified})
    return rows


def fit_paper(binary, out, threads, seconds, tolerance, floor_points, floor_scale):
    f_truth, point = truth_fitness(binary, out, threads)
    target = (1.0 + tolerance) * f_truth
    floor = fitness_floor(binary, out, threads, point, f_truth, floor_points, floor_scale)
    print(f"F(truth) {f_truth:.4g}; {floor_points} points {floor_scale:g} from it: "
          f"{floor['ratio_min']:.3f}-{floor['ratio_max']:.3f} x F(truth)", flush=True)
    config = yaml.safe_load(FIT.read_text())
    for key in ("scenario", "data", "validation"):
        config[key] = str((FIT.parent / config[key]).resolve())
    config.pop("out", None)
    config["threads"] = threads
    if seconds:
        config["budget"] = dict(config.get("budget", {}), seconds=seconds)
    path = out / "nao_paper.yaml"
    write_config(path, config)
    run_dir = out / "runs" / "nao_paper"
    shutil.rmtree(run_dir, ignore_errors=True)
    subprocess.run([binary, "fit", path, "--out", run_dir], check=True, stdout=subprocess.DEVNULL)
    summary = json.loads((run_dir / "summary.json").read_text())
    rows = read_generations(run_dir)
    reach = first_reach(rows, target)
    floor_target = floor["ratio_max"] * f_truth
    floor_reach = first_reach(rows, floor_target)
    saved = summary.get("early_termination", {})
    return {
        "truth_fitness": f_truth, "target": target, "tolerance": tolerance,
        "reached": reach is not None,
        "evaluations_to_target": reach["evaluations"] if reach else None,
        "seconds_to_target": reach["seconds"] if reach else None,
        "floor": floor, "floor_target": floor_target,
        "floor_reach": ({"evaluations": floor_reach["evaluations"],
                         "seconds": floor_reach["seconds"]} if floor_reach else None),
        "best_fitness": summary["best_fitness"], "evaluations": summary["evaluations"],
        "seconds": summary.get("seconds"), "stop_reason": summary.get("stop_reason"),
        "converged": summary.get("converged"), "threads": threads,
        "racing": saved,
        "parameters": recovered(summary, point),
        "validation_rms_deg": summary.get("validation", {}).get("rms_deg", {}).get("overall"),
    }


def fit_chain(binary, out, threads, tolerance):
    """Runs report_paper_chain's stages into OUT/runs/chain; see chain_result."""
    import report_paper_chain  # imports this module: a late import keeps the cycle harmless
    chain_dir = out / "runs" / "chain"
    chain_dir.mkdir(parents=True, exist_ok=True)
    report_paper_chain.run_stages(binary, chain_dir)
    return chain_result(binary, out, threads, tolerance)


def chain_result(binary, out, threads, tolerance):
    """Each stage's evaluations, wall time and best fitness against F(truth) on the whole 10 s
    logs (nao_paper.yaml's scoring, report_paper_chain.whole_log_fitness), the totals, and the
    final parameters."""
    import report_paper_chain
    stages = report_paper_chain.stage_results(binary, out / "runs" / "chain", threads)
    for stage in stages:
        stage["ratio"] = stage["whole_log_fitness"] / stage["whole_log_truth_fitness"]
    last = stages[-1]
    return {"stages": stages, "tolerance": tolerance, "threads": threads,
            "evaluations": sum(s["evaluations"] for s in stages),
            "seconds": sum(s["wall_seconds"] for s in stages),
            "reached": last["ratio"] <= 1.0 + tolerance,
            "within": [p["name"] for p in last["parameters"] if p["within"]],
            "free": len(last["parameters"])}


def chain_lines(chain):
    lines = []
    for stage in chain["stages"]:
        lines.append(f"| chain, stage {stage['stage']} on {chain['threads']} threads: evaluations, "
                     f"wall, best / F(truth) on the whole logs | {stage['evaluations']}, {stage['wall_seconds']:.0f} s, "
                     f"{stage['ratio']:.2f} |")
    verdict = "reached" if chain["reached"] else "not reached"
    lines += [f"| chain, total: evaluations, wall; within {100 * chain['tolerance']:g} % of "
              f"F(truth) | {chain['evaluations']}, {chain['seconds']:.0f} s; {verdict} "
              f"({chain['stages'][-1]['ratio']:.2f} × F(truth)) |",
              f"| chain: within 5 % of the truth ({len(chain['within'])} of {chain['free']}) | "
              f"{', '.join(chain['within']) or 'none'} |"]
    return lines


def racing_share(early):
    """Frames saved by racing as a share of the frames a full evaluation would have run."""
    saved, run = early.get("frames_saved", 0), early.get("frames_simulated", 0)
    return 100.0 * saved / (saved + run) if saved + run else 0.0


def report_lines(result):
    speed, mujoco = result["steps_per_core"], result["mujoco"]
    lines = ["| measure | value |", "|---|---|",
             f"| Nao full pipeline, steps/s per core, exact | {speed['step']:.0f} |",
             f"| Nao full pipeline, steps/s per core, quick | {speed['quick']:.0f} |"]
    if "sparse" in speed:
        lines.insert(3, f"| Nao full pipeline, steps/s per core, exact with the sparse LCP "
                        f"(`solver: sparse`) | {speed['sparse']:.0f} |")
    if "step_parallel" in speed:
        threads = result["threads"]
        if "sparse_parallel" in speed:
            lines.append(f"| same, {threads} rollouts on {threads} threads, per core: exact, "
                         f"sparse, quick | {speed['step_parallel']:.0f}, "
                         f"{speed['sparse_parallel']:.0f}, {speed['quick_parallel']:.0f} |")
        else:
            lines.append(f"| same, {threads} rollouts on {threads} threads, per core: exact, "
                         f"quick | {speed['step_parallel']:.0f}, {speed['quick_parallel']:.0f} |")
    lines += [f"| {mujoco['model']}: MuJoCo steps/s | {mujoco['mujoco_steps_per_s']:.0f} |",
              f"| same: motoflex / MuJoCo, exact | {mujoco['exact_over_mujoco']:.2f} |"]
    if "sparse_over_mujoco" in mujoco:
        lines += [f"| same: motoflex / MuJoCo, sparse | {mujoco['sparse_over_mujoco']:.2f} |",
                  f"| same: sparse vs exact replay, angle RMS (deg) | "
                  f"{mujoco['rms_deg_sparse_vs_exact']:.2g} |"]
    lines.append(f"| same: motoflex / MuJoCo, quick | {mujoco['quick_over_mujoco']:.2f} |")
    fit = result.get("fit")
    if fit:
        reach = (f"{fit['evaluations_to_target']} evaluations, {fit['seconds_to_target']:.0f} s"
                 if fit["reached"] else f"not reached in {fit['evaluations']} evaluations, "
                 f"{fit['seconds']:.0f} s")
        lines += [
            f"| nao_paper: F(truth), target ×{1 + fit['tolerance']:g} | "
            f"{fit['truth_fitness']:.4g}, {fit['target']:.4g} |",
            f"| nao_paper on {fit['threads']} threads: to the target | {reach} |",
        ]
        floor = fit.get("floor")
        if floor:
            floor_reach = fit.get("floor_reach")
            lines += [
                f"| F at {floor['count']} points {floor['scale']:g} (relative) from the truth, "
                f"× F(truth): min, median, max | {floor['ratio_min']:.3f}, "
                f"{floor['ratio_median']:.3f}, {floor['ratio_max']:.3f} |",
                f"| nao_paper: to that scatter's max ({fit['floor_target']:.4g}) | " +
                (f"{floor_reach['evaluations']} evaluations, {floor_reach['seconds']:.0f} s"
                 if floor_reach else "not reached") + " |",
            ]
        lines += [
            f"| nao_paper: final best, evaluations, stop | {fit['best_fitness']:.4g}, "
            f"{fit['evaluations']}, {fit['stop_reason']} |",
            f"| nao_paper: frames saved by racing | "
            f"{racing_share(fit['racing']):.1f} % |",
        ]
        within = [p["name"] for p in fit["parameters"] if p["within"]]
        lines.append(f"| nao_paper: within 5 % of the truth ({len(within)} of "
                     f"{len(fit['parameters'])}) | {', '.join(within) or 'none'} |")
        lines += ["", "| parameter | truth | fitted | error | sensitivity | identified |",
                  "|---|---|---|---|---|---|"]
        for p in fit["parameters"]:
            sens = "—" if p["sensitivity"] is None else f"{p['sensitivity']:.3g}"
            error = (f"{100 * p['relative_error']:.1f} %" if p["truth"] != 0 else
                     f"{p['fitted'] - p['truth']:.3g} (absolute)")
            lines.append(f"| {p['name']} | {p['truth']:.4g} | {p['fitted']:.4g} | {error} | {sens} | "
                         f"{'no' if p['unidentified'] else 'yes'} |")
    if result.get("chain"):
        # After the measures, before the CMA-ES fit's per-parameter table.
        table_end = next((i for i, line in enumerate(lines) if line == ""), len(lines))
        lines[table_end:table_end] = chain_lines(result["chain"])
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "motoflex"))
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "fit_speed"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seconds", default="5", help="simulated seconds per bench rollout")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--fit-seconds", type=float, default=0.0,
                        help="the fit's time budget (default: nao_paper.yaml's)")
    parser.add_argument("--tolerance", type=float, default=0.05)
    parser.add_argument("--floor-points", type=int, default=8,
                        help="points near the truth that measure how finely F resolves it")
    parser.add_argument("--floor-scale", type=float, default=1e-4,
                        help="their relative distance from the truth")
    parser.add_argument("--skip-fit", action="store_true")
    parser.add_argument("--fit", choices=["cma", "chain", "both"], default="cma",
                        help="the nao_paper fit measured: CMA-ES on the whole problem, the "
                             "staged chain (report_paper_chain.py's stages), or both")
    parser.add_argument("--report-only", action="store_true",
                        help="re-read OUT/fit_speed.json and the fit's run folder and rewrite the "
                             "report, measuring nothing")
    args = parser.parse_args()
    out = Path(args.out)
    if args.report_only:
        result = json.loads((out / "fit_speed.json").read_text())
        if result.get("fit"):
            summary = json.loads((out / "runs" / "nao_paper" / "summary.json").read_text())
            result["fit"]["parameters"] = recovered(summary, truth_point(FIT, TRUTH))
        if result.get("chain"):
            result["chain"] = chain_result(args.binary, out, result["threads"],
                                           result["chain"]["tolerance"])
        write_report(str(out), "fit_speed", report_lines(result), result)
        return
    (out / "runs").mkdir(parents=True, exist_ok=True)
    result = {"threads": args.threads,
              "steps_per_core": steps_per_core(args.binary, args.repeats, args.seconds,
                                               args.threads)}
    print(f"steps/s per core: {result['steps_per_core']}", flush=True)
    result["mujoco"] = against_mujoco(args.binary, args.repeats, out / "runs")
    print(f"against MuJoCo: {result['mujoco']}", flush=True)
    if not args.skip_fit and args.fit in ("cma", "both"):
        result["fit"] = fit_paper(args.binary, out, args.threads, args.fit_seconds,
                                  args.tolerance, args.floor_points, args.floor_scale)
    if not args.skip_fit and args.fit in ("chain", "both"):
        result["chain"] = fit_chain(args.binary, out, args.threads, args.tolerance)
        print(f"chain: {result['chain']['evaluations']} evaluations, "
              f"{result['chain']['seconds']:.0f} s", flush=True)
    lines = report_lines(result)
    write_report(str(out), "fit_speed", lines, result)


if __name__ == "__main__":
    main()
