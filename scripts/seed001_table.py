#!/usr/bin/env python3
"""The README table of seed 001's experiments, from what `motoflex experiment seed001` wrote.

Reads DIR/seed001.json and writes DIR/table.md: one row per experiment of seed 001 §5, the
paper's number beside ours. The paper's numbers (and those of the original 2011 program rebuilt,
../shared/reference/motoflex_2011.md §1) are facts from the references, fixed here; every number
in the "ours" column comes from the JSON.

Usage: seed001_table.py [DIR]   (default benchmarks/seed001)
       seed001_table.py --gait DIR  (scenarios/experiments/seed001_gait.yaml's run: one row per
                                     gait option changed, one column per model variant)
"""

import json
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The 2011 semantics' expected results on the walks the original program's falls compare with
# (its own command files, and our planner with its walking engine's gait), with and without the
# float state.
PAPER_DORTMUND_200 = ("209 mm/s, pitch oscillates (original program on its own file: 214 mm/s "
                      "mean over 1 s to the fall at 5.42 s)")
PAPER_DORTMUND_50 = ("falls after the first step, sideways (original program on its own file: "
                     "3.08 s, 0.38 m lateral, 17 mm/s)")
PAPER_COMMANDS_200 = ("209 mm/s (original program rebuilt: 214 mm/s mean over 1-9 s, falls at "
                      "5.42 s; its x87 dWorldStep build: 147 mm/s, falls at 9.2 s)")
PAPER_COMMANDS_50 = ("falls after the first step (original program rebuilt: falls at 3.08 s "
                     "sideways, 0.38 m lateral, 17 mm/s)")

# (walk, variant, row label, the paper's result) in the order of the paper's Section 5.
ROWS = [
    ("walk_200_1", "rigid", "200 mm/s, 1 s: rigid model", "200 mm/s"),
    ("walk_200_1", "ext_2011", "200 mm/s, 1 s: extended, 2011 semantics, Normal.gnm",
     "209 mm/s, pitch oscillates, every second oscillation further out (original program "
     "rebuilt: 214 mm/s, falls at 5.42 s)"),
    ("walk_200_1", "ext_physical",
     "200 mm/s, 1 s: extended, physical semantics fitted to (b)'s logs",
     "209 mm/s"),
    ("walk_50_2", "rigid", "50 mm/s, 2 s: rigid model", "walks on"),
    ("walk_50_2", "ext_2011", "50 mm/s, 2 s: extended, 2011 semantics, Normal.gnm",
     "falls after the first step, sideways (original program rebuilt: falls at 3.08 s, "
     "0.38 m lateral)"),
    ("walk_50_2", "ext_physical",
     "50 mm/s, 2 s: extended, physical semantics fitted to (b)'s logs",
     "falls after the first step"),
    # Our planner with the gait of the engine that wrote the original's command files.
    ("walk_200_1_dortmund", "rigid_2011",
     "200 mm/s, 1 s, the Dortmund engine's gait: rigid model, box robot", "200 mm/s (ODE only)"),
    ("walk_200_1_dortmund", "ext_2011",
     "200 mm/s, 1 s, the Dortmund engine's gait: extended, 2011 semantics",
     PAPER_DORTMUND_200),
    ("walk_200_1_dortmund", "ext_2011_float",
     "200 mm/s, 1 s, the Dortmund engine's gait: extended, 2011 semantics, float state",
     PAPER_DORTMUND_200),
    ("walk_200_1_dortmund", "ext_physical",
     "200 mm/s, 1 s, the Dortmund engine's gait: extended, physical semantics fitted to (b)'s "
     "logs", "209 mm/s"),
    ("walk_50_2_dortmund", "rigid_2011",
     "50 mm/s, 2 s, the Dortmund engine's gait: rigid model, box robot", "walks on"),
    ("walk_50_2_dortmund", "ext_2011",
     "50 mm/s, 2 s, the Dortmund engine's gait: extended, 2011 semantics",
     PAPER_DORTMUND_50),
    ("walk_50_2_dortmund", "ext_2011_float",
     "50 mm/s, 2 s, the Dortmund engine's gait: extended, 2011 semantics, float state",
     PAPER_DORTMUND_50),
    ("walk_50_2_dortmund", "ext_physical",
     "50 mm/s, 2 s, the Dortmund engine's gait: extended, physical semantics fitted to (b)'s "
     "logs", "falls after the first step"),
    # The original's own command files replayed (not bundled; `--commands`, README).
    ("commands_200_1", "rigid_2011", "200 mm/s, original's command file: rigid model, box robot",
     "200 mm/s (ODE only)"),
    ("commands_200_1", "ext_2011", "200 mm/s, original's command file: extended, 2011 semantics",
     PAPER_COMMANDS_200),
    ("commands_200_1", "ext_2011_float",
     "200 mm/s, original's command file: extended, 2011 semantics, float state",
     PAPER_COMMANDS_200),
    ("commands_200_1", "ext_physical",
     "200 mm/s, original's command file: extended, physical semantics fitted to (b)'s logs",
     "209 mm/s"),
    ("commands_50_2", "rigid_2011", "50 mm/s, original's command file: rigid model, box robot",
     "walks on"),
    ("commands_50_2", "ext_2011", "50 mm/s, original's command file: extended, 2011 semantics",
     PAPER_COMMANDS_50),
    ("commands_50_2", "ext_2011_float",
     "50 mm/s, original's command file: extended, 2011 semantics, float state",
     PAPER_COMMANDS_50),
    ("commands_50_2", "ext_physical",
     "50 mm/s, original's command file: extended, physical semantics fitted to (b)'s logs",
     "falls after the first step"),
]


