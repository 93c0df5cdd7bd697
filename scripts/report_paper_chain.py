#!/usr/bin/env python3
"""The paper's problem fitted in three stages (issue 20), measured in one run.

Stage 1, scenarios/fit/nao_paper_short.yaml: the 19 free parameters of nao_paper.yaml from
their nominal starts, scored on the first 2 s of the five training logs (before the walk turns
chaotic), one CMA-ES generation and then Levenberg-Marquardt with its covariance. Stage 2,
scenarios/fit/nao_paper_long.yaml: started from stage 1's best (`motoflex fit --start-from`),
the parameters stage 1 identified held there (`hold_identified`), a CMA-ES over the others on
the first 4 s. Stage 3, scenarios/fit/nao_paper_whole.yaml: the same on the whole 10 s logs from
stage 2's best, holding the same parameters (stage 2's summary lists them). For each stage: evaluations (passes over the stage's logs), wall time
(summary.json), the best fitness against F(truth) under the stage's own scoring and, what the
issue's target is about, under nao_paper.yaml's (the whole 10 s logs; one evaluation at the
stage's best and one at the truth), validation RMS, and per parameter the fitted value against
the truth, with the stage's identification verdict (its 95 % intervals and sensitivities; a
parameter a later stage held keeps stage 1's verdict).

    scripts/report_paper_chain.py                    # runs the three stages (about 21 min on 2 cores)
    scripts/report_paper_chain.py --report-only      # re-reads OUT/runs
    scripts/report_paper_chain.py --report-only --recheck-uncertainty
        # ... and recomputes stage 1's intervals at its best.json with the current binary
        # (no fit: `polish: {method: none, covariance: true}`, OUT/runs/short_uncertainty;
        # about 2 min), whose verdicts then fill its "identified" column

Writes OUT/paper_chain.md and OUT/paper_chain.json (default benchmarks/paper_chain/).
"""

import argparse
import json
import shutil
import subprocess
import time
from pathlib import Path

import yaml  # python3-yaml (scripts/setup)

import bench_fit_speed as fit_speed
from bench_strategies import derived_config, truth_point, write_config

ROOT = Path(__file__).resolve().parent.parent
STAGES = [("short", ROOT / "scenarios/fit/nao_paper_short.yaml"),
          ("long", ROOT / "scenarios/fit/nao_paper_long.yaml"),
          ("whole", ROOT / "scenarios/fit/nao_paper_whole.yaml")]
WINDOWS = {"short": "first 2 s", "long": "first 4 s", "whole": "whole 10 s"}


def one_evaluation(binary, out, config, name, start_from=None):
    """summary.json of a fit of `config` (a derived config: one evaluation) written to
    OUT/NAME.yaml and run into OUT/runs/NAME, started from `start_from` (a best.json) if given."""
    path = out / f"{name}.yaml"
    write_config(path, config)
    run_dir = out / "runs" / name
    shutil.rmtree(run_dir, ignore_errors=True)
    command = [binary, "fit", path, "--out", run_dir]
    if start_from is not None:
        command += ["--start-from", start_from]
    subprocess.run([str(c) for c in command], check=True, stdout=subprocess.DEVNULL)
    return json.loads((run_dir / "summary.json").read_text())


def truth_fitness(binary, out, config_path, threads):
    """F at the truth under `config_path`'s scoring (its window), one evaluation, no polish."""
    point = truth_point(config_path, fit_speed.TRUTH)
    config = derived_config(config_path, {"kind": "nlopt", "algorithm": "sbplx"}, 1, threads, 1)
    config.pop("polish", None)
    config.pop("hold_identified", None)  # every parameter is given: nothing is searched
    config["free"] = {"ideal.torque_max_nm": {"lower": 1.0, "upper": 100.0, "start": 20.0}}
    config["fixed"] = {**(config.get("fixed") or {}), **point}
    summary = one_evaluation(binary, out, config, f"truth_{config_path.stem}")
    return summary["best_fitness"], point


