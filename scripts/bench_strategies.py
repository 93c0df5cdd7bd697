#!/usr/bin/env python3
"""Strategy benchmark on the five-robot Nao fit (issue 4's closing report).

Runs `motoflex fit` on scenarios/fit/nao_strategy_bench.yaml (nao_quick's training set, free
parameters and start point) with six strategies and several seeds, and reports per strategy the
evaluations and wall time until the best fitness first reached a fixed target (median over the
seeds), the final best, and what early termination saved; then the parallel efficiency of 2
OpenMP threads and of 2 MPI ranks against 1 thread on one fixed workload (same seed, and the
three runs must give bit-identical results).

The target: the truth's own fitness. The logs were recorded from a known truth
(scenarios/truth/nao_motoflex.yaml), so the script evaluates F once at the truth's values of the
free parameters, the held ones as the benchmark config holds them (its `fixed:`: near the truth,
see the config), and the target is that fitness (times 1 + --tolerance, default 0). The tied
motor-viscous parameter has one value for both gear types while the truth has two, and the
model's links are rigid while the truth's bend, so the target point is not a point the search
can reach exactly: a run may end above or below it, and the report says how many ended below.
The long reference fit (IPOP-CMA-ES then BOBYQA, seed 1001, 1 400 evaluations) is reported for
context (F*, the best found) and is not counted among the compared runs. The budget, the same
for every strategy, defaults to 810 evaluations: the paper's ES's 10 initial parents and its
first generation of 800 offspring (1 % of its 80 000); every row states its budget. Last, the
goal table: the reference method's IPOP-CMA-ES on two more seeds, each with the goal's budget
(8 000 evaluations, a tenth of the paper's) and stopped at the target.

`--rescore` re-scores the committed runs against the current target from their stored
histories (runs/*/generations.csv and the result files) without running any fit. A run that
was stopped when it reached an earlier, higher target has no history beyond that point: if it
had not reached the current target by then, whether it would have is unknown, and the report
says so ("?").

    scripts/bench_strategies.py                  # default: ~2.5 hours on 2 cores, resumable
    scripts/bench_strategies.py --quick          # ~10 min smoke version (1 seed, tiny budget)
    scripts/bench_strategies.py --target 1.2e-6  # a given target (no reference fit, no goal table)
    scripts/bench_strategies.py --rescore        # re-score the stored runs, run nothing new
    scripts/bench_strategies.py --skip-strategies --skip-parallel   # only what is missing
    scripts/bench_strategies.py --strategies cma_es isres           # two strategies now

How runs are scheduled: every strategy run uses one thread and `--jobs` (default 2) runs go at
once, so each run gets one core whatever its strategy (NLopt's algorithms evaluate one point at
a time and could not use a second thread anyway); wall times are per run on one core. A run is
killed as soon as its best fitness has reached the target and that generation's checkpoint is
written (its counts are read from the checkpoint), or it ends at the evaluation budget, which is
the same for every strategy. The parallel-efficiency runs go one at a time.

Writes into --out (default benchmarks/strategies/): report.md (the tables) and results.json
(every run), rewritten after every part and every goal seed; configs/ (the derived fit configs);
runs/ (each run's folder). Git keeps all but the plots and logs (run dirs keep summary.json,
generations.csv, checkpoint.json and run.json), so a benchmark that needs more than one sitting
can be committed and continued from a clone in the same folder (run.json and the configs name
absolute paths): a finished reference or goal run is reused and an
interrupted one resumes from its checkpoint; each finished strategy run leaves
runs/<strategy>_seed<s>.result.json, reused by any later invocation with the same budget and
target (a strategy run under way when the benchmark was killed starts over, to keep its wall
time honest), and `--strategies` fills the table one strategy at a time. With
--skip-strategies/--skip-parallel/--skip-goal, that part of the report comes from the previous
results.json of the same target.
"""

import argparse
import csv
import fnmatch
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
TRUTH = ROOT / "scenarios" / "truth" / "nao_motoflex.yaml"


def strategies(args):
    """(key, label, strategy node) per strategy, in report order."""
    polish = max(1, round(args.budget * args.polish_fraction))
    paper_mu, paper_lambda = args.paper_mu, args.paper_lambda
    paper_label = f"({paper_mu}+{paper_lambda})-ES, κ=3"
    paper_label += " (the paper's)" if (paper_mu, paper_lambda) == (10, 800) else (
        f" (the paper's (10+800) scaled down, μ/λ = 1/{paper_lambda // paper_mu})")
    return [
        ("es_paper", paper_label,
         {"kind": "mu_plus_lambda", "mu": paper_mu, "lambda": paper_lambda, "kappa": 3,
          "rho": min(2, paper_mu), "initial_step": 0.15}),
        ("es_small", "(4+16)-ES, κ=3, ρ=2 (nao_quick's)",
         {"kind": "mu_plus_lambda", "mu": 4, "lambda": 16, "kappa": 3, "rho": 2,
          "initial_step": 0.15}),
        ("cma_es", "IPOP-aCMA-ES (λ=8)", {"kind": "cma_es", "sigma": 0.25}),
        ("cma_es_bobyqa", f"IPOP-aCMA-ES + BOBYQA polish ({polish} of the budget)",
         {"kind": "cma_es", "sigma": 0.25, "polish": "bobyqa", "polish_evaluations": polish}),
        ("crs2_lm", "NLopt CRS2_LM", {"kind": "nlopt", "algorithm": "crs2_lm"}),
        ("isres", "NLopt ISRES", {"kind": "nlopt", "algorithm": "isres"}),
    ]


