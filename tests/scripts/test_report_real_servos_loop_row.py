"""scripts/report_real_servos.py: a loop's row carries the mean absolute error of its base fit and
of its final model on the training logs (the simulated best/ logs of each run against the
imported training logs) beside the held-out pair of loop.json, and --reuse-loops reads a finished
loop without running anything."""

import json
import os
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent.parent / "scripts"))
import report_real_servos  # noqa: E402


def write_log(path, angles_rad):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("# a comment line the reader skips\ntime_s,pendulum.cmd,pendulum.meas\n")
        for k, angle in enumerate(angles_rad):
            f.write("%g,0,%r\n" % (0.005 * k, angle))


class LoopRowTest(unittest.TestCase):
    def test_training_errors_of_the_base_fit_and_the_final_model(self):
        with tempfile.TemporaryDirectory() as work:
            loop = os.path.join(work, "loop")
            base, final = os.path.join(loop, "00_base"), os.path.join(loop, "02_stribeck")
            # Two training logs; the base fit is 0.010 and 0.030 rad off (4 and 2 samples),
            # the final model 0.002 rad off everywhere.
            write_log(os.path.join(loop, "imported", "train", "a.csv"), [0.1, 0.2, 0.3, 0.4])
            write_log(os.path.join(loop, "imported", "train", "b.csv"), [-0.5, -0.6])
            write_log(os.path.join(base, "best", "a.csv"), [0.11, 0.19, 0.31, 0.39])
            write_log(os.path.join(base, "best", "b.csv"), [-0.47, -0.63])
            write_log(os.path.join(final, "best", "a.csv"), [0.102, 0.198, 0.302, 0.398])
            write_log(os.path.join(final, "best", "b.csv"), [-0.498, -0.602])
            with open(os.path.join(loop, "loop.json"), "w") as f:
                json.dump({"base_run_dir": base, "final_run_dir": final, "evaluations": 1234,
                           "wall_seconds": 56.0,
                           "iterations": [
                               {"added_effect": "load_friction", "val_mae_before_rad": 0.05,
                                "val_mae_after_rad": 0.03},
                               {"added_effect": "stribeck", "val_mae_before_rad": 0.03,
                                "val_mae_after_rad": 0.02}]}, f)
            row = report_real_servos.loop_row("/nonexistent/motoflex", "sts3250", "unused",
                                              "unused", work, 1, reuse=True)
        # (4 x 0.010 + 2 x 0.030) / 6 = 0.016 67 rad; the final model 0.002 rad.
        self.assertAlmostEqual(row["train_mae_before_mrad"], 100.0 / 6.0, places=9)
        self.assertAlmostEqual(row["train_mae_mrad"], 2.0, places=9)
        self.assertAlmostEqual(row["val_mae_before_mrad"], 50.0, places=9)
        self.assertAlmostEqual(row["val_mae_mrad"], 20.0, places=9)
        self.assertEqual(row["model"], "motoflex loop (M1 + load_friction + stribeck)")
        self.assertEqual(row["wall_seconds"], 56.0)  # the loop's own, since nothing ran now
        self.assertEqual(row["evaluations"], 1234)
        # A loop.json without its options was run before they were recorded: five candidates.
        self.assertEqual(row["candidates"], 5)

    def test_a_reused_loop_takes_its_fits_own_times(self):
        # Resumed in its folder, a loop's wall clock is its last session's (50 s for a loop
        # whose fits took 2971 s); the fits' own seconds are the run's.
        self.assertEqual(report_real_servos.loop_seconds(
            {"wall_seconds": 50.0, "fit_seconds": 2971.0}), 2971.0)
        self.assertEqual(report_real_servos.loop_seconds({"wall_seconds": 56.0}), 56.0)

    def test_the_candidates_come_from_the_options_the_loop_ran_with(self):
        self.assertEqual(report_real_servos.loop_candidates({"options": {"candidates": 10}}), 10)
        self.assertEqual(report_real_servos.loop_candidates({"iterations": []}), 5)
        row = {"servo": "a", "model": "motoflex loop (M1 + x)", "seed": 2, "candidates": 10}
        self.assertEqual(report_real_servos.loop_label(row),
                         "motoflex loop (M1 + x), seed 2, 10 candidates")
        self.assertEqual(report_real_servos.loop_label({"servo": "a",
                                                        "model": "motoflex loop (M1)"}),
                         "motoflex loop (M1)")


class LoopSeedsTest(unittest.TestCase):
    def test_a_seed_runs_in_its_own_folder_and_keys_its_own_row(self):
        self.assertEqual(report_real_servos.loop_dir("w", 1), os.path.join("w", "loop"))
        self.assertEqual(report_real_servos.loop_dir("w", 3), os.path.join("w", "loop_s3"))
        stored = {"servo": "xl330_traj", "model": "motoflex loop (M1 + stribeck)"}  # no seed: 1
        seed2 = {"servo": "xl330_traj", "model": "motoflex loop (M1 + load_friction)", "seed": 2}
        self.assertEqual(report_real_servos.row_key(stored), ("xl330_traj", "loop", 1, 5))
        self.assertEqual(report_real_servos.row_key(seed2), ("xl330_traj", "loop", 2, 5))
        # The same seed with another candidates count is a row of its own (--merge keeps both).
        self.assertEqual(report_real_servos.row_key(dict(seed2, candidates=10)),
                         ("xl330_traj", "loop", 2, 10))
        self.assertEqual(report_real_servos.row_key({"servo": "x", "model": "M3", "seed": 2}),
                         ("x", "M3", 1, None))

    def test_the_spread_lists_each_split_with_more_than_one_loop(self):
        rows = [{"servo": "a", "model": "motoflex loop (M1)", "val_mae_mrad": 25.0},
                {"servo": "a", "model": "motoflex loop (M1 + x)", "val_mae_mrad": 31.0, "seed": 3},
                {"servo": "a", "model": "motoflex loop (M1 + y)", "val_mae_mrad": 22.0, "seed": 2},
                {"servo": "a", "model": "M1", "val_mae_mrad": 60.0},
                {"servo": "b", "model": "motoflex loop (M1)", "val_mae_mrad": 40.0},
                {"servo": "a", "model": "motoflex loop (M1 + z)", "val_mae_mrad": 20.0,
                 "seed": 2, "candidates": 10},
                {"servo": "a", "model": "motoflex loop (M1 + w)", "val_mae_mrad": 24.0,
                 "candidates": 10}]
        rows += [{"servo": "c", "model": "motoflex loop (M1)", "val_mae_mrad": 48.0, "seed": 2},
                 {"servo": "c", "model": "motoflex loop (M1 + x)", "val_mae_mrad": 26.0,
                  "seed": 2, "candidates": 10}]
        spread = report_real_servos.seed_spread(rows)
        # Each candidates count is a spread of its own; a split with one loop per count is
        # listed too (one seed rerun with another count), one with a single loop is not.
        self.assertEqual(spread, [("a", 5, [(1, 25.0), (2, 22.0), (3, 31.0)], 25.0),
                                  ("a", 10, [(1, 24.0), (2, 20.0)], 22.0),
                                  ("c", 5, [(2, 48.0)], 48.0), ("c", 10, [(2, 26.0)], 26.0)])
        self.assertEqual(report_real_servos.median([4.0, 1.0, 3.0, 2.0]), 2.5)


if __name__ == "__main__":
    unittest.main()
