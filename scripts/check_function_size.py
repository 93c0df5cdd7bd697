#!/usr/bin/env python3
"""Fails when a library function body is longer than 80 lines without saying why.

STYLE.md: a body over ~80 lines is a sign that two jobs share it. This check reads every C++ file
of the libraries (src/, es/, include/, python/; tests are exempt), finds function bodies by their
braces (comments, strings and character literals removed first), and reports each body over the
limit unless one of the eight lines above its opening line holds a comment starting with
`// long:` that says why it stays long. Lambdas and blocks inside a function count towards it.
A text-level check, not a parser: it knows a function body as the outermost brace block whose
opening line follows a closing parenthesis (optionally `const`, `noexcept`, `override`, a
trailing return type or a constructor's initialiser list), outside any other function.
Prints `file:line: function body of N lines (limit 80): <first line>` per finding and exits 1;
exits 0 with a one-line summary otherwise. clang-tidy's readability-function-size (.clang-tidy,
scripts/check) applies the same limit to changed files with a real parser.
Usage: scripts/check_function_size.py [--root DIR] [--limit N] [FILE ...]
"""
import argparse
import os
import re
import sys

FOLDERS = ("src", "es", "include", "python")
SUFFIXES = (".cpp", ".hpp", ".h", ".cc")
FUNCTION_HEAD = re.compile(
    r"\)\s*(const\s*)?(noexcept\s*)?(override\s*)?(final\s*)?(->\s*[\w:<>,\s*&]+)?\{\s*$")
INITIALISER_LIST = re.compile(r"^\s*:\s*\w+[({]|^\s*,?\s*\w+_?[({].*[)}]\s*\{\s*$")
CONTROL = re.compile(r"\b(if|for|while|switch|catch)\s*\(")
TYPE_BLOCK = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b")


def strip_code(text):
    """The text with comments, string and character literals blanked (line breaks kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            open_paren = text.find("(", i + 2)
            delimiter = text[i + 2:open_paren]
            j = text.find(")" + delimiter + '"', open_paren)
            j = n if j < 0 else j + len(delimiter) + 2
            out.append('""' + "".join(ch if ch == "\n" else " " for ch in text[i + 2:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * max(0, min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def long_functions(text, limit):
    """[(first line number, body lines, first line text)] of bodies over `limit` lines."""
    raw = text.split("\n")
    lines = strip_code(text).split("\n")
    stack = []  # (kind, line index)
    found = []
    for index, line in enumerate(lines):
        for ch in line:
            if ch == "{":
                in_function = any(kind == "function" for kind, _ in stack)
                head = line[: line.index("{") + 1] if "{" in line else line
                is_function = (not in_function and not CONTROL.search(line) and
                               not TYPE_BLOCK.match(line) and
                               (FUNCTION_HEAD.search(head) or INITIALISER_LIST.match(line)))
                stack.append(("function" if is_function else "block", index))
            elif ch == "}" and stack:
                kind, start = stack.pop()
                if kind == "function" and index - start > limit:
                    above = "\n".join(raw[max(0, start - 8):start + 1])
                    if "// long:" not in above:
                        found.append((start + 1, index - start, raw[start].strip()))
    return found


def library_files(root):
    for folder in FOLDERS:
        for directory, _, names in os.walk(os.path.join(root, folder)):
            for name in sorted(names):
                if name.endswith(SUFFIXES):
                    yield os.path.join(directory, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser.add_argument("--limit", type=int, default=80)
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    files = args.files or sorted(library_files(args.root))
    findings = 0
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        for line, length, first in long_functions(text, args.limit):
            shown = os.path.relpath(path, args.root) if not args.files else path
            print(f"{shown}:{line}: function body of {length} lines (limit {args.limit}): "
                  f"{first[:70]}")
            findings += 1
    if findings:
        print(f"{findings} function(s) over {args.limit} lines: split them, or say why above the "
              "function in a `// long:` comment")
        return 1
    print(f"function size: {len(files)} files, no body over {args.limit} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