def derived_config(base_path, strategy, evaluations, threads, seed):
    """The bench fit config with absolute paths and the given strategy and budget."""
    base = yaml.safe_load(base_path.read_text())
    folder = base_path.parent
    config = dict(base)
    config["scenario"] = str((folder / base["scenario"]).resolve())
    config["data"] = str((folder / base["data"]).resolve())
    config.pop("validation", None)
    config.pop("out", None)
    main_budget = evaluations - strategy.get("polish_evaluations", 0)
    config["strategy"] = strategy
    config["budget"] = {"evaluations": main_budget}
    config["threads"] = threads
    config["seed"] = seed
    return config


def write_config(path, config):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(config, sort_keys=False, default_flow_style=None))


def read_generations(run_dir):
    path = run_dir / "generations.csv"
    if not path.exists():
        return []
    with path.open() as f:
        return [{"generation": int(r["generation"]), "evaluations": int(r["evaluations"]),
                 "best": float(r["best"]), "seconds": float(r["seconds"])}
                for r in csv.DictReader(f)]


def first_reach(rows, target):
    for row in rows:
        if row["best"] <= target:
            return row
    return None


def mpirun_prefix(ranks):
    return ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks)]


def mpi_environment():
    env = dict(os.environ)
    # OpenMPI refuses root without these; containers forbid its single-copy (CMA) mechanism.
    env.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
                "OMPI_MCA_btl_vader_single_copy_mechanism": "none"})
    return env


def read_checkpoint(run_dir):
    """(generation, extra counters) of the run's last checkpoint, or (-1, {})."""
    try:
        payload = json.loads((run_dir / "checkpoint.json").read_text())["payload"]
        return payload["strategy"]["common"]["generation"], payload["extra"]
    except (OSError, ValueError, KeyError):
        return -1, {}


class Run:
    """One `motoflex fit` process. Once its best reaches `target` and the checkpoint of that
    generation is written, it is killed (SIGKILL: a SIGTERM would let it finish the generation
    under way, up to λ more rollouts), and the early-termination counts are read from that
    checkpoint instead of summary.json."""

    def __init__(self, name, command, run_dir, target, env=None, fresh=True):
        self.name, self.run_dir, self.target = name, run_dir, target
        if fresh and run_dir.exists():
            shutil.rmtree(run_dir)
        run_dir.parent.mkdir(parents=True, exist_ok=True)
        self.log = open(run_dir.parent / (run_dir.name + ".log"), "w" if fresh else "a")
        self.start = time.monotonic()
        self.process = subprocess.Popen(command, stdout=self.log, stderr=subprocess.STDOUT,
                                        env=env)
        self.reach = None  # the generations.csv row where the best first reached the target
        self.killed_at_target = None  # the checkpoint's extra counters when it was killed
        self.wall_s = None

    def poll(self):
        """True once finished."""
        if self.process.poll() is not None:
            if self.wall_s is None:
                self.wall_s = time.monotonic() - self.start
                self.log.close()
            return True
        if self.target is None or self.killed_at_target is not None:
            return False
        if self.reach is None:
            self.reach = first_reach(read_generations(self.run_dir), self.target)
        if self.reach is not None:
            generation, extra = read_checkpoint(self.run_dir)
            if generation >= self.reach["generation"]:
                self.process.kill()
                self.killed_at_target = extra
        return False

    def succeeded(self):
        if self.killed_at_target is not None:
            return True
        return self.process.returncode == 0 and (self.run_dir / "summary.json").exists()


def run_pool(runs_to_start, jobs, on_finish=None):
    """Starts callables returning Run, `jobs` at a time, calls on_finish(run) as each ends;
    returns the Runs in the order they ended."""
    pending, active, done = list(runs_to_start), [], []
    while pending or active:
        while pending and len(active) < jobs:
            run = pending.pop(0)()
            print(f"  started {run.name}", flush=True)
            active.append(run)
        time.sleep(0.5)
        for run in list(active):
            if run.poll():
                active.remove(run)
                done.append(run)
                code = run.process.returncode
                how = "reached the target" if run.killed_at_target is not None else f"exit {code}"
                print(f"  finished {run.name} ({run.wall_s:.0f} s, {how})", flush=True)
                if not run.succeeded():
                    print(f"  {run.name} FAILED, see {run.log.name}", flush=True)
                if on_finish is not None:
                    on_finish(run)
    return done


def run_result(run, strategy_key, seed, budget, target, polish):
    if not run.succeeded():
        return {"strategy": strategy_key, "seed": seed, "budget": budget, "failed": True,
                "log": run.log.name}
    rows = read_generations(run.run_dir)
    reach = first_reach(rows, target)
    if run.killed_at_target is not None:
        rows = [r for r in rows if r["generation"] <= reach["generation"]]
        early = run.killed_at_target
        summary = {"evaluations": reach["evaluations"], "best_fitness": reach["best"],
                   "stop_reason": "reached the target (killed)"}
    else:
        summary = json.loads((run.run_dir / "summary.json").read_text())
        early = dict(summary.get("early_termination", {}))
        early["stopped_early"] = early.get("individuals_stopped_early", 0)
    simulated = early.get("frames_simulated", 0)
    saved = early.get("frames_saved", 0)
    result = {
        "strategy": strategy_key, "seed": seed, "budget": budget,
        "evaluations": summary["evaluations"], "best_fitness": summary["best_fitness"],
        "stop_reason": summary["stop_reason"], "loop_seconds": rows[-1]["seconds"] if rows else 0,
        "process_seconds": run.wall_s, "reached": reach is not None,
        "evaluations_to_target": reach["evaluations"] if reach else None,
        "seconds_to_target": reach["seconds"] if reach else None,
        "to_target_is_upper_bound": False,
        "individuals_stopped_early": early.get("stopped_early", 0),
        "frames_simulated": simulated, "frames_saved": saved,
        "simulation_saved_fraction": saved / (simulated + saved) if simulated + saved else 0.0,
    }
    if reach is None and polish and summary["best_fitness"] <= target:
        # The polish writes no per-evaluation rows: all we know is that it got there by the end.
        result.update(reached=True, evaluations_to_target=summary["evaluations"],
                      seconds_to_target=summary["seconds"], to_target_is_upper_bound=True)
    return result


