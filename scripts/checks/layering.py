#!/usr/bin/env python3
"""Fails on an include cycle between the folders of src/, or on a src/ file that reaches MPI.

Each folder of src/ is one concept; a folder may use another only if that one does not use it back,
directly or through others. Usage: layering.py [SRC_DIR]; prints every cycle and exits 1 if any.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def folder_of(path, src):
    rel = os.path.relpath(path, src)
    return rel.split(os.sep)[0] if os.sep in rel else "."


def edges_and_problems(src):
    edges, problems = {}, []
    folders = {d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d))}
    for root, _, files in os.walk(src):
        for name in files:
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(root, name)
            here = folder_of(path, src)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for kind, target in INCLUDE.findall(text):
                if target == "mpi.h" or target.startswith("mpi/"):
                    problems.append(f"{os.path.relpath(path, src)} includes {target}: src/ knows nothing of MPI")
                    continue
                if kind != '"' or "/" not in target:
                    continue  # a system header, or one of this folder
                there = target.split("/")[0]
                if there in folders and there != here:
                    edges.setdefault(here, {}).setdefault(there, []).append(f"{os.path.relpath(path, src)} -> {target}")
    return edges, problems


def cycles(edges):
    """Strongly connected components with more than one folder (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "src")
    edges, problems = edges_and_problems(src)
    for component in cycles(edges):
        members = set(component)
        lines = [f"  {e}" for a in component for b, why in sorted(edges[a].items()) if b in members for e in why[:3]]
        problems.append("include cycle between " + ", ".join(component) + ":\n" + "\n".join(lines))
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
