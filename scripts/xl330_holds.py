#!/usr/bin/env python3
"""Where the XL330 arm holds still, and how the released arm loses its swing, read straight from
the raw logs (issue 19, the real-servo stall; no simulation).

1. Holds: every stretch of at least 80 ms where the arm stands still (|θ̇| < 0.08 rad/s) with the
   torque on and the goal more than 0.15 rad away. Per hold: the angle, the gravity torque
   m·g·l·sin θ there, the drive the firmware applied at its start and its end (logged PWM ×
   input_volts), and what ended it. A P servo with Coulomb friction holds only while the drive
   stays within a fixed band around the one that balances gravity; the width of the band the
   logs show is the static friction.
2. The released arm (lift_and_drop after the torque is switched off): per half swing from one
   turning point p_k to the next p_k+1 the energy balance
       m·g·l·[cos(p_k+1 − q0) − cos(p_k − q0)] = f·|p_k+1 − p_k| + b·∫θ̇² dt
   is linear in the Coulomb friction f (N·m) and the viscous coefficient b (N·m·s/rad) for a
   given rest angle q0 of the load (a mounting offset). q0 is scanned on a 1 mrad grid and f, b
   taken by least squares over the half swings of a log (the arm's inertia cancels: each half
   swing starts and ends at rest).

Usage: xl330_holds.py [--results benchmarks/xl330_holds]
Writes RESULTS/xl330_holds.md. Skips (exit 0) when ../shared/data/bam is absent.
"""
import argparse
import os
import sys
import time

import numpy as np

# The torque regression's raw-log loader (time, angle, the servo's speed reading, goal, drive in
# volts, torque on), its constants and its report writer.
from xl330_torque_regression import GRAVITY_M_S2, PWM_FULL_SCALE, ROOT, raw_logs, write_report

STILL_RAD_S = 0.08      # |θ̇| below this is standing still (3 counts of the velocity register)
MIN_HOLD_S = 0.08
MIN_GOAL_GAP_RAD = 0.15


def holds(log):
    """(start, end) sample indices of each hold, end exclusive."""
    still = log["on"] & (np.abs(log["speed"]) < STILL_RAD_S)
    away = np.abs(log["goal"] - log["angle"]) > MIN_GOAL_GAP_RAD
    found, i, n = [], 0, len(still)
    while i < n:
        if not (still[i] and away[i]):
            i += 1
            continue
        j = i
        while j < n and still[j]:
            j += 1
        if log["time_s"][j - 1] - log["time_s"][i] >= MIN_HOLD_S:
            found.append((i, j))
        i = j
    return found


def hold_end(log, end):
    """What ended the hold whose last sample is end - 1."""
    if end >= len(log["angle"]):
        return "log ends"
    if not log["on"][end]:
        return "torque off"
    # It moves again: towards the goal (broke away) or back (the goal came back past it).
    towards = np.sign(log["speed"][end]) == np.sign(log["goal"][end] - log["angle"][end])
    return "breaks away" if towards else "yields back"


def turning_points(rate):
    """Indices where the released arm's rate changes sign (the turning points of its swing), and
    the first sample when the arm is released from standing still."""
    first = [0] if abs(rate[0]) < STILL_RAD_S else []
    return first + [k for k in range(1, len(rate)) if rate[k - 1] * rate[k] < 0.0 or
                    (rate[k] == 0.0 and rate[k - 1] != 0.0)]


