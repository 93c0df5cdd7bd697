#!/usr/bin/env python3
"""Checks that motoflex's public headers do not pull in the engines behind them.

Every header under include/motoflex/ (and es/include/) is preprocessed together with `c++ -M`;
none of them may reach ODE, urdfdom, yaml-cpp, MuJoCo, sdformat, NLopt or MPI headers, so a
program built on motoflex compiles against Eigen and nlohmann-json alone. Exit 1 names the
headers that leak and what they pull in.
Usage: scripts/check_public_headers.py [--compiler c++]
"""
import argparse
import glob
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FORBIDDEN = ["/ode/", "/urdf", "/yaml-cpp/", "/mujoco/", "/sdformat", "/ignition/", "/nlopt",
             "/openmpi/", "/mpi.h"]


def dependencies(compiler, header):
    with tempfile.NamedTemporaryFile("w", suffix=".cpp", delete=False) as tu:
        tu.write(f'#include "{header}"\n')
        path = tu.name
    try:
        out = subprocess.run(
            [compiler, "-std=c++20", "-M", "-I", os.path.join(ROOT, "include"), "-I",
             os.path.join(ROOT, "es", "include"), "-I", "/usr/include/eigen3", path],
            capture_output=True, text=True)
    finally:
        os.unlink(path)
    if out.returncode != 0:
        return None, out.stderr.strip().splitlines()[:3]
    return out.stdout.replace("\\\n", " ").split(), []


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--compiler", default="c++")
    args = parser.parse_args()
    headers = sorted(glob.glob(os.path.join(ROOT, "include", "motoflex", "**", "*.hpp"),
                           recursive=True))
    headers += sorted(glob.glob(os.path.join(ROOT, "es", "include", "**", "*.hpp"),
                                recursive=True))
    problems = []
    for header in headers:
        deps, errors = dependencies(args.compiler, header)
        rel = os.path.relpath(header, ROOT)
        if deps is None:
            problems.append(f"{rel}: does not compile on its own: {' / '.join(errors)}")
            continue
        leaks = sorted({d for d in deps
                        if not d.startswith(ROOT) and any(f in d for f in FORBIDDEN)})
        if leaks:
            problems.append(f"{rel}: pulls in {', '.join(leaks[:3])}")
    for p in problems:
        print(p)
    print(f"check_public_headers: {len(headers)} headers, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
