#!/usr/bin/env python3
"""motoflex from Python, notebook style: simulate the Nao, fit the pendulum bench, export.

    PYTHONPATH=build/python /usr/bin/python3 examples/python_quickstart.py [--out runs/py_demo] [--overwrite]

Each step prints what it did; the same numbers come out of the `motoflex` CLI.
"""

import argparse
import os
import shutil

import numpy as np

import motoflex

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def simulate_nao():
    # 1. A scenario as `motoflex simulate` loads it; simulate() returns NumPy arrays.
    scenario = motoflex.Scenario(os.path.join(ROOT, "scenarios", "nao_default.yaml"),
                                 duration_s=1.0)
    print(scenario)
    nominal = scenario.simulate()
    print(f"  nominal: {nominal['frames_completed']} frames, "
          f"tracking RMS {motoflex.rms_deg(nominal):.3f} deg")
    r_ohm = scenario.parameters["motor.R_ohm"]
    for factor in (2.0, 4.0):
        weaker = scenario.simulate({"motor.R_ohm": factor * r_ohm})
        worst = np.degrees(np.abs(weaker["measured_rad"] - nominal["measured_rad"]).max())
        print(f"  motor.R_ohm x{factor:g}: tracking RMS {motoflex.rms_deg(weaker):.3f} deg, "
              f"largest change {worst:.3f} deg")


def fit_bench(out):
    # 2. A fit from a YAML (the CLI's config) with a progress callback; Ctrl-C stops it after
    #    the current generation with the checkpoint kept, and resume() continues it exactly.
    fit_yaml = os.path.join(ROOT, "scenarios", "fit", "bench_hidden.yaml")
    spec = motoflex.FitSpec.load(fit_yaml)
    print(f"fit {spec.name}: free {[f.pattern for f in spec.free]}")
    summary = motoflex.fit(fit_yaml, out=out, max_generations=4,
                           progress=lambda p: print("  " + p.line))
    print(summary["brief_report"])
    summary = motoflex.resume(out, max_generations=8)
    print(summary["brief_report"])
    return os.path.join(out, "best.json")


def export(best_json, out):
    # 3. The fitted set for MuJoCo, checked by MuJoCo's own parser before it is written.
    robot = os.path.join(ROOT, "scenarios", "robots", "servo_pendulum")
    info = motoflex.export(best_json, robot, "mjcf", os.path.join(out, "pendulum.xml"))
    print(f"exported {info['out']} (read back by {info['read_back_by']})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "runs", "py_demo"))
    parser.add_argument("--overwrite", action="store_true",
                        help="delete an earlier run in --out first (a fit never overwrites one)")
    args = parser.parse_args()
    if args.overwrite and os.path.isdir(args.out):
        shutil.rmtree(args.out)
    simulate_nao()
    best_json = fit_bench(args.out)
    export(best_json, args.out)


if __name__ == "__main__":
    main()