def degrees(rad):
    return math.degrees(rad) if rad is not None else float("nan")


def describe_run(run):
    parts = []
    if run.get("fell"):
        parts.append(f"falls at {run['fall_s']:.2f} s ({run.get('fall_direction') or '?'})")
    else:
        parts.append("no fall")
    if run.get("speed_mm_s") is not None:
        parts.append(f"{run['speed_mm_s']:.1f} mm/s over the steady part")
    lateral_m = run["lateral_m"] if abs(run["lateral_m"]) >= 0.005 else 0.0
    parts.append(f"lateral {lateral_m:.2f} m")
    if run.get("pitch_range_rad") is not None:  # none when it fell before the steady part
        parts.append(f"pitch range {degrees(run['pitch_range_rad']):.1f}°")
    if run.get("pitch_alternation") is not None:
        parts.append(f"alternation {run['pitch_alternation']:.2f}")
    parts.append(f"peak roll {degrees(run.get('max_abs_roll_rad')):.1f}°")
    if run.get("commands"):
        parts.append(f"mean speed 1-9 s {run['mean_speed_mm_s']:.0f} mm/s")
    text = ", ".join(parts)
    if run.get("ensemble"):
        text += "; " + describe_ensemble(run["ensemble"], run.get("commands"))
    if run.get("quickstep_seed_ensemble"):
        text += "; " + describe_ensemble(run["quickstep_seed_ensemble"], run.get("commands"),
                                         kind="seeds")
    return text