def whole_log_fitness(binary, out, best_json, threads):
    """F under nao_paper.yaml's scoring (the whole 10 s logs) at a stage's best.json: one
    evaluation, the incumbent of a fit started there (`--start-from`; a parameter the stage held
    comes from the file's "parameters")."""
    config = derived_config(fit_speed.FIT, {"kind": "cma_es", "sigma": 0.01}, 1, threads, 1)
    config.pop("polish", None)
    return one_evaluation(binary, out, config, f"whole_{best_json.parent.name}", best_json)


def scores_whole_logs(config_path):
    """Whether a stage config scores as nao_paper.yaml does (no window): its own summary is then
    the whole-log evaluation, and its F(truth) is the issue's."""
    fitness = yaml.safe_load(config_path.read_text()).get("fitness", {})
    return fitness == yaml.safe_load(fit_speed.FIT.read_text()).get("fitness", {})


def run_stages(binary, out):
    """Runs the stages in order, each started from the previous one's best; writes each
    process's wall time (start to exit, the validation replays and plots included) to
    OUT/runs/wall_seconds.json."""
    previous = None
    wall = {}
    for name, config in STAGES:
        run_dir = out / "runs" / name
        shutil.rmtree(run_dir, ignore_errors=True)
        command = [binary, "fit", config, "--out", run_dir]
        if previous is not None:
            command += ["--start-from", previous / "best.json"]
        start = time.monotonic()
        subprocess.run([str(c) for c in command], check=True)
        wall[name] = time.monotonic() - start
        previous = run_dir
    (out / "runs" / "wall_seconds.json").write_text(json.dumps(wall, indent=1))


def recheck_uncertainty(binary, out, threads):
    """Stage 1's intervals and sensitivities recomputed at its best.json, without fitting (the
    later stages hold the parameters stage 1 identified and have no covariance of their own)."""
    name, config_path = STAGES[0]
    config = derived_config(config_path, {"kind": "nlopt", "algorithm": "sbplx"}, 1, threads, 1)
    config["polish"] = {"method": "none", "covariance": True}
    one_evaluation(binary, out, config, f"{name}_uncertainty", out / "runs" / name / "best.json")


def stage_results(binary, out, threads):
    """Per stage, read back from OUT/runs/<stage>: evaluations, wall time, best fitness,
    F(truth) under the stage's own scoring, validation RMS, and each parameter against the
    truth with the stage's identification verdict."""
    stages = []
    whole_truth, _ = truth_fitness(binary, out, fit_speed.FIT, threads)
    for name, config in STAGES:
        summary = json.loads((out / "runs" / name / "summary.json").read_text())
        whole_scoring = scores_whole_logs(config)
        if whole_scoring:
            f_truth, point = whole_truth, truth_point(config, fit_speed.TRUTH)
        else:
            f_truth, point = truth_fitness(binary, out, config, threads)
        parameters = fit_speed.recovered(summary, point)
        if stages:
            # The parameters this stage held: the previous stage's values. Every verdict is stage
            # 1's: a later stage has no covariance, and its sensitivities on the chaotic longer
            # windows call nearly everything determined.
            searched = {r["name"] for r in parameters}
            parameters = [dict(r, held=True) for r in stages[-1]["parameters"]
                          if r["name"] not in searched] + parameters
            first = {r["name"]: r["unidentified"] for r in stages[0]["parameters"]}
            for r in parameters:
                r["unidentified"] = first[r["name"]]
        whole = summary if whole_scoring else \
            whole_log_fitness(binary, out, out / "runs" / name / "best.json", threads)
        wall_file = out / "runs" / "wall_seconds.json"
        process_wall = json.loads(wall_file.read_text()).get(name) if wall_file.exists() else None
        verdicts = "the stage's own run"
        recheck = out / "runs" / f"{name}_uncertainty" / "summary.json"
        if stages:
            verdicts = "stage 1's (this stage has no covariance)"
        elif recheck.exists():
            # The verdicts of the recheck at the same point (the fitted values stay the stage's).
            again = {r["name"]: r for r in fit_speed.recovered(json.loads(recheck.read_text()),
                                                              point)}
            for r in parameters:
                r["unidentified"] = again[r["name"]]["unidentified"]
            verdicts = "recomputed at the stage's best (--recheck-uncertainty)"
        stages.append({"stage": name, "config": str(config.relative_to(ROOT)),
                       "identification": verdicts,
                       "evaluations": summary["evaluations"], "wall_seconds": summary["seconds"],
                       "best_fitness": summary["best_fitness"], "truth_fitness": f_truth,
                       "process_wall_seconds": process_wall,
                       "whole_log_fitness": whole["best_fitness"],
                       "whole_log_truth_fitness": whole_truth,
                       "whole_log_per_log": {r["name"]: r["fitness"] for r in whole["robots"]},
                       "validation_rms_deg": summary.get("validation", {}).get("rms_deg", {})
                       .get("overall"), "parameters": parameters,
                       "flat_scan_moves": summary.get("polish", {}).get("flat_scan_moves", [])})
    return stages


