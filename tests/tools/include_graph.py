#!/usr/bin/env python3
"""The include graph between engine/src's folders, and its cycles.

Each folder (fit/optimise counts apart from fit/) is a node; an edge A -> B is a file in A
including "B/name.h". Prints one line per folder (what it includes, how many files), then every
cycle; exits 1 when there is one (a folder including one that depends on it).
Usage: include_graph.py [ENGINE_SRC] [--dot] [--allow A:B ...]
--allow A:B accepts a known cycle between folders A and B (printed, marked "allowed").
"""
import os
import re
import sys

args = sys.argv[1:]
allowed = {frozenset(args[i + 1].split(":")) for i, a in enumerate(args) if a == "--allow" and i + 1 < len(args)}
positional = [a for i, a in enumerate(args) if not a.startswith("--") and (i == 0 or args[i - 1] != "--allow")]
root = next(iter(positional), os.path.join(os.path.dirname(__file__), "..", "..", "engine", "src"))
include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
nodes = {}
edges = {}
for dirpath, _, files in os.walk(root):
    node = os.path.relpath(dirpath, root)
    for f in files:
        if not f.endswith((".h", ".cpp", ".inc")):
            continue
        nodes[node] = nodes.get(node, 0) + 1
        with open(os.path.join(dirpath, f), encoding="utf-8", errors="replace") as fh:
            for inc in include.findall(fh.read()):
                target = os.path.dirname(inc)
                if not target or target == node or not os.path.isdir(os.path.join(root, target)):
                    continue  # same folder, or not a folder of engine/src (svgmotion/ is the public API)
                edges.setdefault(node, set()).add(target)

# Tarjan's strongly connected components: a component of more than one folder is a cycle.
index, low, stack, on, sccs = {}, {}, [], set(), []
def visit(v):
    index[v] = low[v] = len(index)
    stack.append(v); on.add(v)
    for w in sorted(edges.get(v, ())):
        if w not in index:
            visit(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        scc = []
        while True:
            w = stack.pop(); on.discard(w); scc.append(w)
            if w == v: break
        if len(scc) > 1: sccs.append(sorted(scc))
sys.setrecursionlimit(10000)
for v in sorted(nodes):
    if v not in index and v != ".":
        visit(v)

if "--dot" in sys.argv:
    print("digraph includes {")
    for a in sorted(edges):
        for b in sorted(edges[a]):
            print(f'  "{a}" -> "{b}";')
    print("}")
else:
    for v in sorted(n for n in nodes if n != "."):
        print(f"{v:18} ({nodes[v]:2} files) -> {' '.join(sorted(edges.get(v, ()))) or '-'}")
failed = False
for scc in sccs:
    inner = [f"{a} -> {b}" for a in scc for b in sorted(edges.get(a, ())) if b in scc]
    ok = frozenset(scc) in allowed
    failed = failed or not ok
    print(("allowed cycle: " if ok else "cycle: ") + ", ".join(inner))
sys.exit(1 if failed else 0)