def fit_or_resume(args, config_path, run_dir, seed):
    """(command, resuming): `motoflex resume` for a run dir left half-way (killed or
    interrupted; resume gives the bits of an unbroken run), else a fresh `motoflex fit`."""
    if (run_dir / "checkpoint.json").exists():
        return [str(args.binary), "resume", str(run_dir)], True
    return [str(args.binary), "fit", str(config_path), "--out", str(run_dir),
            "--seed", str(seed)], False


def truth_point(bench_config, truth_path):
    """The truth's value of every robot parameter a free entry of the bench config covers (a tied
    pattern such as gear.*.motor_viscous_nm_s_per_rad gets each group's own truth value)."""
    free = yaml.safe_load(bench_config.read_text())["free"]
    truth = yaml.safe_load(Path(truth_path).read_text())["parameters"]
    point = {}
    for pattern in free:
        matched = {name: float(value) for name, value in truth.items()
                   if fnmatch.fnmatchcase(name, pattern)}
        if not matched:
            sys.exit(f"bench_strategies: the truth {truth_path} sets no parameter {pattern}")
        point.update(matched)
    return point


def truth_fitness(args, out, bench_config):
    """F at the truth's values of the free parameters, the others held as the bench config holds
    them: one evaluation. `motoflex fit` needs a free parameter, so the free set is the ideal
    servo's torque limit, which the motoflex servo law never reads, and the truth's values are
    `fixed:`. The result is stored in out/truth_fitness.json and reused while the config is the
    same."""
    point = truth_point(bench_config, args.truth)
    config = derived_config(bench_config, {"kind": "nlopt", "algorithm": "sbplx"}, 1,
                            min(2, os.cpu_count() or 1), 1)
    config["free"] = {"ideal.torque_max_nm": {"lower": 1.0, "upper": 100.0, "start": 20.0}}
    config["fixed"] = {**(config.get("fixed") or {}), **point}
    # The stored config names paths relative to the repository, so that a clone elsewhere
    # reuses the evaluation.
    key = dict(config, **{k: os.path.relpath(config[k], ROOT) for k in ("scenario", "data")})
    stored_path = out / "truth_fitness.json"
    if stored_path.exists():
        stored = json.loads(stored_path.read_text())
        if stored.get("config") == key:
            print(f"truth fitness: reusing {stored_path}", flush=True)
            return stored
    config_path = out / "configs" / "truth_fitness.yaml"
    write_config(config_path, config)
    run_dir = out / "runs" / "truth_fitness"
    if run_dir.exists():
        shutil.rmtree(run_dir)
    print(f"truth fitness: one evaluation at {point}", flush=True)
    subprocess.run([str(args.binary), "fit", str(config_path), "--out", str(run_dir)], check=True,
                   stdout=subprocess.DEVNULL)
    summary = json.loads((run_dir / "summary.json").read_text())
    if summary["evaluations"] != 1:
        sys.exit(f"bench_strategies: the truth evaluation ran {summary['evaluations']} evaluations")
    stored = {"fitness": summary["best_fitness"], "point": point,
              "truth_file": os.path.relpath(Path(args.truth).resolve(), ROOT),
              "rms_deg": summary.get("rms_deg", {}).get("overall"),
              "robots": {r["name"]: r["fitness"] for r in summary.get("robots", [])},
              "config": key}
    stored_path.write_text(json.dumps(stored, indent=2) + "\n")
    return stored


def run_reference(args, out, bench_config):
    """F*: the best fitness of a long IPOP-CMA-ES run (restarts with growing populations: the
    friction terms make the landscape multi-modal, and one CMA-ES run without restarts settles
    in a local optimum four times as high) polished by BOBYQA, on all cores. Returns its
    summary and run dir; a finished run is reused, a half-finished one resumed."""
    seed = 1001
    node = {"kind": "cma_es", "sigma": 0.25, "restarts": 9, "polish": "bobyqa",
            "polish_evaluations": args.reference_polish}
    config = derived_config(bench_config, node, args.reference_evaluations + args.reference_polish,
                            os.cpu_count() or 1, seed)
    config_path = out / "configs" / "reference.yaml"
    write_config(config_path, config)
    run_dir = out / "runs" / "reference"
    summary_path = run_dir / "summary.json"
    if summary_path.exists():
        summary = json.loads(summary_path.read_text())
        if summary.get("stop_reason") != "interrupted":
            print(f"reference: reusing {run_dir}", flush=True)
            return summary, run_dir
    command, resuming = fit_or_resume(args, config_path, run_dir, seed)
    if resuming:
        print(f"reference: resuming {run_dir}", flush=True)
    else:
        print(f"reference: IPOP-CMA-ES {args.reference_evaluations} + BOBYQA "
              f"{args.reference_polish} evaluations, seed {seed} -> {run_dir}", flush=True)
        if run_dir.exists():
            shutil.rmtree(run_dir)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return json.loads(summary_path.read_text()), run_dir