def flat_scan_text(moves):
    """The LM polish's flat-scan moves (summary.json polish.flat_scan_moves) for a table cell."""
    if not moves:
        return "none"
    return "; ".join(f"{m['parameter']} {m['from']:.4g} → {m['to']:.4g}" for m in moves)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "motoflex"))
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "paper_chain"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--report-only", action="store_true")
    parser.add_argument("--recheck-uncertainty", action="store_true")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if not args.report_only:
        run_stages(args.binary, out)
        for name, _ in STAGES:  # a fresh chain's own verdicts replace an older recheck
            shutil.rmtree(out / "runs" / f"{name}_uncertainty", ignore_errors=True)
    if args.recheck_uncertainty:
        recheck_uncertainty(args.binary, out, args.threads)
    result = {"stages": stage_results(args.binary, out, args.threads)}
    lines = ["| stage | logs scored | evaluations | wall s | best F | F(truth) | best / F(truth) | "
             "whole 10 s logs: F / F(truth) | validation RMS (deg) | within 5 % | "
             "identified, of them within 5 % | flat-scan moves |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    tables = []
    for stage in result["stages"]:
        name, rows, f_truth = stage["stage"], stage["parameters"], stage["truth_fitness"]
        identified = [r for r in rows if not r["unidentified"]]
        whole = stage["whole_log_fitness"] / stage["whole_log_truth_fitness"]
        lines.append(
            f"| {name} | {WINDOWS[name]} | {stage['evaluations']} | {stage['wall_seconds']:.0f} | "
            f"{stage['best_fitness']:.4g} | {f_truth:.4g} | {stage['best_fitness'] / f_truth:.2f} | "
            f"{stage['whole_log_fitness']:.4g} / {stage['whole_log_truth_fitness']:.4g} = "
            f"{whole:.3f} | "
            f"{stage['validation_rms_deg']:.3f} | {sum(r['within'] for r in rows)} of {len(rows)} | "
            f"{len(identified)}, {sum(r['within'] for r in identified)} | "
            f"{flat_scan_text(stage.get('flat_scan_moves', []))} |")
        table = [f"Stage `{name}`, per parameter (identified: {stage['identification']}):", "",
                 "| parameter | truth | fitted | error | identified |", "|---|---|---|---|---|"]
        for r in rows:
            error = (f"{100 * r['relative_error']:.1f} %" if r["truth"] != 0
                     else f"{r['relative_error']:.3g} (absolute)")
            verdict = "no" if r["unidentified"] else "yes"
            table.append(f"| {r['name']} | {r['truth']:.4g} | {r['fitted']:.4g} | {error} | "
                         f"{verdict + ' (held at stage 1)' if r.get('held') else verdict} |")
        tables.append("\n".join(table))
    markdown = "\n".join(lines) + "\n\n" + "\n\n".join(tables) + "\n"
    (out / "paper_chain.md").write_text(markdown)
    (out / "paper_chain.json").write_text(json.dumps(result, indent=1))
    print(markdown)


if __name__ == "__main__":
    main()
