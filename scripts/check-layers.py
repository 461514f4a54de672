#!/usr/bin/python3
"""The layers of the source tree and the includes between them.

docs/layers.txt declares every source folder of models/, platform/ and sw/,
bottom to top, grouped in named layers. A file may include a file of its own
folder or of a folder listed before its own; any other include of the
project runs up (or sideways past the order) and is reported as FILE:LINE.

  scripts/check-layers.py [--root DIR] [--table FILE]   check (exit 1 on an up-arrow)
  scripts/check-layers.py --graph                        the include graph's arrows, counted
  scripts/check-layers.py --dot | dot -Tpng -o FILE      the layers and the includes between them
  scripts/check-layers.py --self-test                    the check on made-up trees
"""
import argparse
import collections
import os
import re
import sys
import tempfile

TOPS = ("models", "platform", "sw")
SOURCES = (".h", ".cpp", ".in")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def read_table(path):
    """[(layer, [folder, ...])] bottom to top, and folder -> rank."""
    layers, rank, lines = [], {}, {}
    with open(path) as table:
        for number, text in enumerate(table, 1):
            line = text.split("#", 1)[0].strip()
            if not line:
                continue
            if ":" in line:
                name, folders = line.split(":", 1)
                layers.append((name.strip(), []))
            elif text[0].isspace() and layers:  # an indented line goes on with the layer above
                folders = line
            else:
                raise SystemExit(f"{path}:{number}: expected 'LAYER: FOLDER ...', got '{line}'")
            for folder in folders.split():
                if folder in rank:
                    raise SystemExit(f"{path}:{number}: {folder} is listed twice")
                rank[folder] = len(rank)
                lines[folder] = number
                layers[-1][1].append(folder)
    return layers, rank, lines


def sources(root):
    for top in TOPS:
        for directory, subdirs, files in os.walk(os.path.join(root, top)):
            subdirs.sort()
            for name in sorted(files):
                if name.endswith(SOURCES):
                    yield os.path.relpath(os.path.join(directory, name), root).replace(os.sep, "/")


def includes(root, path):
    with open(os.path.join(root, path), errors="replace") as source:
        for number, line in enumerate(source, 1):
            match = INCLUDE.match(line)
            if match and match.group(1).split("/", 1)[0] in TOPS:
                yield number, match.group(1)


def folder(path):
    return path.rsplit("/", 1)[0] if "/" in path else "."


def check(root, table):
    """The problems found, one line each."""
    layers, rank, lines = read_table(table)
    layer_of = {f: name for name, folders in layers for f in folders}
    problems = []
    seen = set()
    for path in sources(root):
        here = folder(path)
        seen.add(here)
        if here not in rank:
            problems.append(f"{path}:1: folder {here} is in no layer of {table}")
            continue
        for number, target in includes(root, path):
            there = folder(target)
            if there == here:
                continue
            if there not in rank:
                problems.append(f"{path}:{number}: includes {target}, whose folder {there} is in no layer")
            elif rank[there] > rank[here]:
                problems.append(f"{path}:{number}: includes {target}: {there} ({layer_of[there]}) "
                                f"sits above {here} ({layer_of[here]})")
    for listed in sorted(set(rank) - seen, key=rank.get):
        problems.append(f"{table}:{lines[listed]}: {listed} holds no sources")
    return problems


def graph(root, table=None):
    tops, folders = collections.Counter(), collections.Counter()
    for path in sources(root):
        for _, target in includes(root, path):
            if folder(target) != folder(path):
                folders[(folder(path), folder(target))] += 1
            if target.split("/")[0] != path.split("/")[0]:
                tops[(path.split("/")[0], target.split("/")[0])] += 1
    lines = ["top-level arrows (includes):"]
    lines += [f"  {a} -> {b}: {n}" for (a, b), n in sorted(tops.items())]
    lines.append("folder arrows (includes):")
    lines += [f"  {a} -> {b}: {n}" for (a, b), n in sorted(folders.items())]
    return lines


