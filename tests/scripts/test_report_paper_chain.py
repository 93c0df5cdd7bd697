"""scripts/report_paper_chain.py: the stage table's flat-scan cell lists each move of the LM
polish's flat scan (summary.json polish.flat_scan_moves) in order, or says there was none."""

import importlib.util
import sys
import unittest
from pathlib import Path

SCRIPTS = Path(__file__).resolve().parent.parent.parent / "scripts"
sys.path.insert(0, str(SCRIPTS))
spec = importlib.util.spec_from_file_location("report_paper_chain",
                                              SCRIPTS / "report_paper_chain.py")
report_paper_chain = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report_paper_chain)


class FlatScanCellTest(unittest.TestCase):
    def test_no_move_says_none(self):
        self.assertEqual(report_paper_chain.flat_scan_text([]), "none")

    def test_moves_are_listed_in_order_with_four_digits(self):
        moves = [{"parameter": "flex.friction_nm", "from": 4.99712, "to": 0.0},
                 {"parameter": "flex.spring_nm_per_rad", "from": 12640.3, "to": 50000.0}]
        self.assertEqual(report_paper_chain.flat_scan_text(moves),
                         "flex.friction_nm 4.997 → 0; flex.spring_nm_per_rad 1.264e+04 → 5e+04")


if __name__ == "__main__":
    unittest.main()
