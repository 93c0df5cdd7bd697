#!/usr/bin/env python3
"""Generate the small synthetic bench log replayed by scenarios/servo_pendulum_replay.yaml.

Writes a SYNTHETIC log in BAM's raw trajectory format (shared/data/bam/README.md) and converts
it with `motoflex import-bam`, so the replay goes through the same importer as the real logs:

  reference_data/bench/synthetic_sin_sin.csv  (+ .yaml sidecar)

The log is not a measurement. The goal is BAM's `sin_sin` trajectory,
(pi/2) sin t + 0.5 sin(5t) sin(2t) rad, over 2 s on an irregular clock like the XL330 raw logs
(period 5.2-5.5 ms, first sample at 3.5 ms); `position` is that goal through a first-order lag
(time constant 40 ms), a stand-in for a real servo's tracking. The header is the XL330 bench's
(0.49 kg at 0.1 m, kp 400, vin 7.4 V, motor xl330). Deterministic: the same bytes every run.

Usage: make_bench_replay_log.py [--motoflex build/motoflex] [--out reference_data/bench]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME = "synthetic_sin_sin"
DURATION_S = 2.0
LAG_TAU_S = 0.04


def goal_rad(t):
    return (math.pi / 2) * math.sin(t) + 0.5 * math.sin(5 * t) * math.sin(2 * t)


def synthetic_log():
    entries = []
    t = 0.0035
    position = 0.0
    previous_t = 0.0
    i = 0
    while t <= DURATION_S:
        goal = goal_rad(t)
        # Exact solution of the lag over the step, with the goal held at its new value.
        position = goal + (position - goal) * math.exp(-(t - previous_t) / LAG_TAU_S)
        entries.append({"position": position, "speed": 0.0, "load": 0, "input_volts": 7.4,
                        "temp": 30, "timestamp": t, "goal_position": goal,
                        "torque_enable": True})
        previous_t = t
        # Irregular period 5.2..5.5 ms from a fixed sequence (no random generator involved).
        t += 0.0052 + 0.0001 * (i * 7 % 4)
        i += 1
    return {"mass": 0.49, "length": 0.1, "kp": 400, "vin": 7.4, "motor": "xl330",
            "trajectory": NAME, "entries": entries}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--motoflex", default=os.path.join(ROOT, "build", "motoflex"))
    parser.add_argument("--out", default=os.path.join(ROOT, "reference_data", "bench"))
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, NAME + ".json"), "w") as f:
            json.dump(synthetic_log(), f)
        # Run inside the temporary folder so the sidecar's origin names just the file.
        result = subprocess.run([os.path.abspath(args.motoflex), "import-bam", NAME + ".json",
                                 "--out", out], cwd=work)
    return result.returncode


if __name__ == "__main__":
    sys.exit(main())
