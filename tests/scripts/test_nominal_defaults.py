"""scripts/check_nominal_defaults.py: a robot default within 1 % of a truth value must fail."""

import importlib.util
import os
import tempfile
import unittest
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent.parent / "scripts" / "check_nominal_defaults.py"
spec = importlib.util.spec_from_file_location("check_nominal_defaults", SCRIPT)
check_nominal_defaults = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check_nominal_defaults)

ROBOT = """name: r
parameters:
  pid.kp_v_per_rad: [{kp}, 1.0, 1000.0]
  motor.R_ohm: [6.44, 1.0, 10.0]
  flex.friction_nm: [0.0, 0.0, 1.0]
"""
TRUTH = """name: t
robot: ../robots/r
parameters: {{pid.kp_v_per_rad: 319.4724, motor.R_ohm: 6.44, flex.friction_nm: 0.0}}
recordings:
  - {{name: train/a, scenario: a.yaml}}
"""


class NominalDefaultsTest(unittest.TestCase):
    def check(self, kp):
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "robots", "r"))
            os.makedirs(os.path.join(root, "truth"))
            Path(root, "robots", "r", "robot.yaml").write_text(ROBOT.format(kp=kp))
            Path(root, "truth", "t.yaml").write_text(TRUTH.format())
            found, pairs = check_nominal_defaults.check(Path(root, "truth"))
            self.assertEqual(pairs, 1)
            return found

    def test_default_at_the_truth_fails(self):
        found = self.check(319.47)  # 0.0007 % off: the old Nao default
        self.assertEqual(len(found), 1)
        self.assertIn("pid.kp_v_per_rad", found[0])

    def test_default_just_inside_one_percent_fails(self):
        self.assertEqual(len(self.check(319.4724 * 1.0099)), 1)

    def test_nominal_default_passes_and_datasheet_values_are_exempt(self):
        # R equal to the truth (datasheet, exempt); flex friction 0 in both (structure).
        self.assertEqual(self.check(300.0), [])  # 6.1 % off

    def test_bundled_robots_have_nominal_defaults(self):
        root = Path(check_nominal_defaults.ROOT)
        found, pairs = check_nominal_defaults.check(root / "scenarios" / "truth")
        self.assertGreaterEqual(pairs, 12)  # 12 truth files, one robot each: 12 measured
        self.assertEqual(found, [])


if __name__ == "__main__":
    unittest.main()
