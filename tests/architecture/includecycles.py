#!/usr/bin/env python3
"""No include cycle between folders (docs/architecture.md, "Folders and their dependencies").

Reads every #include "..." of the C++ sources under src/ and models/, resolves it to a file of the
repository (relative to the including file, to src/, or to the repository's root), and draws an edge
from the including file's folder to the included file's folder. A cycle between folders (document/
includes trace/, which includes document/) is reported with the include lines that make it, and the
exit code is 1. A folder is the first level below src/ or models/ (one library, or one part of the
models library); its subfolders belong to it. Includes of Qt, the standard library and other libraries (<...>) are not followed.

Usage: includecycles.py REPOSITORY_ROOT [--expect-cycle "FOLDER, FOLDER..."]
With --expect-cycle (the check's own test), the exit code is 0 only when exactly that cycle is found.
"""
import os
import re
import sys
from collections import defaultdict

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCES = (".h", ".hpp", ".cpp", ".cc")
TREES = ("src", "models")


def folder_of(path, root):
    """The folder of a file: the first level below src/ or models/ (src/geometry, models/document).
    A subfolder belongs to its folder (src/geometry/splines is part of the geometry library)."""
    parts = os.path.relpath(os.path.dirname(path), root).split(os.sep)
    return "/".join(parts[:2])


def resolve(name, including, root):
    for base in (os.path.dirname(including), os.path.join(root, "src"), root):
        candidate = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(candidate):
            return candidate
    return None


def edges_of(root):
    """folder -> folder -> [(file, line number, include)]: every include that crosses folders."""
    edges = defaultdict(lambda: defaultdict(list))
    for tree in TREES:
        for dirpath, _dirs, files in os.walk(os.path.join(root, tree)):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                path = os.path.join(dirpath, name)
                with open(path, encoding="utf-8", errors="replace") as source:
                    for number, line in enumerate(source, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        target = resolve(match.group(1), path, root)
                        if target is None:
                            continue  # generated (moc, ui) or outside the repository
                        a, b = folder_of(path, root), folder_of(target, root)
                        if a != b and not b.startswith(".."):
                            edges[a][b].append((os.path.relpath(path, root), number, match.group(1)))
    return edges


def strongly_connected(edges):
    """Tarjan's strongly connected components of the folder graph, iteratively."""
    nodes = sorted(set(edges) | {b for a in edges for b in edges[a]})
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    counter = 0
    for start in nodes:
        if start in index:
            continue
        work = [(start, iter(sorted(edges.get(start, {}))))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(edges.get(child, {})))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    components.append(sorted(component))
    return components


def main():
    args = sys.argv[1:]
    expected = None
    if len(args) == 3 and args[1] == "--expect-cycle":
        expected = args[2]
        args = args[:1]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = os.path.abspath(args[0])
    edges = edges_of(root)
    cycles = strongly_connected(edges)
    if expected is not None:
        found = [", ".join(component) for component in cycles]
        print("cycles found: " + ("; ".join(found) or "none"))
        return 0 if found == [expected] else 1
    crossing = sum(len(targets) for targets in edges.values())
    if not cycles:
        print(f"no include cycle between {len(set(edges) | {b for a in edges for b in edges[a]})} folders "
              f"({crossing} folder-to-folder dependencies)")
        return 0
    for component in cycles:
        print("include cycle between folders: " + ", ".join(component), file=sys.stderr)
        members = set(component)
        for a in component:
            for b in sorted(edges[a]):
                if b in members:
                    for path, number, name in edges[a][b]:
                        print(f"  {a} -> {b}: {path}:{number}: #include \"{name}\"", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
