"""scripts/readme_tables.py: a generated README table must equal its committed source table."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                      "readme_tables.py")
SOURCE = "# Results\n\nprose\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n| c |\n|---|\n| 3 |\n"


def run(root, mode, name="doc.md"):
    return subprocess.run([sys.executable, SCRIPT, mode, "--root", root, name],
                          capture_output=True, text=True)


class ReadmeTablesTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        os.makedirs(os.path.join(self.root, "benchmarks", "x"))
        with open(os.path.join(self.root, "benchmarks", "x", "report.md"), "w") as f:
            f.write(SOURCE)

    def tearDown(self):
        self.tmp.cleanup()

    def write_doc(self, body):
        with open(os.path.join(self.root, "doc.md"), "w") as f:
            f.write(body)

    def read_doc(self):
        with open(os.path.join(self.root, "doc.md")) as f:
            return f.read()

    def block(self, table_index, rows):
        return (f"text\n<!-- generated from benchmarks/x/report.md, table {table_index} -->\n"
                + "".join(r + "\n" for r in rows) + "<!-- end of generated table -->\nmore\n")

    def test_matching_table_passes(self):
        self.write_doc(self.block(2, ["| c |", "|---|", "| 3 |"]))
        result = run(self.root, "--check")
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_a_changed_number_fails_and_write_repairs_it(self):
        self.write_doc(self.block(1, ["| a | b |", "|---|---|", "| 1 | 5 |"]))
        result = run(self.root, "--check")
        self.assertEqual(result.returncode, 1)
        self.assertIn("-| 1 | 5 |", result.stdout)
        self.assertIn("+| 1 | 2 |", result.stdout)
        self.assertEqual(run(self.root, "--write").returncode, 0)
        self.assertIn("| 1 | 2 |\n<!-- end of generated table -->\nmore", self.read_doc())
        self.assertEqual(run(self.root, "--check").returncode, 0)

    def test_missing_source_table_or_file_fails(self):
        self.write_doc(self.block(3, []))
        self.assertIn("has 2 table(s), not a table 3", run(self.root, "--check").stderr)
        self.write_doc(self.block(1, []).replace("x/report", "y/report"))
        self.assertIn("does not exist", run(self.root, "--check").stderr)

    def test_unclosed_marker_names_the_line(self):
        self.write_doc("a\n<!-- generated from benchmarks/x/report.md, table 1 -->\n| a |\n")
        result = run(self.root, "--check")
        self.assertEqual(result.returncode, 1)
        self.assertIn("doc.md:2: generated table never closed", result.stderr)


if __name__ == "__main__":
    unittest.main()
