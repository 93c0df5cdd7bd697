#!/usr/bin/env python3
"""Writes the hardening evidence of issue 21 as OUT/results.json and OUT/results.md: per fuzz
target (scripts/fuzz's logs in build-fuzz/) the executions, executions per second, corpus size,
findings and minutes run; the ASan+UBSan fast tier (a saved `scripts/test --sanitize` output)
with its test count, pass count and wall time; the git commit, date and machine load.

    scripts/fuzz --minutes 10 > fuzz.txt
    scripts/hardening_report.py --minutes 10 [--sanitize-log sanitize.txt --sanitize-wall-s S] \
        --out benchmarks/hardening

Without --sanitize-log the sanitizer section of an existing OUT/results.json is kept. What each
finding was and how it was fixed comes from OUT/findings.json (a hand-written list of
{target, input, cause, fix}), kept beside the results."""

import argparse
import json
import os
import pathlib
import re
import subprocess
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGETS = ["yaml_config", "joint_log", "sidecar", "robot", "parameter_json"]


def stat(log_text, name):
    found = re.findall(rf"stat::{name}:\s*([0-9]+)", log_text)
    return int(found[-1]) if found else None


def fuzz_target(build, target, minutes):
    log = build / f"{target}.log"
    if not log.exists():
        return None
    text = log.read_text(errors="replace")
    corpus = build / "corpus" / target
    findings = build / "findings" / target
    return {
        "target": target,
        "minutes": int(minutes) if minutes == int(minutes) else minutes,
        "executions": stat(text, "number_of_executed_units"),
        "executions_per_s": stat(text, "average_exec_per_sec"),
        "new_units": stat(text, "new_units_added"),
        "peak_rss_mb": stat(text, "peak_rss_mb"),
        "corpus_inputs": sum(1 for p in corpus.iterdir() if p.is_file()) if corpus.exists() else 0,
        "findings": sorted(p.name for p in findings.iterdir()) if findings.exists() else [],
        "regression_inputs": sorted(p.name for p in (ROOT / "fuzz" / "regressions" / target).glob("*")),
    }


def fuzz_rows(build, minutes, previous):
    """One row per target: from its log in BUILD when there is one (dated now), else the row of
    the previous results (it keeps its own date and commit), so that a sanitizer-only update does
    not drop the fuzz evidence."""
    earlier = {f["target"]: f for f in previous.get("fuzz", [])}
    rows = []
    for target in TARGETS:
        row = fuzz_target(build, target, minutes)
        if row:
            row["date"] = time.strftime("%Y-%m-%d")
            row["commit"] = git("rev-parse", "--short", "HEAD")
        else:
            row = earlier.get(target)
            if row:
                row.setdefault("date", previous.get("date", "?")[:10])
                row.setdefault("commit", previous.get("commit", "?")[:7])
        if row:
            rows.append(row)
    return rows


def sanitize_section(log_paths, wall_s, scope):
    """Sums the ctest summaries of one or more saved runs (a whole tier, or module by module)."""
    tests = failed = skipped = 0
    seconds = 0.0
    failed_tests = []
    for log_path in log_paths:
        text = pathlib.Path(log_path).read_text(errors="replace")
        summary = re.search(r"(\d+)% tests passed, (\d+) tests? failed out of (\d+)", text)
        real = re.search(r"Total Test time \(real\) =\s*([0-9.]+) sec", text)
        if not summary:
            raise SystemExit(f"hardening_report: no ctest summary in {log_path}")
        failed += int(summary.group(2))
        tests += int(summary.group(3))
        seconds += float(real.group(1)) if real else 0.0
        failed_part = text.split("The following tests FAILED:", 1)
        if len(failed_part) == 2:
            failed_tests += re.findall(r"^\s*\d+ - (\S+) \((?!Skipped)", failed_part[1], re.M)
        skipped += len(re.findall(r"^\s*\d+ - \S+ \(Skipped\)", text, re.M))
    return {
        "date": time.strftime("%Y-%m-%d"),
        "commit": git("rev-parse", "--short", "HEAD"),
        "command": "scripts/test --sanitize",
        "scope": scope,
        "tests": tests,
        "passed": tests - failed,
        "failed": failed,
        "skipped": skipped,
        "ctest_seconds": round(seconds, 1),
        "wall_s_with_build": wall_s,
        "failed_tests": failed_tests,
    }


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True,
                          text=True).stdout.strip()