def swing_friction(time_s, angle, rate, mass_kg, length_m):
    """From the energy balance of each half swing of a released pendulum (module docstring): a dict
    of f_nm, b_nm_s_per_rad, q0_rad, the half swings used and the fitted mean loss per half swing
    (J), or None with fewer than three half swings (three unknowns). Half swings shorter than
    0.1 rad are left out: there the reading's 1.5 mrad steps dominate. f and b separate only
    through swings of different amplitude; their sum over a half swing, the loss, is always
    determined."""
    mgl = mass_kg * GRAVITY_M_S2 * length_m
    turns = turning_points(rate)
    rows = []
    for a, b in zip(turns, turns[1:]):
        path = abs(angle[b] - angle[a])
        if path < 0.1:
            continue
        dt = np.diff(time_s[a:b + 1])
        rate_sq = 0.5 * (rate[a:b] ** 2 + rate[a + 1:b + 1] ** 2)
        rows.append((angle[a], angle[b], path, float(np.sum(rate_sq * dt))))
    if len(rows) < 3:
        return None
    best = None
    for q0 in np.arange(-0.1, 0.1 + 1e-9, 0.001):
        x = np.array([[path, viscous] for _, _, path, viscous in rows])
        y = np.array([mgl * (np.cos(end - q0) - np.cos(start - q0)) for start, end, _, _ in rows])
        coefficients, *_ = np.linalg.lstsq(x, y, rcond=None)
        error = float(np.sum((y - x @ coefficients) ** 2))
        if best is None or error < best[0]:
            best = (error, coefficients, q0, float(np.mean(x @ coefficients)))
    _, (f_nm, b_nm_s), q0, loss_j = best
    return dict(f_nm=f_nm, b_nm_s_per_rad=b_nm_s, q0_rad=q0, half_swings=len(rows),
                mean_loss_j=loss_j)


def hold_lines(logs):
    lines = ["| kp | trajectory | t (s) | angle (rad) | m·g·l·sin θ (N·m) | drive at start (V) | "
             "drive at end (V) | ends |", "|---|---|---|---|---|---|---|---|"]
    for log in logs:
        mgl = log["mass"] * GRAVITY_M_S2 * log["length"]
        for start, end in holds(log):
            lines.append("| %d | %s | %.2f-%.2f | %.3f | %.3f | %.2f | %.2f | %s |" % (
                log["kp"], log["trajectory"], log["time_s"][start], log["time_s"][end - 1],
                log["angle"][start], mgl * np.sin(log["angle"][start]), log["drive_v"][start],
                log["drive_v"][end - 1], hold_end(log, end)))
    return lines


def swing_lines(logs):
    lines = ["| kp | released at (rad) | half swings | Coulomb f (N·m) | viscous b (N·m·s/rad) | "
             "rest angle q0 (rad) | mean loss per half swing (J) |", "|---|---|---|---|---|---|---|"]
    for log in logs:
        off = np.nonzero(~log["on"])[0]
        if log["trajectory"] != "lift_and_drop" or not len(off):
            continue
        first = off[0]
        fit = swing_friction(log["time_s"][first:], log["angle"][first:], log["speed"][first:],
                             log["mass"], log["length"])
        if fit is None:
            continue
        lines.append("| %d | %.3f | %d | %.4f | %.4f | %+.3f | %.4f |" % (
            log["kp"], log["angle"][first], fit["half_swings"], fit["f_nm"],
            fit["b_nm_s_per_rad"], fit["q0_rad"], fit["mean_loss_j"]))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "benchmarks", "xl330_holds"))
    args = parser.parse_args()
    logs = raw_logs()
    if logs is None:
        return 0
    lines = ["XL330 raw logs (../shared/data/bam/xl330/raw), every log we have. "
             "`scripts/xl330_holds.py`, %s." % time.strftime("%Y-%m-%d"), "",
             "Holds: the arm still (|θ̇| < %g rad/s for %g s or more), torque on, the goal more than "
             "%g rad away. Drive = PWM/%g × input_volts." % (
                 STILL_RAD_S, MIN_HOLD_S, MIN_GOAL_GAP_RAD, PWM_FULL_SCALE), ""]
    lines += hold_lines(logs)
    lines += ["", "The released arm (lift_and_drop after torque off): Coulomb and viscous friction "
              "and the load's rest angle from the energy balance of its half swings.", ""]
    lines += swing_lines(logs)
    write_report(args.results, "xl330_holds.md", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
