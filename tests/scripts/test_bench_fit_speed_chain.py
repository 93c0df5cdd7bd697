"""scripts/bench_fit_speed.py: the staged chain's rows sit after the measures and before the
CMA-ES fit's per-parameter table, add up the stages, and say whether the target was reached."""

import importlib.util
import sys
import unittest
from pathlib import Path

SCRIPTS = Path(__file__).resolve().parent.parent.parent / "scripts"
sys.path.insert(0, str(SCRIPTS))
spec = importlib.util.spec_from_file_location("bench_fit_speed", SCRIPTS / "bench_fit_speed.py")
bench_fit_speed = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bench_fit_speed)


def chain(ratio_last):
    return {"stages": [{"stage": "short", "evaluations": 600, "wall_seconds": 500.0, "ratio": 1.1},
                       {"stage": "finish", "evaluations": 100, "wall_seconds": 400.0,
                        "ratio": ratio_last}],
            "tolerance": 0.05, "threads": 2, "evaluations": 700, "seconds": 900.0,
            "reached": ratio_last <= 1.05, "within": ["pid.kp_v_per_rad"], "free": 19}


RESULT = {"threads": 2,
          "steps_per_core": {"step": 10000.0, "quick": 25000.0},
          "mujoco": {"model": "m", "mujoco_steps_per_s": 30000.0, "exact_over_mujoco": 0.8,
                     "quick_over_mujoco": 1.1}}


class ChainRowsTest(unittest.TestCase):
    def test_rows_follow_the_measures(self):
        lines = bench_fit_speed.report_lines(dict(RESULT, chain=chain(3.6)))
        self.assertEqual(lines[0], "| measure | value |")
        rows = [line for line in lines if line.startswith("| chain")]
        self.assertEqual(len(rows), 4)
        self.assertEqual(lines[-4:], rows)  # no CMA-ES fit: the chain ends the table
        self.assertIn("700, 900 s; not reached (3.60 × F(truth))", rows[2])
        self.assertIn("(1 of 19) | pid.kp_v_per_rad", rows[3])

    def test_reached_is_said(self):
        rows = bench_fit_speed.chain_lines(chain(1.02))
        self.assertIn("; reached (1.02 × F(truth))", rows[2])


if __name__ == "__main__":
    unittest.main()
