#!/usr/bin/env python3
"""How the XL330's torque follows its drive, read straight from the logs (issue 19): the arm's
equation of motion J0·θ̈ + m·g·l·sin θ = τ_motor + τ_friction − J_a·θ̈ is regressed, by linear
least squares over the moving, torque-on, unsaturated samples, on the drive the firmware
logged (its Present PWM register as a duty, times the logged input_volts), the rate, its sign
and the acceleration. No simulation: the motor's apparent K_t/R (N·m per volt of drive) comes
out per kp block. A linear motor has one K_t/R whatever the gain; the regression also tries
the motor's torque saturation (the effect torque_saturation, τ ∝ tanh(k·I)) through a concave
drive term U·|U|, which a linear motor does not need.

Usage: xl330_torque_regression.py [--results benchmarks/xl330_torque_regression]
Writes RESULTS/xl330_torque_regression.md. Skips (exit 0) when ../shared/data/bam is absent.
"""
import argparse
import glob
import json
import os
import sys
import time

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BAM = os.path.join(ROOT, "..", "shared", "data", "bam")
GRAVITY_M_S2 = 9.80665
PWM_FULL_SCALE = 885.0  # the XL330's PWM limit register at 100 % duty (bam.md)
DT_S = 0.005  # the processed logs' sample period
SMOOTH = 5  # samples in the moving averages of the differentiated signals (25 ms)


def load(path):
    """One processed log as arrays; the rate and acceleration from the positions."""
    with open(path) as f:
        log = json.load(f)
    entries = log["entries"]
    angle = np.array([e["position"] for e in entries])
    kernel = np.ones(SMOOTH) / SMOOTH
    rate = np.convolve(np.gradient(angle, DT_S), kernel, "same")
    acceleration = np.convolve(np.gradient(rate, DT_S), kernel, "same")
    return dict(kp=log["kp"], trajectory=log["trajectory"], mass=log["mass"], length=log["length"],
                angle=angle, rate=rate, acceleration=acceleration,
                duty=np.array([e["load"] for e in entries]) / PWM_FULL_SCALE,
                supply=np.array([e["input_volts"] for e in entries]),
                on=np.array([bool(e["torque_enable"]) for e in entries]))


def columns(log, concave):
    drive_v = log["supply"] * log["duty"]
    out = [drive_v, -log["rate"], -np.sign(log["rate"]), -log["acceleration"]]
    if concave:
        out.append(drive_v * np.abs(drive_v))
    return np.stack(out, 1)


def regress(logs, concave):
    xs, ys = [], []
    for log in logs:
        keep = log["on"] & (np.abs(log["rate"]) > 0.1) & (np.abs(log["duty"]) < 0.98)
        keep[:2 * SMOOTH] = False
        keep[-2 * SMOOTH:] = False
        inertia = log["mass"] * log["length"] ** 2
        y = inertia * log["acceleration"] + log["mass"] * GRAVITY_M_S2 * log["length"] * np.sin(
            log["angle"])
        xs.append(columns(log, concave)[keep])
        ys.append(y[keep])
    x = np.concatenate(xs)
    y = np.concatenate(ys)
    coefficients, *_ = np.linalg.lstsq(x, y, rcond=None)
    residual = y - x @ coefficients
    return coefficients, float(np.sqrt(np.mean(residual ** 2))), float(np.std(y)), len(y)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "benchmarks",
                                                          "xl330_torque_regression"))
    args = parser.parse_args()
    folder = os.path.join(BAM, "xl330", "processed")
    if not os.path.isdir(folder):
        print("BAM logs absent (%s): nothing to regress" % folder)
        return 0
    logs = [load(p) for p in sorted(glob.glob(os.path.join(folder, "*.json")))]
    gains = sorted({log["kp"] for log in logs})
    lines = ["XL330 processed logs (../shared/data/bam/xl330), every log we have, moving "
             "(|θ̇| > 0.1 rad/s), torque on, duty below 98 %%; least squares of "
             "J0·θ̈ + m·g·l·sin θ on the logged drive U = input_volts·PWM/%g, −θ̇, −sign θ̇, "
             "−θ̈ (and U·|U|). `scripts/xl330_torque_regression.py`, %s." % (
                 PWM_FULL_SCALE, time.strftime("%Y-%m-%d")), "",
             "| logs | samples | linear: K_t/R (N·m/V) | linear: residual RMS (N·m) | "
             "with U·\\|U\\|: K_t/R | U·\\|U\\| (N·m/V²) | with U·\\|U\\|: residual RMS (N·m) |",
             "|---|---|---|---|---|---|---|"]
    for name, chosen in [("every gain", logs)] + [
            ("kp %d" % kp, [log for log in logs if log["kp"] == kp]) for kp in gains]:
        linear, linear_rms, _, samples = regress(chosen, False)
        concave, concave_rms, _, _ = regress(chosen, True)
        lines.append("| %s | %d | %.4f | %.4f | %.4f | %.5f | %.4f |" % (
            name, samples, linear[0], linear_rms, concave[0], concave[4], concave_rms))
    text = "\n".join(lines) + "\n"
    os.makedirs(args.results, exist_ok=True)
    with open(os.path.join(args.results, "xl330_torque_regression.md"), "w") as f:
        f.write(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
