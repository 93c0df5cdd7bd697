#!/usr/bin/env python3
"""Builds the libFuzzer seed corpus of scripts/fuzz from the repository's own inputs:
YAML configs (scenarios/, reference_data/ sidecars), joint logs with their sidecars (first
rows only), robot.yaml + URDF pairs, parameter JSON files, plus the hand-written seeds in
fuzz/seeds/<target>/.  Usage: fuzz_corpus.py OUT_DIR"""
import pathlib
import re
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
SEPARATOR = "\n=====\n"
MAX_BYTES = 60000


def put(out, target, name, text):
    folder = out / target
    folder.mkdir(parents=True, exist_ok=True)
    data = text.encode("utf-8", "replace")[:MAX_BYTES]
    (folder / re.sub(r"[^A-Za-z0-9_.-]", "_", name)).write_bytes(data)


def main():
    out = pathlib.Path(sys.argv[1])
    yamls = sorted(ROOT.glob("scenarios/**/*.yaml")) + sorted(ROOT.glob("reference_data/**/*.yaml"))
    for path in yamls:
        put(out, "yaml_config", str(path.relative_to(ROOT)), path.read_text())
    for csv in sorted(ROOT.glob("reference_data/**/*.csv"))[:60]:
        sidecar = csv.with_suffix(".yaml")
        head = "".join(csv.read_text().splitlines(keepends=True)[:40])
        side = sidecar.read_text() if sidecar.exists() else ""
        put(out, "joint_log", str(csv.relative_to(ROOT)), head + (SEPARATOR + side if side else ""))
        if side:
            put(out, "sidecar", str(sidecar.relative_to(ROOT)), side)
    for robot in sorted(ROOT.glob("scenarios/robots/*/robot.yaml")):
        text = robot.read_text()
        urdf_name = re.search(r"^urdf:\s*(\S+)", text, re.M)
        if not urdf_name:
            continue
        urdf = (robot.parent / urdf_name.group(1)).read_text()
        text = re.sub(r"^urdf:\s*\S+", "urdf: robot.urdf", text, flags=re.M)
        put(out, "robot", robot.parent.name, text + SEPARATOR + urdf)
    for path in sorted(ROOT.glob("reference_data/**/*.json"))[:40]:
        put(out, "parameter_json", str(path.relative_to(ROOT)), path.read_text())
    seeds = ROOT / "fuzz" / "seeds"
    if seeds.exists():
        for folder in seeds.iterdir():
            for path in folder.iterdir():
                (out / folder.name).mkdir(parents=True, exist_ok=True)
                shutil.copy(path, out / folder.name / ("seed_" + path.name))


if __name__ == "__main__":
    main()
