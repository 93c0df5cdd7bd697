#!/usr/bin/env python3
"""MuJoCo vs motoflex on the MJCF export (issue 7's closing report).

For each model, `motoflex export --format mjcf --check-mujoco LOG` replays the log's commands in
motoflex (ODE, dWorldStep and dWorldQuickStep) and in MuJoCo on the export, 1 ms steps in all,
and prints the joint-angle RMS between them and each engine's steps/s. Each check runs --repeats times (the RMS is the same
every time; steps/s are the median, and the ratio is taken within each run, so machine load
affects both engines alike).

Models: the servo pendulum bench (BAM's servo law, chirp log); the Nao held by its torso on
the 10 s validation excitation log with the truth's parameters: rigid links and ideal servos;
the full MoToFlex servo; the full servo with 2 flexible sub-bodies per thigh and tibia; the Nao
walking on the ground (validation walk, 50 mm steps of 1 s) with ideal and MoToFlex servos; the
TITAN-VIII crawling on the ground (crawl A, 3 periods, velocity servos; log recorded here with
`motoflex record`); the mesh-described mini_arm on the walk-through's chirp (recorded here); the
2011 Nao model (nao_motoflex_2011) held, on the validation excitation recorded for it here.

Usage: report_export.py [--binary build/motoflex] [--repeats 3] [--out runs/export_report]
Writes OUT/export_report.md and OUT/export_report.json.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

from report_files import write_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def truth_parameters(path, out):
    """A truth file's parameters without sensor noise and quantisation (motoflex's encoders
    would otherwise read differently from MuJoCo's exact joint angles)."""
    with open(path) as f:
        parameters = json.load(f)["parameters"]
    parameters["sensor.noise_rad"] = 0.0
    parameters["sensor.resolution_bits"] = 0
    with open(out, "w") as f:
        json.dump(parameters, f)
    return out


def check(binary, params, robot, servo, flex, log, out_xml, held, settle_s):
    command = [binary, "export", params, "--robot", robot, "--servo", servo,
               "--flex-sub-bodies", str(flex), "--format", "mjcf", "--out", out_xml,
               "--check-mujoco", log, "--settle", str(settle_s)]
    if held:
        command += ["--hold-torso"]
    line = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    return json.loads(line.strip().splitlines()[-1])


def record(binary, out, name, scenario_text):
    """Writes `scenario_text` as OUT/NAME.yaml, records it with the robot's defaults and
    returns the log (only its commanded angles are replayed by the check)."""
    scenario = os.path.join(out, f"{name}_scenario.yaml")
    with open(scenario, "w") as f:
        f.write(scenario_text)
    truth = os.path.join(out, f"{name}_truth.yaml")
    with open(truth, "w") as f:
        f.write(f"name: {name}_truth\nseed: 1\nparameters: {{}}\n"
                f"recordings:\n  - {{name: {name}, scenario: {scenario}}}\n")
    subprocess.run([binary, "record", truth, "--out", os.path.join(out, "logs")], check=True,
                   capture_output=True, text=True)
    return os.path.join(out, "logs", f"{name}.csv")


