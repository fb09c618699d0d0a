#!/usr/bin/env python3
"""The include graph between the folders of common/, checked.

    scripts/check_layers.py [COMMON_DIR]     (default: common/ beside scripts/)
    scripts/check_layers.py --self-test

A folder A includes folder B when a file of common/A/ has `#include "B/..."`.
A folder's sub-folders are nodes of the graph too: common/calib/solver/ is
"calib/solver", apart from "calib" (the files of calib/ itself), so the
layers of calib (solver < start < evaluate < calib < node) are checked like
the folders.
Fails (exit 1), saying which files make each edge, when
  - the folders form a cycle once the edges of ALLOWED_EDGES are left out
    (each closes a loop known today; the goal is an empty list);
  - an allowed edge no longer exists or closes no loop (take it off
    ALLOWED_EDGES);
  - a file of the solver core (SOLVER_CORE: files, or every file of a
    folder given as "folder/") includes, directly or through other headers
    of common/, an LCM header or a file-format header (FORBIDDEN_IN_SOLVER),
    other than the known SOLVER_CORE_ALLOWED ones.
Prints the graph either way. Python 3 standard library only.
"""
import os
import re
import sys
import tempfile

# The edges that close today's folder loops, each pointing the wrong way (a
# lower layer including a higher one); the goal is an empty list.
ALLOWED_EDGES = []

# The solver core: every file of calib/solver/ (the problem and its blocks,
# residuals, priors, covariance, outliers, the data it works on, its
# settings).
SOLVER_CORE = ["calib/solver/"]

# Include prefixes the solver core must not reach: LCM (the library, the
# generated message types, the codecs) and file formats.
FORBIDDEN_IN_SOLVER = {
    "lcm/": "LCM", "widestereo/": "an LCM message type", "lcm_io/": "LCM codecs",
    "yaml-cpp/": "YAML", "nlohmann/": "JSON", "runtime/opencv_yaml.h": "YAML files",
    "runtime/yaml_config.h": "YAML files", "runtime/atomic_file.h": "file writing",
    "rig/rig_file.h": "the calibration file", "rig/rig_message.h": "LCM codecs",
    "runtime/json_file.h": "JSON files", "calib/node/": "the calibration node (LCM, files)",
    "interop/": "other tools' files", "opencv2/core/persistence.hpp": "cv::FileStorage",
    "opencv2/imgcodecs.hpp": "image files", "fstream": "file I/O", "filesystem": "files",
}

# (solver core file, forbidden include) pairs known today, to be removed;
# the goal is an empty list.
SOLVER_CORE_ALLOWED = []

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
SOURCE_ENDINGS = (".h", ".hpp", ".cpp", ".cc", ".in")


def read_includes(common):
    """{file relative to common: [(include, quoted)]} for every source file."""
    files = {}
    for root, _, names in os.walk(common):
        for name in sorted(names):
            if not name.endswith(SOURCE_ENDINGS):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, common).replace(os.sep, "/")
            with open(path, encoding="utf-8", errors="replace") as f:
                files[rel] = [(m.group(2), m.group(1) == '"') for m in INCLUDE.finditer(f.read())]
    return files


def node_folders(common):
    """The nodes of the graph: the folders of common/ and their sub-folders."""
    folders = []
    for d in sorted(os.listdir(common)):
        if os.path.isdir(os.path.join(common, d)):
            folders.append(d)
            folders += ["%s/%s" % (d, sub) for sub in sorted(os.listdir(os.path.join(common, d)))
                        if os.path.isdir(os.path.join(common, d, sub))]
    return folders


def node_of(rel, folders):
    """The folder node a path relative to common/ belongs to: its sub-folder
    ("calib/solver/problem.h": "calib/solver") or else its folder."""
    parts = rel.split("/")
    if len(parts) > 2 and "/".join(parts[:2]) in folders:
        return "/".join(parts[:2])
    return parts[0]


