#!/usr/bin/env python3
"""Instructions per physics step of two motoflex binaries, counted by callgrind.

Wall-clock benchmarks on a shared 2-core machine are noisy; an instruction count is the same
for the same binary and input whatever else runs. This runs `motoflex bench` under
`valgrind --tool=callgrind` for two simulated durations and takes the difference, so model
loading cancels out and what remains is the cost of the extra physics steps.
Usage: scripts/compare_instructions.py OLD_BINARY NEW_BINARY [bench options...]
       (default bench options: --robot nao --servo motoflex --flex 2 --substeps 100 --solver step)
"""
import re
import subprocess
import sys

DEFAULT = ["--robot", "nao", "--servo", "motoflex", "--flex", "2", "--substeps", "100",
           "--solver", "step"]
SHORT_S, LONG_S = 0.3, 0.6


def instructions(binary, options, seconds):
    run = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                          binary, "bench", *options, "--seconds", str(seconds)],
                         capture_output=True, text=True, check=True)
    return int(re.search(r"Collected : (\d+)", run.stderr).group(1))


def per_step(binary, options):
    steps = (LONG_S - SHORT_S) / 0.001
    return (instructions(binary, options, LONG_S) - instructions(binary, options, SHORT_S)) / steps


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    options = sys.argv[3:] or DEFAULT
    a, b = per_step(old, options), per_step(new, options)
    print(f"instructions per physics step ({' '.join(options)}):")
    print(f"  {old}: {a:,.0f}")
    print(f"  {new}: {b:,.0f}")
    print(f"  new/old = {b / a:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
