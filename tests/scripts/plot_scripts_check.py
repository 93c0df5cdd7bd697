"""The shared CSV reader of the plot scripts (scripts/csv_columns.py) and two plot scripts that
draw from it, on small files written here: a joint log with a comment header (plot_log.py) and a
loop folder (plot_loop.py). Needs matplotlib (run by ctest with Debian's python3)."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
from csv_columns import read_columns  # noqa: E402


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def run(script, *args):
    return subprocess.run([sys.executable, os.path.join(SCRIPTS, script), *args],
                          capture_output=True, text=True)


class CsvColumnsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_comments_blank_lines_and_padded_names(self):
        path = write(os.path.join(self.tmp.name, "a.csv"),
                     "# robot: arm\n\ntime_s, elbow.cmd ,elbow.meas\n0,1.5,-2\n0.01,2.5,-3e-1\n")
        header, columns = read_columns(path)
        self.assertEqual(header, ["time_s", "elbow.cmd", "elbow.meas"])
        self.assertEqual(columns["elbow.cmd"], [1.5, 2.5])
        self.assertEqual(columns["elbow.meas"], [-2.0, -0.3])

    def test_a_bad_number_names_the_file_and_row(self):
        path = write(os.path.join(self.tmp.name, "b.csv"), "t,x\n0,1\n1,oops\n")
        with self.assertRaises(SystemExit) as caught:
            read_columns(path)
        self.assertIn("b.csv: data row 3", str(caught.exception))

    def test_an_empty_file_is_refused(self):
        path = write(os.path.join(self.tmp.name, "c.csv"), "# only a comment\n")
        with self.assertRaises(SystemExit) as caught:
            read_columns(path)
        self.assertIn("no header row", str(caught.exception))


class PlotScriptsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def assert_png(self, path):
        self.assertTrue(os.path.exists(path), path)
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)

    def test_plot_log_draws_a_log_with_a_comment_header(self):
        rows = "\n".join(f"{0.01 * i},{0.1 * i},{0.09 * i}" for i in range(50))
        log = write(os.path.join(self.dir, "log.csv"),
                    "# motoflex joint log\ntime_s,knee.cmd,knee.meas\n" + rows + "\n")
        out = os.path.join(self.dir, "log.png")
        result = run("plot_log.py", log, "--out", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_png(out)

    def test_plot_loop_draws_residuals_and_ranking(self):
        for name, scale in (("before_series.csv", 1.0), ("after_series.csv", 0.2)):
            rows = "\n".join(f"{0.01 * i},{scale * 0.001 * (i % 7)}" for i in range(40))
            write(os.path.join(self.dir, name), "time_s,knee.residual_rad\n" + rows + "\n")
        write(os.path.join(self.dir, "loop.json"),
              '{"iterations": [{"ranking": [{"effect": "stribeck", "score": 0.4},'
              ' {"effect": "backlash", "score": 0.1}]}]}')
        result = run("plot_loop.py", self.dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_png(os.path.join(self.dir, "residuals_before_after.png"))
        self.assert_png(os.path.join(self.dir, "ranking.png"))


if __name__ == "__main__":
    unittest.main()