def markdown(results, fixes):
    lines = ["# Hardening evidence (issue 21)", "",
             f"Commit `{results['commit']}`{' (with local changes)' if results['tree_changed'] else ''}, "
             f"{results['date']}, load average {results['load_average']} on {results['cores']} cores "
             "shared with other jobs.", "",
             "## Fuzzing (`scripts/fuzz --minutes N`: libFuzzer, ASan + UBSan, clang)", "",
             "| target | minutes | executions | exec/s | corpus inputs | findings now | regression inputs | run |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    for f in results["fuzz"]:
        lines.append(f"| {f['target']} | {f['minutes']} | {f['executions']} | {f['executions_per_s']} | "
                     f"{f['corpus_inputs']} | {len(f['findings'])} | {len(f['regression_inputs'])} | "
                     f"{f.get('date', '?')}, {f.get('commit', '?')} |")
    lines += ["", "## What fuzzing and the sanitizers found, and the fix", ""]
    lines += [f"- **{x['target']}** `{x['input']}`: {x['cause']} Fix: {x['fix']}" for x in fixes] or ["- nothing"]
    s = results.get("sanitize")
    lines += ["", "## ASan + UBSan fast tier (`scripts/test --sanitize`)", ""]
    if s:
        lines += [f"Scope: {s.get('scope', 'the whole fast tier')}. Run {s.get('date', '?')} at "
                  f"{s.get('commit', '?')}.", ""]
        with_build = (f", {s['wall_s_with_build']:.0f} s with the build" if s["wall_s_with_build"]
                      else "")
        lines += [f"{s['passed']} of {s['tests']} tests passed ({s['failed']} failed, "
                  f"{s.get('skipped', 0)} of the passed skipped); ctest {s['ctest_seconds']} s"
                  f"{with_build} (2 shared cores)."]
        lines += [f"- failed: {t}" for t in s["failed_tests"]]
    else:
        lines += ["not run"]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build-fuzz"))
    parser.add_argument("--minutes", type=float, required=True, help="minutes per fuzz target")
    parser.add_argument("--sanitize-log", action="append",
                        help="saved output of scripts/test --sanitize (repeat for partial runs)")
    parser.add_argument("--sanitize-scope", default="the whole fast tier (ctest -L fast)")
    parser.add_argument("--sanitize-wall-s", type=float, help="its wall time, build included")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    previous = {}
    if (out / "results.json").exists():
        previous = json.loads((out / "results.json").read_text())
    fixes = json.loads((out / "findings.json").read_text()) if (out / "findings.json").exists() else []
    results = {
        "commit": git("rev-parse", "HEAD"),
        "tree_changed": bool(git("status", "--porcelain", "--untracked-files=no")),
        "date": time.strftime("%Y-%m-%d %H:%M:%S %Z"),
        "load_average": round(os.getloadavg()[0], 2),
        "cores": os.cpu_count(),
        "fuzz": fuzz_rows(pathlib.Path(args.build), args.minutes, previous),
        "sanitize": (sanitize_section(args.sanitize_log, args.sanitize_wall_s, args.sanitize_scope) if args.sanitize_log
                     else previous.get("sanitize")),
    }
    (out / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    (out / "results.md").write_text(markdown(results, fixes))
    print(f"hardening_report: {out}/results.json, {out}/results.md")


if __name__ == "__main__":
    main()
