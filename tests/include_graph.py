#!/usr/bin/env python3
"""includes.acyclic: no file under the texfilter include folder reaches itself through its #include lines.

usage: include_graph.py INCLUDE_FOLDER   (shaders/texfilter)

Every `#include "NAME"` line counts, whatever #if surrounds it: an include guard stops a second inclusion in
glslang, but Slang's preprocessor refuses a file that is already being included ("cyclic include"). A name
resolves against the including file's folder first, then INCLUDE_FOLDER's parent (-I shaders), as the
compilers resolve it. Prints the cycle and exits 1 if there is one. Standard library only.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def resolve(name, including, root):
    for base in (including.parent, root.parent):
        candidate = (base / name).resolve()
        if candidate.is_file():
            return candidate
    return None


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1]).resolve()
    files = sorted(root.rglob("*.glsl"))
    if not files:
        print(f"FAIL  no .glsl files under {root}")
        return 1
    edges = {}
    for f in files:
        edges[f] = []
        for name in INCLUDE.findall(f.read_text()):
            target = resolve(name, f, root)
            if target is None:
                print(f"FAIL  {f.relative_to(root)}: #include \"{name}\" names no file")
                return 1
            edges[f].append(target)
    done, stack = set(), []

    def visit(f):  # depth first; a file on the stack reached again is a cycle
        if f in stack:
            cycle = stack[stack.index(f):] + [f]
            print("FAIL  cyclic include: " + " -> ".join(str(c.relative_to(root)) for c in cycle))
            return False
        if f in done:
            return True
        stack.append(f)
        ok = all(visit(t) for t in edges[f])
        stack.pop()
        done.add(f)
        return ok

    if not all(visit(f) for f in files):
        return 1
    print(f"ok    {len(files)} files, {sum(len(e) for e in edges.values())} #include lines, no cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
