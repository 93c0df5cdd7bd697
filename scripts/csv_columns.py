"""Numeric CSV files as columns: the reader the plot scripts share.

A file has one header row of column names, then rows of numbers; lines that start with `#`
(a log's comment header) and blank lines are skipped.
"""
import csv


def read_columns(path):
    """Returns (header, columns): the column names in file order, and name -> list of floats."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(line for line in f if line.strip() and not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: no header row")
    header = [name.strip() for name in rows[0]]
    columns = {name: [] for name in header}
    for line, row in enumerate(rows[1:], start=2):
        try:
            for name, value in zip(header, row):
                columns[name].append(float(value))
        except ValueError as error:
            raise SystemExit(f"{path}: data row {line}: {error}") from None
    return header, columns
