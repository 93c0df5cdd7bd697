#!/usr/bin/env python3
"""How the XL330's torque follows its drive, read straight from the logs (issue 19): the arm's
equation of motion J0·θ̈ + m·g·l·sin θ = τ_motor + τ_friction − J_a·θ̈ is regressed, by linear
least squares over the moving, torque-on, unsaturated samples of the raw logs, on the drive the
firmware logged (its Present PWM register as a signed duty, times the logged input_volts), the
rate, its sign and the acceleration. No simulation: the motor's apparent K_t/R (N·m per volt of
drive) comes out per kp block. A linear motor has one K_t/R whatever the gain; the regression
also tries concave drive laws a linear motor does not need: a quadratic term in the drive
U·|U|, one in the winding current's proxy (the effect torque_saturation acts on the current)
and a power law of the duty.

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
SMOOTH = 5  # samples in the moving averages of the differentiated signals (about 27 ms)


def signed_pwm(register):
    """The Present PWM register as the recorder stored it, unsigned 16-bit, as a signed count."""
    return register - 65536 if register > 32767 else register


def load(path):
    """One raw log as arrays (time from its first sample); the rate and acceleration from the
    positions and timestamps, beside the servo's own velocity reading (`speed`). The raw logs, not
    the processed ones: their PWM register is exact, while the processed logs interpolate the
    unsigned register across every sign change (../shared/data/bam/xl330)."""
    with open(path) as f:
        log = json.load(f)
    entries = log["entries"]
    time_s = np.array([e["timestamp"] for e in entries]) - entries[0]["timestamp"]
    angle = np.array([e["position"] for e in entries])
    kernel = np.ones(SMOOTH) / SMOOTH
    rate = np.convolve(np.gradient(angle, time_s), kernel, "same")
    acceleration = np.convolve(np.gradient(rate, time_s), kernel, "same")
    duty = np.array([signed_pwm(e["load"]) for e in entries]) / PWM_FULL_SCALE
    supply = np.array([e["input_volts"] for e in entries])
    return dict(kp=log["kp"], trajectory=log["trajectory"], mass=log["mass"], length=log["length"],
                time_s=time_s, angle=angle, rate=rate, acceleration=acceleration,
                speed=np.array([e["speed"] for e in entries]),
                goal=np.array([e["goal_position"] for e in entries]),
                duty=duty, supply=supply, drive_v=supply * duty,
                on=np.array([bool(e["torque_enable"]) for e in entries]))


def raw_logs():
    """Every raw XL330 log we have, loaded, or None (and a line saying so) when
    ../shared/data/bam is absent."""
    folder = os.path.join(BAM, "xl330", "raw")
    if not os.path.isdir(folder):
        print("BAM logs absent (%s): nothing to read" % folder)
        return None
    return [load(p) for p in sorted(glob.glob(os.path.join(folder, "*.json")))]


def columns(log, drive):
    """The regressors: `drive` (name -> list of drive columns from U and θ̇), then −θ̇, −sign θ̇,
    −θ̈."""
    return np.stack(DRIVES[drive](log["drive_v"], log["rate"]) +
                    [-log["rate"], -np.sign(log["rate"]), -log["acceleration"]], 1)


def power_law(exponent):
    return lambda u, rate: [np.sign(u) * np.abs(u) ** exponent]


# Concave drive laws the logs are asked to choose between: a quadratic term in the drive, a
# power law of the duty (U_s·|d|^γ), and a quadratic term in the winding current's proxy
# U − K_t·θ̇ (the torque saturation, which acts on the current; K_t 0.3 N·m/A, the fits' range).
DRIVES = {
    "linear": lambda u, rate: [u],
    "U·|U|": lambda u, rate: [u, u * np.abs(u)],
    "I·|I|": lambda u, rate: [u, (u - 0.3 * rate) * np.abs(u - 0.3 * rate)],
    **{"|U|^%.1f" % gamma: power_law(gamma) for gamma in (0.6, 0.7, 0.8, 0.9)},
}


def regress(logs, drive):
    xs, ys = [], []
    for log in logs:
        keep = log["on"] & (np.abs(log["rate"]) > 0.1) & (np.abs(log["duty"]) < 0.98)
        keep[:2 * SMOOTH] = False
        keep[-2 * SMOOTH:] = False
        inertia = log["mass"] * log["length"] ** 2
        y = inertia * log["acceleration"] + log["mass"] * GRAVITY_M_S2 * log["length"] * np.sin(
            log["angle"])
        xs.append(columns(log, drive)[keep])
        ys.append(y[keep])
    x = np.concatenate(xs)
    y = np.concatenate(ys)
    coefficients, *_ = np.linalg.lstsq(x, y, rcond=None)
    residual = y - x @ coefficients
    return coefficients, float(np.sqrt(np.mean(residual ** 2))), float(np.std(y)), len(y)


# Which samples each column of the supply table pools: torque off, then by |duty| with the
# torque on.
SUPPLY_KINDS = [
    lambda log: ~log["on"],
    lambda log: log["on"] & (np.abs(log["duty"]) < 0.05),
    lambda log: log["on"] & (np.abs(log["duty"]) > 0.1) & (np.abs(log["duty"]) < 0.9),
    lambda log: log["on"] & (np.abs(log["duty"]) > 0.98),
]


def supply_reading(logs, kind):
    """Mean ± SD of the logged supply over the samples `kind` selects, and their count."""
    volts = np.concatenate([log["supply"][kind(log)] for log in logs])
    if not len(volts):
        return "—"
    return "%.2f ± %.2f (%d)" % (volts.mean(), volts.std(), len(volts))


def write_report(folder, file_name, lines):
    """The report's lines into FOLDER/FILE_NAME (the folder made if need be), and to stdout."""
    text = "\n".join(lines) + "\n"
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, file_name), "w") as f:
        f.write(text)
    print(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "benchmarks",
                                                          "xl330_torque_regression"))
    args = parser.parse_args()
    logs = raw_logs()
    if logs is None:
        return 0
    gains = sorted({log["kp"] for log in logs})
    lines = ["XL330 raw logs (../shared/data/bam/xl330/raw, the PWM register read as signed), every log we have, moving "
             "(|θ̇| > 0.1 rad/s), torque on, duty below 98 %%; least squares of "
             "J0·θ̈ + m·g·l·sin θ on the logged drive U = input_volts·PWM/%g, −θ̇, −sign θ̇, "
             "−θ̈ (and U·|U|). `scripts/xl330_torque_regression.py`, %s." % (
                 PWM_FULL_SCALE, time.strftime("%Y-%m-%d")), "",
             "| logs | samples | linear: K_t/R (N·m/V) | linear: residual RMS (N·m) | "
             "with U·\\|U\\|: K_t/R | U·\\|U\\| (N·m/V²) | with U·\\|U\\|: residual RMS (N·m) |",
             "|---|---|---|---|---|---|---|"]
    subsets = [("every gain", logs)] + [
        ("kp %d" % kp, [log for log in logs if log["kp"] == kp]) for kp in gains]
    # Every drive law on every subset, regressed once for both tables.
    fits = {(name, drive): regress(chosen, drive) for name, chosen in subsets for drive in DRIVES}
    for name, _ in subsets:
        linear, linear_rms, _, samples = fits[(name, "linear")]
        concave, concave_rms, _, _ = fits[(name, "U·|U|")]
        lines.append("| %s | %d | %.4f | %.4f | %.4f | %.5f | %.4f |" % (
            name, samples, linear[0], linear_rms, concave[0], concave[1], concave_rms))
    lines += ["", "Which concave law: residual RMS (N·m) of each drive law, same samples and "
              "other regressors. U·|U|: quadratic in the drive; |U|^γ: a power law of the duty; "
              "I·|I|: quadratic in the current proxy U − 0.3·θ̇, as the torque saturation acts "
              "on the current.", "",
              "| drive law | " + " | ".join(name for name, _ in subsets) + " |",
              "|---|" + "---|" * len(subsets)]
    for drive in DRIVES:
        lines.append("| %s | %s |" % (drive.replace("|", "\\|"), " | ".join(
            "%.4f" % fits[(name, drive)][1] for name, _ in subsets)))
    lines += ["", "The supply reading (input_volts, V) by drive: mean ± standard deviation over the "
              "samples of each kind, every log of a gain pooled. With the bridge switching "
              "(partial duty) the register samples the PWM ripple; at full duty it shows the "
              "sag under the stall current.", "",
              "| logs | torque off | duty < 5 % | duty 10-90 % | duty > 98 % |", "|---|---|---|---|---|"]
    for name, chosen in subsets:
        lines.append("| %s | %s |" % (name, " | ".join(
            supply_reading(chosen, kind) for kind in SUPPLY_KINDS)))
    write_report(args.results, "xl330_torque_regression.md", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