def folder_graph(files, folders):
    """{folder: {included folder: [files that include it]}}."""
    graph = {folder: {} for folder in folders}
    for rel, includes in files.items():
        here = node_of(rel, folders)
        if here not in folders:
            continue
        for include, quoted in includes:
            there = node_of(include, folders)
            # Only headers of common/: "widestereo/image_t.hpp" is a generated
            # LCM type, not common/widestereo/.
            if quoted and include in files and there in folders and there != here:
                graph[here].setdefault(there, []).append(rel)
    return graph


def strongly_connected(graph):
    """Tarjan's algorithm: the groups of two or more folders that reach each other."""
    index, low, stack, on_stack, groups = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = set()
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.add(w)
                if w == v:
                    break
            if len(group) > 1:
                groups.append(group)

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return groups


def path(graph, start, goal):
    """A shortest path of folders from start to goal, or None."""
    came_from, todo = {start: None}, [start]
    while todo:
        v = todo.pop(0)
        if v == goal:
            walk = []
            while v is not None:
                walk.append(v)
                v = came_from[v]
            return walk[::-1]
        for w in sorted(graph[v]):
            if w not in came_from:
                came_from[w] = v
                todo.append(w)
    return None


def reached_includes(files, start):
    """Every include reached from `start` through the quoted headers of common/."""
    seen, todo, reached = {start}, [start], set()
    while todo:
        for include, quoted in files.get(todo.pop(), []):
            reached.add(include)
            if quoted and include in files and include not in seen:
                seen.add(include)
                todo.append(include)
    return reached


def check(common, allowed_edges, solver_core, solver_allowed, out):
    files = read_includes(common)
    folders = node_folders(common)
    graph = folder_graph(files, folders)
    failures = []

    out.write("folder include graph of %s:\n" % common)
    width = max(map(len, folders), default=0)
    for folder in folders:
        if graph[folder]:
            out.write("  %-*s -> %s\n" % (width, folder, ", ".join(sorted(graph[folder]))))

    layered = {a: {b: who for b, who in edges.items() if (a, b) not in allowed_edges}
               for a, edges in graph.items()}
    loops = []
    for a, b in allowed_edges:
        if b not in graph.get(a, {}):
            failures.append("the allowed edge %s -> %s is gone: take it off ALLOWED_EDGES in %s"
                            % (a, b, os.path.basename(__file__)))
            continue
        back = path(layered, b, a)
        loops.append((a, b, [a] + back if back else None))
        if not back:
            failures.append("the allowed edge %s -> %s closes no loop: take it off ALLOWED_EDGES in %s"
                            % (a, b, os.path.basename(__file__)))
    out.write("allowed edges, to be removed: %d\n" % len(loops))
    for a, b, loop in loops:
        out.write("  %s -> %s (%s): %s\n" % (a, b, ", ".join(sorted(set(graph[a][b]))),
                                             "closes " + " -> ".join(loop) if loop else "closes no loop"))
    groups = strongly_connected(layered)
    out.write("cycles without them: %d\n" % len(groups))
    for group in groups:
        out.write("  %s\n" % " <-> ".join(sorted(group)))
        for a in sorted(group):
            for b in sorted(set(layered[a]) & group):
                out.write("    %s -> %s: %s\n" % (a, b, ", ".join(sorted(set(layered[a][b])))))
        failures.append("a folder cycle: " + " <-> ".join(sorted(group)))

    core = []
    for entry in solver_core:
        if entry.endswith("/"):
            found = sorted(rel for rel in files if rel.startswith(entry))
            if not found:
                failures.append("the solver core folder %s has no files: update SOLVER_CORE" % entry)
            core += found
        elif entry not in files:
            failures.append("solver core file %s does not exist: update SOLVER_CORE" % entry)
        else:
            core.append(entry)
    out.write("solver core (%d files: %s):\n" % (len(core), ", ".join(solver_core)))
    for rel in core:
        for include in sorted(reached_includes(files, rel)):
            for prefix, what in FORBIDDEN_IN_SOLVER.items():
                if include.startswith(prefix):
                    known = (rel, include) in solver_allowed
                    out.write("  %s reaches %s (%s)%s\n" % (rel, include, what,
                                                           ", allowed, to be removed" if known else ""))
                    if not known:
                        failures.append("the solver core's %s reaches %s (%s)" % (rel, include, what))
    for rel, include in solver_allowed:
        if rel in files and include not in reached_includes(files, rel):
            failures.append("%s no longer reaches %s: take it off SOLVER_CORE_ALLOWED" % (rel, include))

    for failure in failures:
        out.write("FAIL: %s\n" % failure)
    out.write("%s\n" % ("FAILED" if failures else "OK"))
    return not failures


