#!/usr/bin/env python3
"""Fails when a bundled robot's default for a fitted parameter is (within 1 %) the truth.

Every truth file in scenarios/truth/ (the models behind reference_data/, recorded by
scripts/make_reference_data) names a robot, directly (`robot:`) or through the scenarios of its
recordings. A fit holds every parameter it does not free at that robot's default, so a default
equal to the truth would hand the fit the answer. This check compares, for every parameter a
truth file sets, the robot's default with the truth value and reports each fitted kind whose
default lies within 1 % of it.

Exempt, by the explicit list EXEMPT below: datasheet values (supply, R, L, K_t, gear ratios, the
bench's measured R), set-up values the original program never fitted (MoToFlex's stiffness, mu,
soft ERP, slip, ERP, the motoflex_2011 switches; ../shared/reference/nao.md §3.2) and recording
conditions (sensor.*). A term switched off (0) in both the truth and the default is a choice of
model structure, not a value, and is not compared either.

    scripts/check_nominal_defaults.py          # exit 1 and one line per violation
"""

import fnmatch
import sys
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
TOLERANCE = 0.01

# (pattern, reason): parameters whose default may rightly equal the truth.
EXEMPT = [
    ("motor.supply_v", "datasheet: Li-ion 21.6 V nominal"),
    ("motor.R_ohm", "datasheet constant"),
    ("motor.L_h", "datasheet constant"),
    ("motor.Kt_nm_per_a", "datasheet constant"),
    ("gear.*.ratio", "datasheet reduction"),
    ("bench.R_ohm", "measured on the bench (BAM: 2.6 ohm)"),
    ("motor.stiffness", "set-up value MoToFlex does not fit"),
    ("contact.mu", "set-up value MoToFlex does not fit"),
    ("contact.soft_erp", "set-up value MoToFlex does not fit"),
    ("contact.slip", "set-up value MoToFlex does not fit"),
    ("world.erp", "set-up value MoToFlex does not fit"),
    ("motoflex_2011.*", "switches of the 2011 program's semantics"),
    ("sensor.*", "recording condition (encoder resolution, noise, delay)"),
]


def exemption(name):
    for pattern, reason in EXEMPT:
        if fnmatch.fnmatchcase(name, pattern):
            return reason
    return None


def load(path):
    return yaml.safe_load(Path(path).read_text())


def truth_robots(truth_path):
    """The robot.yaml files a truth file's recordings run on."""
    truth = load(truth_path)
    folder = truth_path.parent
    if "robot" in truth:
        return {(folder / truth["robot"] / "robot.yaml").resolve()}
    robots = set()
    for recording in truth.get("recordings", []):
        scenario_path = (folder / recording["scenario"]).resolve()
        scenario = load(scenario_path)
        robots.add((scenario_path.parent / scenario["robot"] / "robot.yaml").resolve())
    return robots


def truth_values(truth_path):
    """(name, value) of every parameter the truth file sets, its recordings' own included."""
    truth = load(truth_path)
    values = dict(truth.get("parameters") or {})
    for recording in truth.get("recordings", []):
        values.update(recording.get("parameters") or {})
    return values


def violations(truth_path, robot_path):
    """Lines naming each fitted-kind default within TOLERANCE of the truth."""
    defaults = {name: row[0] for name, row in (load(robot_path).get("parameters") or {}).items()}
    found = []
    for name, truth in truth_values(truth_path).items():
        if name not in defaults or exemption(name):
            continue  # effect parameters (not in the robot) or an exempt kind
        default, truth = float(defaults[name]), float(truth)
        if default == 0.0 and truth == 0.0:
            continue  # a term off in both: structure, not a value
        if abs(default - truth) <= TOLERANCE * abs(truth):
            found.append(f"{robot_path.relative_to(ROOT) if robot_path.is_relative_to(ROOT) else robot_path}: "
                         f"{name} default {default:g} is within {100 * TOLERANCE:g} % of the "
                         f"truth {truth:g} ({truth_path.name})")
    return found


def check(truth_dir):
    """(violations, number of (truth, robot) pairs compared)."""
    found, pairs = [], 0
    for truth_path in sorted(Path(truth_dir).rglob("*.yaml")):
        if "recordings" not in (load(truth_path) or {}):
            continue
        for robot_path in sorted(truth_robots(truth_path)):
            pairs += 1
            found += violations(truth_path, robot_path)
    return found, pairs


def main():
    found, pairs = check(ROOT / "scenarios" / "truth")
    for line in found:
        print(line)
    print(f"check_nominal_defaults: {pairs} truth/robot pairs, {len(found)} default(s) within "
          f"{100 * TOLERANCE:g} % of the truth")
    return 1 if found or pairs == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