def run_goal(args, out, bench_config, rows, after_each):
    """The issue's goal, a method that reaches the paper setup's final fitness with at most a
    tenth of its 80 000 evaluations: the reference method (IPOP-CMA-ES on all cores) on more
    seeds, each with that tenth as its budget and stopped as soon as it reaches the target (the
    reference run itself is not a row: it is not an independent run). A seed caught in a local optimum restarts with growing
    populations until the budget is spent (up to ~3 h per seed on 2 cores), so each finished
    seed is stored and reused, and an interrupted one resumes from its checkpoint. Appends to
    `rows` and calls after_each() once per row."""
    node = {"kind": "cma_es", "sigma": 0.25, "restarts": 20}
    budget = args.goal_evaluations
    config_path = out / "configs" / f"goal_budget{budget}.yaml"
    for seed in args.goal_seeds:
        run_dir = out / "runs" / f"goal_seed{seed}_budget{budget}"
        result_path = run_dir.parent / (run_dir.name + ".result.json")
        result = stored_result(result_path, budget, args.target)
        if result is None:
            write_config(config_path, derived_config(bench_config, node, budget,
                                                     os.cpu_count() or 1, seed))
            command, resume = fit_or_resume(args, config_path, run_dir, seed)
            name = f"goal seed {seed}"
            run = run_pool([lambda: Run(name, command, run_dir, args.target, fresh=not resume)],
                           1)[0]
            result = run_result(run, "goal", seed, budget, args.target, False)
            result["target"] = args.target
            result_path.write_text(json.dumps(result, indent=2) + "\n")
        if result.get("failed"):
            continue
        rows.append(goal_row(seed, budget, result))
        after_each()


def rescore_result(result, run_dir, target, polish):
    """A stored run's result scored against `target` from its own history (generations.csv),
    without running anything. A run that was killed when it reached an earlier target has no
    history after that: if it had not reached `target` by then, `reached` is None (unknown)."""
    result = dict(result)
    if result.get("failed"):
        return result
    rows = read_generations(run_dir)
    killed = str(result.get("stop_reason", "")).startswith("reached the target")
    if result.get("target") != target:
        result.setdefault("measured_with_target", result.get("target"))
    result.update(target=target, history_stops_at_earlier_target=killed,
                  reached=False, evaluations_to_target=None, seconds_to_target=None,
                  to_target_is_upper_bound=False)
    reach = first_reach(rows, target)
    if reach is not None:
        result.update(reached=True, evaluations_to_target=reach["evaluations"],
                      seconds_to_target=reach["seconds"])
    elif polish and not killed and result["best_fitness"] <= target:
        # Reached during the polish, which writes no per-evaluation rows.
        result.update(reached=True, evaluations_to_target=result["evaluations"],
                      seconds_to_target=result["loop_seconds"], to_target_is_upper_bound=True)
    elif killed:
        result["reached"] = None
    return result


def rescore_stored(args, out, table):
    """(strategy results, goal rows) of the stored runs, re-scored against args.target; each
    result file is rewritten with the new target so that later invocations reuse it."""
    results, goal = [], []
    for key, _, node in table:
        for seed in args.seeds:
            path = out / "runs" / f"{key}_seed{seed}.result.json"
            if not path.exists():
                continue
            result = rescore_result(json.loads(path.read_text()), path.parent / f"{key}_seed{seed}",
                                    args.target, "polish" in node)
            path.write_text(json.dumps(result, indent=2) + "\n")
            results.append(result)
    for seed in args.goal_seeds:
        name = f"goal_seed{seed}_budget{args.goal_evaluations}"
        path = out / "runs" / (name + ".result.json")
        if not path.exists():
            continue
        result = rescore_result(json.loads(path.read_text()), out / "runs" / name, args.target,
                                False)
        path.write_text(json.dumps(result, indent=2) + "\n")
        if not result.get("failed"):
            goal.append(goal_row(seed, args.goal_evaluations, result))
    return results, goal


def goal_row(seed, budget, result):
    return {"seed": seed, "budget": budget, "best_fitness": result["best_fitness"],
            "evaluations": result["evaluations"], "seconds": result["loop_seconds"],
            "reached": result["reached"], "evaluations_to_target": result["evaluations_to_target"],
            "to_target_is_upper_bound": False,
            "history_stops_at_earlier_target": result.get("history_stops_at_earlier_target", False)}


def stored_result(path, budget, target):
    """A finished run's result from an earlier invocation, if it was measured with this budget
    and target (a run stopped half-way stored nothing and runs again from its start)."""
    if not path.exists():
        return None
    result = json.loads(path.read_text())
    if result.get("budget") != budget or result.get("target") != target or result.get("failed"):
        return None
    return result