def file_text(path, robot_line=None, robot_dir=None):
    with open(path) as f:
        text = f.read()
    return text.replace(robot_line, f"robot: {robot_dir}") if robot_line else text


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(ROOT, "runs", "export_report"))
    args = parser.parse_args()
    if not os.path.exists(args.binary):
        sys.exit(f"report_export: no binary at {args.binary} (run scripts/build first)")
    os.makedirs(args.out, exist_ok=True)

    nao_params = truth_parameters(
        os.path.join(ROOT, "reference_data/nao/truth/validation/excitation_held.json"),
        os.path.join(args.out, "nao_truth.json"))
    nao_log = os.path.join(ROOT, "reference_data/nao/validation/excitation_held.csv")
    pendulum_params = os.path.join(args.out, "defaults.json")
    with open(pendulum_params, "w") as f:
        json.dump({}, f)  # each robot's defaults
    pendulum_log = os.path.join(ROOT, "reference_data/bench/synthetic_sin_sin.csv")
    walk_params = truth_parameters(
        os.path.join(ROOT, "reference_data/nao/truth/validation/walk_050mm_1s.json"),
        os.path.join(args.out, "nao_walk_truth.json"))
    walk_log = os.path.join(ROOT, "reference_data/nao/validation/walk_050mm_1s.csv")
    robots = os.path.join(ROOT, "scenarios/robots")
    titan_log = record(args.binary, args.out, "titan_crawl_A",
                       file_text(os.path.join(ROOT, "scenarios/titan/crawl_A.yaml"),
                                 "robot: ../robots/titan8", os.path.join(robots, "titan8")))
    arm_log = record(args.binary, args.out, "mini_arm_chirp",
                     file_text(os.path.join(robots, "mini_arm/walkthrough/chirp.yaml"),
                               "robot: my_arm", os.path.join(robots, "mini_arm")))
    nao_2011_log = record(args.binary, args.out, "nao_2011_excitation_held",
                          file_text(os.path.join(ROOT, "scenarios/nao/excitation_held.yaml"),
                                    "robot: ../robots/nao\n",
                                    os.path.join(robots, "nao_motoflex_2011") + "\n"))
    models = [
        ("servo pendulum, bench servo", pendulum_params, "servo_pendulum", "bench", 1,
         pendulum_log, False, 0.0),
        ("Nao held, rigid, ideal servos", nao_params, "nao", "ideal", 1, nao_log, True, 0.5),
        ("Nao held, rigid, full MoToFlex servo", nao_params, "nao", "motoflex", 1, nao_log, True,
         0.5),
        ("Nao held, full MoToFlex servo + 2 flexible sub-bodies", nao_params, "nao", "motoflex", 2,
         nao_log, True, 0.5),
        ("Nao walking on the ground, ideal servos", walk_params, "nao", "ideal", 1, walk_log,
         False, 0.5),
        ("Nao walking on the ground, full MoToFlex servo", walk_params, "nao", "motoflex", 1,
         walk_log, False, 0.5),
        ("TITAN-VIII crawling on the ground, velocity servo", pendulum_params, "titan8",
         "velocity", 1, titan_log, False, 0.5),
        ("Nao 2011 model held, full MoToFlex servo", pendulum_params, "nao_motoflex_2011",
         "motoflex", 1, nao_2011_log, True, 0.5),
        ("mini_arm (STL meshes), Feetech servo, chirp", pendulum_params, "mini_arm", "feetech", 1,
         arm_log, False, 0.0),
    ]
    rows = []
    for label, params, robot, servo, flex, log, held, settle_s in models:
        runs = [check(args.binary, params, os.path.join(robots, robot), servo, flex, log,
                      os.path.join(args.out, f"{robot}_{servo}_{flex}.xml"), held, settle_s)
                for _ in range(args.repeats)]
        row = {
            "model": label,
            "rms_deg": runs[0]["rms_deg"],
            "max_abs_deg": runs[0]["max_abs_deg"],
            "visual_geoms": runs[0]["visual_geoms"],
            "rms_deg_per_joint": runs[0]["rms_deg_per_joint"],
            "mujoco_steps_per_s": statistics.median(r["mujoco_steps_per_s"] for r in runs),
            "motoflex_steps_per_s": statistics.median(r["motoflex_steps_per_s"] for r in runs),
            "motoflex_quick_steps_per_s": statistics.median(
                r["motoflex_quick_steps_per_s"] for r in runs),
            "rms_deg_quick": runs[0]["rms_deg_quick"],
            # ratios within each run (the same machine load for all three), then the median
            "motoflex_over_mujoco": statistics.median(
                r["motoflex_steps_per_s"] / r["mujoco_steps_per_s"] for r in runs),
            "motoflex_quick_over_mujoco": statistics.median(
                r["motoflex_quick_steps_per_s"] / r["mujoco_steps_per_s"] for r in runs),
        }
        rows.append(row)
        print(f"{label}: RMS {row['rms_deg']:.4f} deg, MuJoCo {row['mujoco_steps_per_s']:.0f} "
              f"vs motoflex {row['motoflex_steps_per_s']:.0f} (exact) / "
              f"{row['motoflex_quick_steps_per_s']:.0f} (quick) steps/s", flush=True)

    lines = ["| model | RMS MuJoCo vs motoflex (deg) | worst joint (deg) | max (deg) | "
             "visual geoms | MuJoCo steps/s | motoflex steps/s, exact / quick | "
             "motoflex / MuJoCo, exact / quick | RMS MuJoCo vs motoflex quick (deg) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        worst = max(r["rms_deg_per_joint"].items(), key=lambda item: item[1])
        lines.append(f"| {r['model']} | {r['rms_deg']:.4f} | {worst[1]:.4f} ({worst[0]}) | "
                     f"{r['max_abs_deg']:.3f} | {r['visual_geoms']} | "
                     f"{r['mujoco_steps_per_s']:.0f} | {r['motoflex_steps_per_s']:.0f} / "
                     f"{r['motoflex_quick_steps_per_s']:.0f} | "
                     f"{r['motoflex_over_mujoco']:.2f} / {r['motoflex_quick_over_mujoco']:.2f} | "
                     f"{r['rms_deg_quick']:.4f} |")
    write_report(args.out, "export_report", lines, rows)


if __name__ == "__main__":
    main()