def self_test():
    """The check fails on a new cycle, a forbidden include and a stale allowance."""
    import io

    def tree(files):
        root = tempfile.mkdtemp(prefix="check-layers-")
        for rel, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        return root

    clean = {"a/x.h": '#include "b/y.h"\n', "b/y.h": "#include <vector>\n", "core/p.h": '#include "b/y.h"\n'}
    looped = dict(clean, **{"b/y.h": '#include "a/x.h"\n'})
    lcm = dict(clean, **{"b/y.h": '#include "widestereo/frame_t.hpp"\n'})
    # Sub-folders are nodes: a/low/ < a/high/ < a/ (its own files).
    layered = dict(clean, **{"a/low/l.h": "#include <vector>\n", "a/high/h.h": '#include "a/low/l.h"\n',
                             "a/z.h": '#include "a/high/h.h"\n'})
    sub_looped = dict(layered, **{"a/low/l.h": '#include "a/high/h.h"\n'})
    parent_looped = dict(layered, **{"a/low/l.h": '#include "a/z.h"\n'})
    core_folder = dict(layered, **{"core/p.h": '#include "a/low/l.h"\n', "core/q.cpp": '#include "core/p.h"\n'})
    core_lcm = dict(core_folder, **{"core/q.cpp": '#include "core/p.h"\n#include <lcm/lcm-cpp.hpp>\n'})
    core_file = dict(core_folder, **{"a/low/l.h": "#include <fstream>\n"})
    cases = [
        ("a clean tree passes", clean, [], ["core/p.h"], True),
        ("a new cycle fails", looped, [], ["core/p.h"], False),
        ("an allowed edge passes", looped, [("b", "a")], ["core/p.h"], True),
        ("a stale allowance fails", clean, [("b", "a")], ["core/p.h"], False),
        ("an allowance closing no loop fails", clean, [("a", "b")], ["core/p.h"], False),
        ("the core reaching LCM through a header fails", lcm, [], ["core/p.h"], False),
        ("sub-folders in layers pass", layered, [], ["core/p.h"], True),
        ("a cycle between sub-folders fails", sub_looped, [], ["core/p.h"], False),
        ("a cycle between a sub-folder and its folder fails", parent_looped, [], ["core/p.h"], False),
        ("a core folder of clean files passes", core_folder, [], ["core/"], True),
        ("a core folder's other file including LCM fails", core_lcm, [], ["core/"], False),
        ("a core folder reaching file I/O through a sub-folder fails", core_file, [], ["core/"], False),
        ("an empty core folder fails", clean, [], ["nowhere/"], False),
    ]
    ok = True
    for name, files, allowed, core, expect in cases:
        got = check(tree(files), allowed, core, [], io.StringIO())
        print("%s: %s" % (name, "ok" if got == expect else "WRONG"))
        ok &= got == expect
    return ok


def main(argv):
    if argv[1:] == ["--self-test"]:
        return 0 if self_test() else 1
    if len(argv) > 2 or argv[1:2] in (["-h"], ["--help"]):
        print(__doc__)
        return 0 if argv[1:2] in (["-h"], ["--help"]) else 2
    common = argv[1] if len(argv) == 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common")
    if not os.path.isdir(common):
        print("check_layers: %s is not a folder (give the common/ folder)" % common)
        return 2
    return 0 if check(os.path.normpath(common), ALLOWED_EDGES, SOLVER_CORE, SOLVER_CORE_ALLOWED, sys.stdout) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