def run_strategies(args, out, bench_config):
    """Every (strategy, seed) run: a run finished by an earlier invocation with the same budget
    and target is reused from its stored result; of the others, only the strategies named by
    --strategies (default: all) run now. A killed benchmark therefore loses only the runs that
    were under way."""
    table = strategies(args)
    selected = set(args.strategies or [key for key, _, _ in table])
    unknown = selected - {key for key, _, _ in table}
    if unknown:
        sys.exit(f"bench_strategies: unknown --strategies {', '.join(sorted(unknown))} "
                 f"(known: {', '.join(key for key, _, _ in table)})")
    stored, to_run = {}, []
    for key, _, node in table:
        config_path = out / "configs" / f"{key}.yaml"
        write_config(config_path, derived_config(bench_config, node, args.budget, 1, args.seeds[0]))
        for seed in args.seeds:
            run_dir = out / "runs" / f"{key}_seed{seed}"
            result_path = run_dir.parent / (run_dir.name + ".result.json")
            previous = stored_result(result_path, args.budget, args.target)
            if previous is not None:
                print(f"  reusing {key} seed {seed} ({result_path})", flush=True)
                stored[(key, seed)] = previous
            elif key in selected:
                command = [str(args.binary), "fit", str(config_path), "--out", str(run_dir),
                           "--seed", str(seed), "--threads", "1"]
                to_run.append((key, seed, node, result_path,
                               lambda c=command, d=run_dir, n=f"{key} seed {seed}":
                               Run(n, c, d, args.target)))
    by_name = {f"{key} seed {seed}": (key, seed, node, path) for key, seed, node, path, _ in to_run}

    def store(run):  # at once, so that a benchmark killed later keeps this run
        key, seed, node, result_path = by_name[run.name]
        result = run_result(run, key, seed, args.budget, args.target, "polish" in node)
        result["target"] = args.target
        result_path.write_text(json.dumps(result, indent=2) + "\n")
        stored[(key, seed)] = result

    run_pool([make for *_, make in to_run], args.jobs, store)
    results = [stored[(key, seed)] for key, _, _ in table for seed in args.seeds
               if (key, seed) in stored]
    return table, results


def run_parallel(args, out, bench_config):
    """1 thread, 2 threads, 2 MPI ranks x 1 thread on the same fixed workload."""
    node = {"kind": "mu_plus_lambda", "mu": 4, "lambda": 16, "kappa": 3, "rho": 2,
            "initial_step": 0.15}
    config = derived_config(bench_config, node, 100000, 1, args.seeds[0])
    config["budget"] = {"generations": args.parallel_generations}
    config_path = out / "configs" / "parallel.yaml"
    write_config(config_path, config)
    setups = [("1 thread", [], 1), ("2 threads", [], 2)]
    if shutil.which("mpirun"):
        setups.append(("2 MPI ranks x 1 thread", mpirun_prefix(2), 1))
    results = []
    for label, prefix, threads in setups:
        run_dir = out / "runs" / ("parallel_" + label.replace(" ", "_"))
        command = prefix + [str(args.binary), "fit", str(config_path), "--out", str(run_dir),
                            "--threads", str(threads)]
        env = mpi_environment() if prefix else None
        load = os.getloadavg()[0]
        done = run_pool([lambda c=command, d=run_dir, e=env: Run(label, c, d, None, e)], 1)[0]
        rows = read_generations(run_dir)
        summary = json.loads((run_dir / "summary.json").read_text())
        results.append({"setup": label, "load_average_before": load,
                        "loop_seconds": rows[-1]["seconds"],
                        "process_seconds": done.wall_s, "evaluations": summary["evaluations"],
                        "generations": summary["generations"],
                        "evaluator": summary.get("evaluator", ""),
                        "best_fitness": summary["best_fitness"],
                        "fingerprint": fingerprint(run_dir)})
    base = results[0]
    for r in results:
        r["speedup"] = base["loop_seconds"] / r["loop_seconds"]
        workers = 1 if r is base else 2
        r["efficiency"] = r["speedup"] / workers
        r["identical_to_1_thread"] = r["fingerprint"] == base["fingerprint"]
    return results


def fingerprint(run_dir):
    """generations.csv without seconds, and best.json without its date."""
    lines = [line.rsplit(",", 1)[0] for line in
             (run_dir / "generations.csv").read_text().splitlines()]
    best = json.loads((run_dir / "best.json").read_text())
    best["provenance"].pop("date", None)
    return "\n".join(lines) + json.dumps(best, sort_keys=True)


