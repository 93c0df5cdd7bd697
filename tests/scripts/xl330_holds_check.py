#!/usr/bin/env python3
"""scripts/xl330_holds.py's released-arm estimator against a pendulum with known friction: a
point mass released from 0.9 rad, Coulomb f and viscous b, its load at rest at q0, integrated
finely and sampled every 5 ms with the XL330's 4096-count encoder steps. The energy balance of
the half swings must give back f, b and q0; a frictionless arm must give f and b near zero.
Exit 1 on a failure."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
import xl330_holds  # noqa: E402

MASS_KG, LENGTH_M, G = 0.49, 0.1, 9.80665
COUNT_RAD = 2.0 * np.pi / 4096.0


def released_swing(f_nm, b_nm_s, q0_rad, start_rad=-0.9, duration_s=5.0):
    """Semi-implicit Euler at 0.1 ms; the arm sticks once it stops where gravity is below f."""
    inertia = MASS_KG * LENGTH_M ** 2 + 0.0015  # the arm and a reflected rotor, kg·m²
    dt, every = 1.0e-4, 50
    q, v = start_rad, 0.0
    times, angles, rates = [], [], []
    for step in range(int(duration_s / dt)):
        if step % every == 0:
            times.append(step * dt)
            angles.append(np.round(q / COUNT_RAD) * COUNT_RAD)
            rates.append(v)
        gravity = -MASS_KG * G * LENGTH_M * np.sin(q - q0_rad)
        if v == 0.0 and abs(gravity) <= f_nm:
            continue
        direction = np.sign(v) if v != 0.0 else np.sign(gravity)
        new_v = v + (gravity - direction * (f_nm + b_nm_s * abs(v))) / inertia * dt
        v = 0.0 if new_v * v < 0.0 else new_v
        q += v * dt
    return np.array(times), np.array(angles), np.array(rates)


def check(name, value, truth, tolerance):
    ok = abs(value - truth) <= tolerance
    print("%s %s: %.5f (truth %.5f, tolerance %.5f)" % ("ok  " if ok else "FAIL", name, value,
                                                         truth, tolerance))
    return ok


def main():
    ok = True
    for f_nm, b_nm_s, q0 in [(0.012, 0.006, -0.033), (0.02, 0.002, 0.02)]:
        fit = xl330_holds.swing_friction(*released_swing(f_nm, b_nm_s, q0), MASS_KG, LENGTH_M)
        if fit is None:
            print("FAIL no half swings found")
            return 1
        print("%d half swings, mean loss %.4f J" % (fit["half_swings"], fit["mean_loss_j"]))
        ok &= check("Coulomb f", fit["f_nm"], f_nm, 0.1 * f_nm)
        ok &= check("viscous b", fit["b_nm_s_per_rad"], b_nm_s, 0.2 * b_nm_s + 5e-4)
        ok &= check("rest angle q0", fit["q0_rad"], q0, 0.003)
    # Without friction every half swing keeps its energy: the estimate must not invent a loss
    # (f and b alone are not determined then, all half swings being alike).
    frictionless = xl330_holds.swing_friction(*released_swing(0.0, 0.0, 0.0, duration_s=3.0),
                                              MASS_KG, LENGTH_M)
    ok &= check("frictionless loss per half swing (J)", frictionless["mean_loss_j"], 0.0, 2e-4)
    ok &= check("frictionless rest angle", frictionless["q0_rad"], 0.0, 0.003)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
