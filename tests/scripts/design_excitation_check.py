"""scripts/design_excitation.py on the pendulum bench (needs the built binary): at the bench's
reference values, a larger excitation is predicted to pin every parameter better than a small
one, a candidate faster than --max-velocity is rejected, and fitting the simulated data from
the config's starts lands within three predicted standard errors of the values behind them."""

import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCRIPT = os.path.join(ROOT, "scripts", "design_excitation.py")
FIT = os.path.join(ROOT, "scenarios", "fit", "bench_hidden.yaml")
BINARY = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(ROOT, "build", "motoflex")
# The bench's reference values (scenarios/truth/hidden/none.yaml), as a first fit finds them.
ESTIMATE = {"bench.Kt_nm_per_a": 0.35, "bench.armature_kg_m2": 0.003,
            "joint.pendulum.friction_nm": 0.08, "joint.pendulum.viscous_nm_s_per_rad": 0.02}


class DesignExcitationTest(unittest.TestCase):
    def test_ranks_rejects_and_predicts(self):
        with tempfile.TemporaryDirectory() as tmp:
            estimate = os.path.join(tmp, "estimate.json")
            with open(estimate, "w", encoding="utf-8") as f:
                json.dump({"free": ESTIMATE}, f)
            out = os.path.join(tmp, "out")
            result = subprocess.run(
                [sys.executable, SCRIPT, FIT, "--params", estimate, "--out", out, "--binary",
                 BINARY, "--kinds", "chirp", "--bands", "0.2-1,1-6", "--amplitudes", "0.3,1.2",
                 "--max-velocity", "8", "--check"], capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(os.path.join(out, "design.md"), encoding="utf-8") as f:
                table = f.read()
            rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
                    for line in table.splitlines() if line.startswith("| chirp")}
            big, small = rows["chirp 0.2-1 Hz, 1.2 rad"], rows["chirp 0.2-1 Hz, 0.3 rad"]
            for b, s in zip(big[2:], small[2:]):  # relative errors, parameter by parameter
                self.assertLess(float(b), float(s))
            self.assertEqual(rows["chirp 1-6 Hz, 1.2 rad"][1], "too fast")
            checks = [line for line in table.splitlines() if re.match(r"\| chirp .*\(score", line)]
            self.assertEqual(len(checks), 2)
            for line in checks:
                for cell in line.split("|")[2:-1]:
                    self.assertLess(float(cell), 3.0, line)
            for name in ("excitation_scenario.yaml", "excitation.csv", "excitation.yaml"):
                self.assertTrue(os.path.exists(os.path.join(out, name)), name)


if __name__ == "__main__":
    unittest.main()
