#!/usr/bin/env python3
"""Checks the include graph of the sources (docs/design.md "Layers"):

- no include loop: a header and its source count as one unit, and no chain
  of includes between units leads back to where it started;
- layers point one way: ecs/ includes none of systems/, render/, game/;
  systems/ none of render/, game/; render/ none of game/; the public
  headers (include/snow/) none of them at all.

Prints each violation and exits 1; exits 0 with a one-line summary.
Usage: check_includes.py [source root] (default: this script's parent's parent).
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), ".."))
FOLDERS = ["include", "ecs", "systems", "render", "game"]
LAYER = {"ecs": 0, "systems": 1, "render": 2, "game": 3}
INCLUDE = re.compile(r'^\s*#\s*include\s+(?:"([^"]+)"|<(snow/[^>]+)>)', re.M)


def sources():
    for folder in FOLDERS:
        for dirpath, _, files in os.walk(os.path.join(ROOT, folder)):
            for f in files:
                if f.endswith((".hpp", ".cpp", ".h", ".c")):
                    yield os.path.relpath(os.path.join(dirpath, f), ROOT)


def target(path, name):
    """The repository path an include names, or None for a generated or outside one."""
    quoted, snow = name
    if snow:
        return "include/" + snow
    for base in (ROOT, os.path.join(ROOT, os.path.dirname(path))):
        candidate = os.path.relpath(os.path.join(base, quoted), ROOT)
        if os.path.isfile(os.path.join(ROOT, candidate)):
            return candidate
    return None


def unit(path):
    return os.path.splitext(path)[0]


def main():
    edges = {}
    problems = []
    files = sorted(sources())
    for path in files:
        text = open(os.path.join(ROOT, path), encoding="utf-8").read()
        top = path.split("/")[0]
        for m in INCLUDE.finditer(text):
            to = target(path, m.groups())
            if to is None:
                continue
            to_top = to.split("/")[0]
            if top == "include" and to_top != "include":
                problems.append(f"{path}: a public header includes the internal {to}")
            if top in LAYER and to_top in LAYER and LAYER[to_top] > LAYER[top]:
                problems.append(f"{path}: {top}/ reaches up into {to}")
            if unit(to) != unit(path):
                edges.setdefault(unit(path), set()).add(unit(to))

    # Tarjan's strongly connected components: any with more than one unit is a loop.
    index, low, on_stack, stack, loops = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                loops.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    for loop in loops:
        problems.append("include loop through: " + ", ".join(loop))
    for p in problems:
        print(p)
    if problems:
        return 1
    print(f"check_includes: {len(files)} files, {len(edges)} units: no include loop, "
          "layers point one way")
    return 0


if __name__ == "__main__":
    sys.exit(main())