def median_or_none(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def fmt(value, digits=3):
    if value is None:
        return "–"
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return str(value)


def summarise(table, results, args):
    rows = []
    for key, label, _ in table:
        mine = [r for r in results if r["strategy"] == key and not r.get("failed")]
        if not mine:
            rows.append({"strategy": key, "label": label, "seeds": 0, "failed": True})
            continue
        reached = [r for r in mine if r["reached"]]
        # Median over all seeds, a seed that missed the target (or whose history ends before
        # telling) counting as worse than any that reached it (so the median is only a number
        # when most seeds reached it).
        n = len(mine)
        ranked = sorted(reached, key=lambda r: r["evaluations_to_target"])
        median_evals = median_secs = None
        if 2 * len(reached) > n:
            lower = (n - 1) // 2
            upper = n // 2
            evals = [r["evaluations_to_target"] for r in ranked] + [math.inf] * (n - len(ranked))
            secs = sorted([r["seconds_to_target"] for r in reached]) + [math.inf] * (n - len(reached))
            median_evals = (evals[lower] + evals[upper]) / 2
            median_secs = (secs[lower] + secs[upper]) / 2
        rows.append({
            "strategy": key, "label": label, "seeds": n, "reached": len(reached),
            "unknown": sum(1 for r in mine if r["reached"] is None),
            "budget": sorted({r["budget"] for r in mine}),
            "median_evaluations_to_target": median_evals,
            "median_seconds_to_target": median_secs,
            "upper_bound": any(r["to_target_is_upper_bound"] for r in reached),
            "evaluations_to_target": [r["evaluations_to_target"] for r in mine],
            "evaluations_run": [r["evaluations"] for r in mine],
            "reached_per_seed": [r["reached"] for r in mine],
            "evaluations_to_target_is_upper_bound": [r["to_target_is_upper_bound"] for r in mine],
            "median_final_best": statistics.median(r["best_fitness"] for r in mine),
            "median_evaluations_run": statistics.median(r["evaluations"] for r in mine),
            "individuals_stopped_early": sum(r["individuals_stopped_early"] for r in mine),
            "evaluations_total": sum(r["evaluations"] for r in mine),
            "simulation_saved_fraction": (
                sum(r["frames_saved"] for r in mine) /
                max(1, sum(r["frames_saved"] + r["frames_simulated"] for r in mine))),
        })
    return rows


PAPER_EVALUATIONS = 80000  # seed 001: (10+800)-ES, ~100 generations


def target_origin(args):
    truth = args.truth_result
    if truth is None:
        return " (given)"
    free = yaml.safe_load(Path(args.config).read_text())["free"]
    groups = []
    for pattern in free:
        values = sorted({v for name, v in truth["point"].items()
                         if fnmatch.fnmatchcase(name, pattern)})
        groups.append(f"{pattern} {' / '.join(f'{v:.7g}' for v in values)}")
    tolerance = f" × (1 + {args.tolerance:g})" if args.tolerance else ""
    return (f" = F(truth){tolerance}, the truth's own fitness: one evaluation at the truth's values "
            f"of the free parameters ({truth['truth_file']}: {'; '.join(groups)}; the tied "
            "motor-viscous parameter gets each gear type's own value, A / B) with every other "
            "parameter held as the benchmark holds it")


def reference_note(args):
    ref = args.reference
    if ref is None:
        return []
    return ["", f"For context, not a compared run: the long reference fit (IPOP-CMA-ES then "
            f"BOBYQA, seed 1001, budget {args.reference_evaluations + args.reference_polish} "
            f"evaluations) ended at F* = {ref['best_fitness']:.6g} after {ref['evaluations']} "
            f"evaluations ({ref['seconds']:.0f} s on {os.cpu_count()} cores): "
            f"{ref['best_fitness'] / args.target:.3g} × the target."]


def markdown(args, summary_rows, parallel, goal, started, finished, load):
    lines = [
        "# Strategy benchmark: five-robot Nao fit",
        "",
        f"`{' '.join(sys.argv)}` — {time.strftime('%Y-%m-%d %H:%M', time.localtime(started))}, "
        f"{os.cpu_count()} cores, load average {load[0]:.1f} at the start and {load[1]:.1f} at "
        f"the end, {finished - started:.0f} s in all.",
        "",
        f"Fit: `{os.path.relpath(Path(args.config).resolve(), ROOT)}`, a controlled comparison "
        "of optimisers, not an identification: 4 free parameters from a nominal start, every "
        "other parameter held near the truth (the config's `fixed:`, the values the runs were "
        "made with). Target fitness "
        f"{args.target:.6g}{target_origin(args)}. Budget {args.budget} evaluations per run "
        f"({100.0 * args.budget / PAPER_EVALUATIONS:.2g} % of the paper's ~{PAPER_EVALUATIONS}); seeds "
        f"{', '.join(map(str, args.seeds))}; each run on one core ({args.jobs} runs at once), "
        "stopped when its best reached the target it was run with.",
    ] + args.measured_note + [
        "",
        "| strategy | budget | reached | evaluations to target (median) | share of 80 000 | "
        "per seed | wall s to target (median, 1 core) | final best (median) | stopped early | "
        "simulation saved |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in summary_rows:
        if r.get("failed"):
            lines.append(f"| {r['label']} | every run failed (see results.json) |||||||||")
            continue
        bound = "≤ " if r["upper_bound"] else ""
        per_seed = ", ".join(
            (f"? (> {run})" if reached is None else "–") if e is None
            else ("≤ " if upper else "") + str(e)
            for e, upper, reached, run in zip(
                r["evaluations_to_target"], r["evaluations_to_target_is_upper_bound"],
                r.get("reached_per_seed", [False] * r["seeds"]),
                r.get("evaluations_run", [None] * r["seeds"])))
        unknown = f" (+{r['unknown']} ?)" if r.get("unknown") else ""
        budget = "/".join(str(b) for b in r.get("budget", [args.budget]))
        evals = r["median_evaluations_to_target"]
        secs = r["median_seconds_to_target"]
        share = (f"{bound}{100.0 * evals / PAPER_EVALUATIONS:.2g} %" if evals is not None
                 else f"> {100.0 * args.budget / PAPER_EVALUATIONS:.2g} %")
        lines.append(
            f"| {r['label']} | {budget} | {r['reached']}/{r['seeds']}{unknown} | "
            f"{bound + fmt(evals) if evals is not None else '> ' + str(args.budget)} | {share} | "
            f"{per_seed} | {bound + fmt(secs) if secs is not None else '–'} | "
            f"{fmt(r['median_final_best'])} | {r['individuals_stopped_early']} of "
            f"{r['evaluations_total']} | {100 * r['simulation_saved_fraction']:.0f} % |")
    if args.truth_result is not None:
        below = args.below_target
        runs = [r for r in args.scored_runs if not r.get("failed")]
        lines += ["", f"{len(below)} of {len(runs)} runs ended below the target" + (
            " (the rigid model can fit these logs better than the truth's values do: the target "
            "is the truth's fitness, not the lowest possible)." if below else ".")]
    lines += reference_note(args)
    lines += [
        "",
        "*stopped early*: individuals whose rollout stopped once it could no longer beat the "
        "selection threshold (summary.json `early_termination`), of all evaluations; *simulation "
        "saved*: the simulated frames this spared, as a share of all frames the runs asked for "
        "(CMA-ES and NLopt offer no threshold, so they save nothing). `≤`: the target was reached "
        "during the BOBYQA polish, which writes no per-evaluation rows, so the count is the run's "
        "total. `? (> N)`: the run was stopped after N evaluations when it reached the earlier, "
        "higher target it was run with (1.05 × the reference fit's best) and had not reached this "
        "one yet; its history ends there, so whether it would have is unknown (counted as not "
        "reached).",
    ]
    if goal:
        reached = [g for g in goal if g["reached"]]
        lines += [
            "",
            f"## The goal: the paper setup's final fitness with at most 1/10 of its "
            f"{PAPER_EVALUATIONS} evaluations",
            "",
            f"The reference method (IPOP-CMA-ES on {os.cpu_count()} cores) on {len(goal)} "
            f"independent seeds, each with the goal's budget, {args.goal_evaluations} evaluations, "
            f"and stopped at the target it was run with: {len(reached)} reached the target "
            f"{args.target:.6g}. (The reference fit, seed 1001, is not counted: it set the earlier "
            "target.)",
            "",
            "| seed | budget | evaluations to target | share of 80 000 | best | wall s |",
            "|---|---|---|---|---|---|",
        ]
        for g in goal:
            e = g["evaluations_to_target"]
            bound = "≤ " if g["to_target_is_upper_bound"] else ""
            missed = (f"? (> {g['evaluations']}, stopped at the earlier target)"
                      if g["reached"] is None else "not reached")
            lines.append(
                f"| {g['seed']} | {g.get('budget', '')} | "
                f"{bound + str(e) if e is not None else missed} | "
                f"{bound + f'{100.0 * e / PAPER_EVALUATIONS:.2g} %' if e is not None else '–'} | "
                f"{g['best_fitness']:.4g} | {g['seconds']:.0f} |")
        if 2 * len(reached) > len(goal):
            evals = sorted(g["evaluations_to_target"] for g in reached)
            evals += [math.inf] * (len(goal) - len(reached))
            median = statistics.median(evals)
            lines += ["", f"Median evaluations to the target: {median:g} "
                      f"({100.0 * median / PAPER_EVALUATIONS:.2g} % of the paper's "
                      f"{PAPER_EVALUATIONS}; goal ≤ 10 %)."]
    if parallel:
        lines += [
            "",
            f"## Parallel efficiency ({parallel[0]['evaluations']} evaluations: (4+16)-ES, "
            f"{parallel[0]['generations']} generation(s), seed {args.seeds[0]}, one run at a time)",
            "",
            "| setup | fit loop s | speed-up | efficiency | bit-identical to 1 thread | "
            "load average before |",
            "|---|---|---|---|---|---|",
        ]
        for r in parallel:
            lines.append(f"| {r['setup']} | {r['loop_seconds']:.1f} | {r['speedup']:.2f} | "
                         f"{100 * r['efficiency']:.0f} % | "
                         f"{'yes' if r['identical_to_1_thread'] else 'NO'} | "
                         f"{r['load_average_before']:.1f} |")
        lines += ["", "Fit loop s: the `seconds` of the last generations.csv row (start-up, final "
                  "report and plots excluded). Efficiency = speed-up / 2 workers."]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "motoflex"))
    parser.add_argument("--config", default=str(ROOT / "scenarios/fit/nao_strategy_bench.yaml"))
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "strategies"),
                        help="default benchmarks/strategies: git keeps its report, results, "
                             "configs and each run's small files (see .gitignore), so the "
                             "benchmark can be continued from a clone in the same folder")
    parser.add_argument("--quick", action="store_true", help="~10 minute smoke version")
    parser.add_argument("--seeds", type=int, nargs="+", help="default 1 2 3 (quick: 1)")
    parser.add_argument("--budget", type=int, help="evaluations per run (default 810, quick 16)")
    parser.add_argument("--target", type=float,
                        help="target fitness (default: F(truth)·(1 + tolerance), one evaluation)")
    parser.add_argument("--tolerance", type=float, default=0.0,
                        help="target = F(truth)·(1 + tolerance)")
    parser.add_argument("--truth", default=str(TRUTH),
                        help="the truth file behind the logs (its values of the free parameters "
                             "give the target)")
    parser.add_argument("--rescore", action="store_true",
                        help="re-score the stored runs against the target from their histories "
                             "and rewrite the report; run no fit but the one truth evaluation")
    parser.add_argument("--reference-evaluations", type=int,
                        help="CMA-ES evaluations of the reference fit (default 1200, quick 24)")
    parser.add_argument("--reference-polish", type=int,
                        help="BOBYQA evaluations polishing it (default 200, quick 8)")
    parser.add_argument("--jobs", type=int, default=2, help="strategy runs at once")
    parser.add_argument("--paper-mu", type=int, help="default 10 (quick: 1)")
    parser.add_argument("--paper-lambda", type=int, help="default 800 (quick: 12)")
    parser.add_argument("--polish-fraction", type=float, default=0.25,
                        help="share of the budget CMA-ES + BOBYQA leaves to the polish")
    parser.add_argument("--parallel-generations", type=int,
                        help="generations of the efficiency workload (default 2, quick 1)")
    parser.add_argument("--strategies", nargs="+", metavar="KEY",
                        help="run only these strategies (es_paper es_small cma_es cma_es_bobyqa "
                             "crs2_lm isres); finished runs of the others are still reported")
    parser.add_argument("--skip-strategies", action="store_true")
    parser.add_argument("--skip-parallel", action="store_true")
    parser.add_argument("--goal-seeds", type=int, nargs="*",
                        help="more seeds of the reference method for the goal table "
                             "(default 1002 1003, quick: none)")
    parser.add_argument("--goal-evaluations", type=int,
                        help="budget of each goal seed, stopped at the target (default 8000, a "
                             "tenth of the paper's 80 000; quick: 40)")
    parser.add_argument("--skip-goal", action="store_true")
    args = parser.parse_args()
    args.seeds = args.seeds or ([1] if args.quick else [1, 2, 3])
    args.budget = args.budget or (16 if args.quick else 810)
    args.paper_mu = args.paper_mu or (1 if args.quick else 10)
    args.paper_lambda = args.paper_lambda or (12 if args.quick else 800)
    args.reference_evaluations = args.reference_evaluations or (24 if args.quick else 1200)
    args.reference_polish = args.reference_polish or (8 if args.quick else 200)
    args.parallel_generations = args.parallel_generations or (1 if args.quick else 2)
    args.goal_evaluations = args.goal_evaluations or (40 if args.quick else 8000)
    if args.goal_seeds is None:
        args.goal_seeds = [] if args.quick else [1002, 1003]
    args.binary = Path(args.binary).resolve()
    if not args.binary.exists():
        sys.exit(f"bench_strategies: no binary at {args.binary} (build first, or --binary)")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    bench_config = Path(args.config).resolve()

    started = time.time()
    load_start = os.getloadavg()[0]
    args.reference, args.reference_dir, args.truth_result = None, None, None
    if args.target is None:
        args.truth_result = truth_fitness(args, out, bench_config)
        args.target = args.truth_result["fitness"] * (1.0 + args.tolerance)
        reference_summary = out / "runs" / "reference" / "summary.json"
        if args.rescore and reference_summary.exists():
            args.reference = json.loads(reference_summary.read_text())
        elif not args.rescore:
            args.reference, args.reference_dir = run_reference(args, out, bench_config)
    table, results, parallel, goal = strategies(args), [], [], []
    previous_path = out / "results.json"
    previous = json.loads(previous_path.read_text()) if previous_path.exists() else {}
    args.measured_note = previous.get("measured_note", [])
    if args.rescore:
        if not args.measured_note and (out / "report.md").exists():
            measured = (out / "report.md").read_text().splitlines()[2]
            args.measured_note = [
                "", f"The runs were measured by earlier invocations (the last: {measured}) and "
                "are re-scored against this target from their stored histories (generations.csv, "
                "result files) by `scripts/bench_strategies.py --rescore`, without re-running any "
                "fit."]
        parallel = previous.get("parallel", [])
        results, goal = rescore_stored(args, out, table)
        args.skip_strategies = args.skip_parallel = args.skip_goal = True
    elif previous.get("target") != args.target:
        previous = {}  # results of another target cannot be combined with these
    if args.skip_strategies and not args.rescore:
        results = previous.get("runs", [])
    if args.skip_parallel and not args.rescore:
        parallel = previous.get("parallel", [])
    if args.skip_goal and not args.rescore:
        goal = previous.get("goal", [])

    def write_outputs():
        """report.md and results.json of everything so far: after every part, so that a
        benchmark killed during a long part keeps the parts before it."""
        summary_rows = summarise(table, results, args) if results else []
        args.scored_runs = results
        args.below_target = [r for r in results if not r.get("failed")
                             and r["best_fitness"] < args.target]
        now = time.time()
        report = markdown(args, summary_rows, parallel, goal, started, now,
                          (load_start, os.getloadavg()[0]))
        (out / "report.md").write_text(report)
        (out / "results.json").write_text(json.dumps(
            {"target": args.target, "tolerance": args.tolerance,
             "truth_fitness": {k: v for k, v in (args.truth_result or {}).items()
                               if k != "config"} or None,
             "measured_note": args.measured_note,
             "reference": args.reference, "reference_is_compared": False,
             "budget": args.budget, "seeds": args.seeds,
             "summary": summary_rows, "runs": results,
             "parallel": [{k: v for k, v in r.items() if k != "fingerprint"} for r in parallel],
             "goal": goal,
             "seconds": now - started}, indent=2) + "\n")
        return report

    if not args.skip_strategies:
        print(f"strategies: {len(table)} x seeds {args.seeds}, budget {args.budget}, "
              f"target {args.target:g}", flush=True)
        table, results = run_strategies(args, out, bench_config)
        write_outputs()
    if not args.skip_parallel:
        print(f"parallel efficiency: {args.parallel_generations} generations", flush=True)
        parallel = run_parallel(args, out, bench_config)
        write_outputs()
    if not args.skip_goal and args.truth_result is not None:
        goal = []
        run_goal(args, out, bench_config, goal, write_outputs)
    print(write_outputs())


if __name__ == "__main__":
    main()