def spread(values, digits, unit):
    known = sorted(v for v in values if v is not None)
    if not known:
        return "none"
    median = known[len(known) // 2] if len(known) % 2 else \
        0.5 * (known[len(known) // 2 - 1] + known[len(known) // 2])
    return f"{median:.{digits}f} {unit} (median; {known[0]:.{digits}f}-{known[-1]:.{digits}f})"


def describe_ensemble(ensemble, commands, label=None, kind="noise"):
    """The perturbed replays (same model, commands + 1e-7 rad noise; kind "seeds": the commands
    as they are, the quick step's rows in other orders): how much is chaos. Their mean speed from
    1 s for a command file (or `commands`), else their steady speed; `label` names it ("" for
    none)."""
    n = ensemble["size"]
    what = "replays with 1e-7 rad noise" if kind == "noise" else "other quick-step row orders"
    text = f"{n} {what}: {ensemble['fell']} of {n} fall"
    if ensemble["fell"]:
        text += ", at " + spread(ensemble["fall_s"], 2, "s")
    key = "mean_speed_mm_s" if commands else "speed_mm_s"
    if label is None:
        label = "mean speed 1-9 s" if commands else "steady speed"
    return text + ", " + (label + " " if label else "") + spread(ensemble[key], 0, "mm/s")


def describe_zmp(variant, result):
    trials = result["trials"]
    walked = [t for t in trials if not t.get("fell") and t.get("speed_mm_s") is not None]
    chosen = result.get("chosen")
    text = f"{variant}: {len(walked)} of {len(trials)} settings walk to the end"
    if chosen:
        pick = next(t for t in trials
                    if t["option"] == chosen["option"] and t["value"] == chosen["value"])
        text += (f"; chosen `{chosen['option']}` {chosen['value']:g} (peak roll "
                 f"{degrees(pick['max_abs_roll_rad']):.1f}°, {pick['speed_mm_s']:.0f} mm/s)")
    return text


def describe_gait_cell(run):
    """One variant's run in the gait table: fall or not, and the mean speed from 1 s to
    min(9 s, the end) (the measure of the original program's 214 mm/s, motoflex_2011.md §1)."""
    if run is None:
        return "not run"
    if "unplannable" in run:
        return "unplannable"
    end = min(9.0, run["end_time_s"]) if run.get("end_time_s") else 9.0
    speed = f"{run['mean_speed_mm_s']:.0f} mm/s over 1-{end:.1f} s"
    if run.get("fell"):
        return f"falls at {run['fall_s']:.2f} s ({run.get('fall_direction') or '?'}), {speed}"
    return f"walks, {speed}"


# The gait file's walks: the paper's result and the original program's on its own command file
# (motoflex_2011.md §1), beside each walk of our planner.
GAIT_WALKS = {
    "walk_200_1": ("200 mm/s, 1 s, our planner's gait",
                   "209 mm/s (rigid 200); original program on its own file: 214 mm/s, falls "
                   "at 5.42 s"),
    "walk_50_2": ("50 mm/s, 2 s, our planner's gait",
                  "falls after the first step, sideways; original program on its own file: "
                  "3.08 s, 0.38 m lateral, 17 mm/s"),
    "walk_200_1_dortmund": ("200 mm/s, 1 s, the Dortmund engine's gait options",
                            "209 mm/s (rigid 200); original program on its own file: 214 mm/s, "
                            "falls at 5.42 s"),
    "walk_50_2_dortmund": ("50 mm/s, 2 s, the Dortmund engine's gait options",
                           "falls after the first step, sideways; original program on its own "
                           "file: 3.08 s, 0.38 m lateral, 17 mm/s"),
}


def describe_gait_run(run):
    """A walk's run with its perturbed replays, if any."""
    cell = describe_gait_cell(run)
    if run and run.get("fell") and abs(run.get("lateral_m") or 0.0) >= 0.005:
        cell += f", lateral {run['lateral_m']:.2f} m"
    ensemble = (run or {}).get("ensemble")
    if ensemble:  # the speed's measure is the cell's, named there
        cell += "; " + describe_ensemble(ensemble, True, label="")
    seeds = (run or {}).get("quickstep_seed_ensemble")
    if seeds:
        cell += "; " + describe_ensemble(seeds, True, label="", kind="seeds")
    return cell


def gait_walk_lines(data, variants):
    """Table 1 of the gait file: each of its walks under each variant."""
    lines = ["| walk | paper; original program | " + " | ".join(variants) + " |",
             "|---|---|" + "---|" * len(variants)]
    for name, (label, paper) in GAIT_WALKS.items():
        if name in data:
            cells = [describe_gait_run(data[name].get(v)) for v in variants]
            lines.append(f"| {label} (`{name}`) | {paper} | " + " | ".join(cells) + " |")
    return lines


def gait_table_lines(data):
    """The gait file's run (scenarios/experiments/seed001_gait.yaml): table 1, its walks under
    every variant; table 2, the 200 mm/s walk of our planner with one gait option changed at a
    time (the file's `zmp.search`)."""
    zmp = data["zmp_experiment"]
    walk = data[zmp["walk"]]
    variants = list(zmp["variants"])
    lines = gait_walk_lines(data, variants) + [""]
    lines += ["| walk option changed | " + " | ".join(variants) + " |",
              "|---|" + "---|" * len(variants)]
    defaults = ", ".join(f"{k} {v:g}" for k, v in zmp["defaults"].items())
    cells = [describe_gait_cell(walk.get(v)) for v in variants]
    lines.append(f"| none (the walk file: {defaults}) | " + " | ".join(cells) + " |")
    trials = {v: zmp["variants"][v]["trials"] for v in variants}
    for i, trial in enumerate(trials[variants[0]]):
        row = [describe_gait_cell(trials[v][i]) for v in variants]
        lines.append(f"| `{trial['option']}` {trial['value']:g} | " + " | ".join(row) + " |")
    return lines


def table_lines(data):
    lines = ["| row | paper | ours |", "|---|---|---|"]
    for walk, variant, label, paper in ROWS:
        run = data.get(walk, {}).get(variant)
        if run and (walk.startswith("commands_") or walk.endswith("_dortmund")):
            run = dict(run, commands=True)  # the original's measure: mean speed from 1 s
        ours = ("pending: " + run["pending"]) if run and "pending" in run else \
            describe_run(run) if run else "not run"
        lines.append(f"| {label} | {paper} | {ours} |")
    zmp = data.get("zmp_experiment")
    if zmp:
        cells = [describe_zmp(v, r) for v, r in zmp["variants"].items()]
        lines.append("| modified reference ZMP, 50 mm/s, extended | stable in simulation iff on "
                     f"the robot | {'; '.join(cells)} |")
    return lines


def main():
    args = sys.argv[1:]
    gait = "--gait" in args
    args = [a for a in args if a != "--gait"]
    folder = args[0] if args else os.path.join(ROOT, "benchmarks", "seed001")
    with open(os.path.join(folder, "seed001.json"), encoding="utf-8") as f:
        data = json.load(f)
    lines = gait_table_lines(data) if gait else table_lines(data)
    with open(os.path.join(folder, "table.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
