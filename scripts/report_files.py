"""The one way the report scripts leave their results: OUT/<stem>.md (a Markdown table for
people), OUT/<stem>.json (the rows for programs), and the table on stdout."""
import json
import os


def write_report(out_dir, stem, lines, rows):
    with open(os.path.join(out_dir, stem + ".md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out_dir, stem + ".json"), "w") as f:
        json.dump(rows, f, indent=2)
    print("\n".join(lines))
