#!/usr/bin/env python3
"""The module graph of ARCHITECTURE.md, generated from CMake's own view of the targets.

Runs `cmake --graphviz` on the build tree, keeps motoflex's module libraries and the binary,
drops the edges implied by others (a module's link to a module two layers down through one in
between), and renders docs/module_graph.png with Graphviz's dot (layers from
cmake/module_layers.txt, lowest at the bottom).
Usage: scripts/module_graph.py [--build build] [--out docs/module_graph.png]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_layers():
    layers = {}
    with open(os.path.join(ROOT, "cmake", "module_layers.txt")) as f:
        for line in f:
            m = re.match(r"^(\d+)\s+(\w+)", line)
            if m:
                layers[m.group(2)] = int(m.group(1))
    return layers


def cmake_edges(build):
    with tempfile.TemporaryDirectory() as tmp:
        dot = os.path.join(tmp, "targets.dot")
        subprocess.run(["cmake", f"--graphviz={dot}", "."], cwd=build, check=True,
                       capture_output=True)
        text = open(dot).read()
    # Labels read "motoflex_fit\n(motoflex::fit)": the target name is the first line.
    names = {node: label.split("\\n")[0]
             for node, label in re.findall(r'"(node\d+)"\s*\[\s*label\s*=\s*"([^"]+)"', text)}
    edges = set()
    for a, b in re.findall(r'"(node\d+)"\s*->\s*"(node\d+)"', text):
        edges.add((names.get(a, a), names.get(b, b)))
    return edges


def module_of(target):
    if target == "motoflex":
        return "cli"
    if target.startswith("motoflex::"):
        target = "motoflex_" + target[len("motoflex::"):]
    return target[len("motoflex_"):] if target.startswith("motoflex_") else None


def reduce(edges):
    """Drops a → c when a → b → ... → c exists (the graph is a DAG)."""
    children = {}
    for a, b in edges:
        children.setdefault(a, set()).add(b)

    def reaches(start, goal, skip):
        stack = [n for n in children.get(start, ()) if (start, n) != skip]
        seen = set()
        while stack:
            n = stack.pop()
            if n == goal:
                return True
            if n not in seen:
                seen.add(n)
                stack.extend(children.get(n, ()))
        return False

    return {(a, b) for a, b in edges if not reaches(a, b, (a, b))}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "module_graph.png"))
    args = parser.parse_args()
    layers = read_layers()
    edges = set()
    for a, b in cmake_edges(args.build):
        ma, mb = module_of(a), module_of(b)
        if ma in layers and mb in layers and ma != mb:
            edges.add((ma, mb))
    edges = reduce(edges)
    modules = sorted({m for e in edges for m in e}, key=lambda m: (layers[m], m))
    lines = ["digraph motoflex {", "  rankdir=TB; node [shape=box, fontname=Helvetica];"]
    for level in sorted({layers[m] for m in modules}):
        same = " ".join(f'"{m}"' for m in modules if layers[m] == level)
        lines.append(f"  {{ rank=same; {same} }}")
    for a, b in sorted(edges):
        lines.append(f'  "{a}" -> "{b}";')
    lines.append("}")
    dot_text = "\n".join(lines) + "\n"
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(os.path.splitext(args.out)[0] + ".dot", "w") as f:
        f.write(dot_text)
    try:
        subprocess.run(["dot", "-Tpng", "-Gdpi=80", "-o", args.out], input=dot_text, text=True,
                       check=True)
    except (OSError, subprocess.CalledProcessError) as error:
        print(f"module_graph: warning: dot failed ({error}); wrote only the .dot", file=sys.stderr)
        return 0
    print(f"module_graph: {len(modules)} modules, {len(edges)} direct links -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
