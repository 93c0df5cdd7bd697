#!/usr/bin/env python3
"""Fails when a motoflex library file includes a header of a module on its own or a higher layer.

The layers live in cmake/module_layers.txt (`level module folder...`). Every C++ file under the
folders listed there belongs to that module; an #include of "motoflex/<module>/..." (or
"motoflex_es/...", the es module) is allowed only into the same module or a lower layer. A quoted
include that climbs out of its folder ("../sim/x.hpp") is refused too: a private header is private
to its module. Prints one line per violation, `file:line: includes <header> (module a, layer 4)
from module b (layer 2)`, and exits 1; exits 0 with a one-line summary otherwise.
Usage: scripts/check_layers.py [--root DIR]
"""
import argparse
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".cc", ".inc")


def read_layers(root):
    """[(level, module, [folders])] from cmake/module_layers.txt."""
    layers = []
    with open(os.path.join(root, "cmake", "module_layers.txt"), encoding="utf-8") as f:
        for line in f:
            fields = line.split("#", 1)[0].split()
            if len(fields) >= 3 and fields[0].isdigit():
                layers.append((int(fields[0]), fields[1], fields[2:]))
    return layers


def module_of_header(header, by_include_prefix):
    """The module a `motoflex/...` or `motoflex_es/...` include belongs to, or None."""
    if header.startswith("motoflex_es/"):
        return "es"
    best = None
    for prefix, module in by_include_prefix.items():
        if header.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, module)
    return best[1] if best else None


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    root = parser.parse_args().root

    layers = read_layers(root)
    level = {module: lvl for lvl, module, _ in layers}
    folder_module = []  # (folder, module), longest folders first
    by_include_prefix = {}
    for _, module, folders in layers:
        for folder in folders:
            folder_module.append((folder.rstrip("/") + "/", module))
            if folder.startswith("include/"):
                by_include_prefix[folder[len("include/"):].rstrip("/") + "/"] = module
    folder_module.sort(key=lambda fm: -len(fm[0]))

    violations = []
    files = 0
    for folder, module in folder_module:
        base = os.path.join(root, folder)
        if not os.path.isdir(base):
            continue
        for dirpath, _, names in os.walk(base):
            for name in sorted(names):
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root).replace(os.sep, "/")
                # A file belongs to the most specific folder that holds it.
                owner = next(m for f, m in folder_module if rel.startswith(f))
                if owner != module:
                    continue
                files += 1
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        header = match.group(1)
                        if header.startswith("../"):
                            violations.append(f"{rel}:{number}: includes {header}: a relative "
                                              f"include leaves module {module}'s folder")
                            continue
                        target = module_of_header(header, by_include_prefix)
                        if target is None or target == module:
                            continue
                        if level[target] >= level[module]:
                            violations.append(
                                f"{rel}:{number}: includes {header} (module {target}, layer "
                                f"{level[target]}) from module {module} (layer {level[module]})")
    for v in violations:
        print(v)
    if violations:
        print(f"check_layers: {len(violations)} include(s) against cmake/module_layers.txt")
        return 1
    print(f"check_layers: {files} files, every include goes to the same or a lower layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())