def dot(root, table):
    """Graphviz text: one box a layer (its folders inside), bottom to top, and an arrow from each
    layer to each layer it includes, labelled with the count of includes: every arrow points down."""
    layers, rank, _ = read_table(table)
    layer_of = {f: name for name, folders in layers for f in folders}
    arrows = collections.Counter()
    for path in sources(root):
        for _, target in includes(root, path):
            a, b = layer_of.get(folder(path)), layer_of.get(folder(target))
            if a and b and a != b:
                arrows[(a, b)] += 1
    lines = ["digraph layers {",
             '  rankdir=BT; nodesep=0.25; ranksep=0.35;',
             '  label="the layers, bottom to top; an arrow: the includes from one layer into one below it";',
             '  labelloc=t; fontname="Helvetica"; fontsize=12;',
             '  node [shape=box, style="rounded,filled", fillcolor="#eef3fb", fontname="Helvetica", fontsize=11];',
             '  edge [color="#7f8c9d", arrowsize=0.6, fontname="Helvetica", fontsize=9, fontcolor="#56606b"];']
    for name, folders in layers:
        rows = []
        for f in folders:  # three folders a line keeps the boxes narrow
            if not rows or len(rows[-1]) == 3:
                rows.append([])
            rows[-1].append(f)
        label = "\\n".join("  ".join(row) for row in rows)
        lines.append(f'  "{name}" [label="{name}\\n{label}"];')
    order = [name for name, _ in layers]
    for below, above in zip(order, order[1:]):  # the stack itself, bottom to top
        lines.append(f'  "{below}" -> "{above}" [style=invis, weight=10];')
    for (a, b), n in sorted(arrows.items(), key=lambda x: (order.index(x[0][0]), order.index(x[0][1]))):
        lines.append(f'  "{a}" -> "{b}" [label="{n}", constraint=false];')
    lines.append("}")
    return lines


def self_test():
    """The check passes a tree that keeps the order and names each include that breaks it."""
    table_text = ("# a comment\nbase: models/common\nblocks: models/a\n        models/b  # goes on\n"
                  "top: platform sw/cli\n")
    good = {
        "models/common/c.h": "",
        "models/a/a.h": '#include "models/common/c.h"\n',
        "models/b/b.h": '#include "models/a/a.h"\n#include <vector>\n',
        "platform/p.cpp": '#include "platform/p.h"\n#include "models/b/b.h"\n',
        "platform/p.h": "",
        "sw/cli/main.cpp": '#include "platform/p.h"\n  #  include "models/common/c.h"\n',
    }
    bad = dict(good)
    bad["models/a/a.h"] = '#include "models/common/c.h"\n#include "models/b/b.h"\n'  # sideways, up the order
    bad["models/common/c.h"] = '// base\n#include "platform/p.h"\n'                  # up two layers
    bad["models/x/x.h"] = ""                                                          # a folder in no layer
    bad["sw/cli/main.cpp"] = '#include "sw/nowhere/n.h"\n'                            # a folder in no layer
    del bad["platform/p.cpp"], bad["platform/p.h"]                                     # a layer left empty
    bad["models/b/b.h"] = '#include "platform/p.h"\n'                                 # up, to a folder gone
    expected = {"models/a/a.h:2:", "models/b/b.h:1:", "models/common/c.h:2:", "models/x/x.h:1:",
                "sw/cli/main.cpp:1:", "layers.txt:5:"}
    failures = []
    for name, tree, want in (("good", good, set()), ("bad", bad, expected)):
        with tempfile.TemporaryDirectory() as root:
            for path, text in tree.items():
                os.makedirs(os.path.join(root, folder(path)), exist_ok=True)
                with open(os.path.join(root, path), "w") as f:
                    f.write(text)
            table = os.path.join(root, "layers.txt")
            with open(table, "w") as f:
                f.write(table_text)
            found = {p.split(" ", 1)[0].replace(root + os.sep, "") for p in check(root, table)}
            if found != want:
                failures.append(f"{name} tree: expected {sorted(want)}, found {sorted(found)}")
    for failure in failures:
        print("self-test: " + failure, file=sys.stderr)
    print("self-test: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", default=os.path.dirname(here))
    parser.add_argument("--table", help="the layer table (default ROOT/docs/layers.txt)")
    parser.add_argument("--graph", action="store_true", help="print the include graph's arrows")
    parser.add_argument("--dot", action="store_true", help="print the layers as a Graphviz graph")
    parser.add_argument("--self-test", action="store_true", help="run the check on made-up trees")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    if args.graph:
        print("\n".join(graph(args.root)))
        return 0
    table = args.table or os.path.join(args.root, "docs", "layers.txt")
    if args.dot:
        print("\n".join(dot(args.root, table)))
        return 0
    problems = check(args.root, table)
    for problem in problems:
        print(problem)
    count = sum(1 for _ in sources(args.root))
    print(f"{len(problems)} problem(s) with the layers of {os.path.relpath(table, args.root)} "
          f"in {count} source files")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
