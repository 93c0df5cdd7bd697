#!/usr/bin/env python3
"""README tables generated from committed results (benchmarks/<name>/).

A generated table in a Markdown file sits between two marker lines:

    <!-- generated from benchmarks/strategies/report.md, table 1 -->
    | ... |
    <!-- end of generated table -->

and must equal the N-th table (a run of lines starting with '|') of the named file, which a
benchmark or report script wrote (scripts/reproduce runs them all). `--check` (the fast-tier
test docs.ReadmeTablesMatchCommittedResults) fails when a table differs from its source or
names a missing one; `--write` copies the sources into the documents.

Usage: readme_tables.py [--check | --write] [--root DIR] [FILE.md ...]
       (default files: README.md and scenarios/robots/nao/README.md)
"""

import argparse
import difflib
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_FILES = ["README.md", "scenarios/robots/nao/README.md"]
BEGIN = re.compile(r"^<!-- generated from (\S+), table (\d+) -->$")
END = "<!-- end of generated table -->"


class TableError(Exception):
    """A marker or source problem, with the document and line it is about."""


def tables_of(lines):
    """The Markdown tables of a file: lists of consecutive lines that start with '|'."""
    tables, current = [], []
    for line in lines:
        if line.startswith("|"):
            current.append(line)
        elif current:
            tables.append(current)
            current = []
    if current:
        tables.append(current)
    return tables


def source_table(root, source, index, where):
    path = os.path.join(root, source)
    if not os.path.isfile(path):
        raise TableError(f"{where}: source {source} does not exist")
    with open(path, encoding="utf-8") as f:
        tables = tables_of(f.read().splitlines())
    if not 1 <= index <= len(tables):
        raise TableError(f"{where}: {source} has {len(tables)} table(s), not a table {index}")
    return tables[index - 1]


def generated_blocks(lines, name):
    """(begin line index, end line index, source, table index) of every marker pair."""
    blocks, open_block = [], None
    for i, line in enumerate(lines):
        match = BEGIN.match(line.strip())
        if match:
            if open_block:
                raise TableError(f"{name}:{i + 1}: a generated table opens before "
                                 f"line {open_block[0] + 1}'s is closed")
            open_block = (i, match.group(1), int(match.group(2)))
        elif line.strip() == END:
            if not open_block:
                raise TableError(f"{name}:{i + 1}: '{END}' without an opening marker")
            blocks.append((open_block[0], i, open_block[1], open_block[2]))
            open_block = None
    if open_block:
        raise TableError(f"{name}:{open_block[0] + 1}: generated table never closed")
    return blocks


def process(root, name, write):
    """Returns the list of differences (empty when the document is up to date)."""
    path = os.path.join(root, name)
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    blocks = generated_blocks(lines, name)
    problems, output, last = [], [], 0
    for begin, end, source, index in blocks:
        expected = source_table(root, source, index, f"{name}:{begin + 1}")
        actual = lines[begin + 1:end]
        if actual != expected:
            diff = "\n".join(difflib.unified_diff(actual, expected, f"{name}:{begin + 2}",
                                                  f"{source} table {index}", lineterm=""))
            problems.append(diff)
        output += lines[last:begin + 1] + expected
        last = end
    output += lines[last:]
    if write and problems:
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(output) + "\n")
    return problems, len(blocks)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 when a table differs")
    mode.add_argument("--write", action="store_true", help="copy the sources into the files")
    parser.add_argument("--root", default=ROOT)
    parser.add_argument("files", nargs="*", default=DEFAULT_FILES)
    args = parser.parse_args()
    failed = False
    for name in args.files:
        try:
            problems, count = process(args.root, name, args.write)
        except (TableError, OSError) as error:
            print(f"readme_tables: {error}", file=sys.stderr)
            failed = True
            continue
        for diff in problems:
            print(diff)
        if problems and not args.write:
            print(f"readme_tables: {name}: {len(problems)} of {count} generated table(s) differ "
                  "from their committed results (scripts/readme_tables.py --write)",
                  file=sys.stderr)
            failed = True
        elif args.write:
            print(f"{name}: {len(problems)} of {count} generated table(s) rewritten")
        else:
            print(f"{name}: {count} generated table(s) match their committed results")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
