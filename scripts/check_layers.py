#!/usr/bin/env python3
"""The include graph between the folders of common/, checked.

    scripts/check_layers.py [COMMON_DIR]     (default: common/ beside scripts/)
    scripts/check_layers.py --self-test

A folder A includes folder B when a file of common/A/ has `#include "B/..."`.
Fails (exit 1), saying which files make each edge, when
  - the folders form a cycle once the edges of ALLOWED_EDGES are left out
    (each closes a loop known today; the goal is an empty list);
  - an allowed edge no longer exists or closes no loop (take it off
    ALLOWED_EDGES);
  - a file of the solver core (SOLVER_CORE) includes, directly or through
    other headers of common/, an LCM header or a file-format header
    (FORBIDDEN_IN_SOLVER), other than the known SOLVER_CORE_ALLOWED ones.
Prints the graph either way. Python 3 standard library only.
"""
import os
import re
import sys
import tempfile

# The edges that close today's folder loops, each pointing the wrong way (a
# lower layer including a higher one); the goal is an empty list.
ALLOWED_EDGES = [
    ("rectify", "calib"),    # rectify/stereo_rig.cpp reads calib_file: calib <-> rectify
    ("calib", "interop"),    # calib/projection_diff.h: calib <-> interop
    ("lcm_io", "detect"),    # lcm_io/validate.cpp: detect -> lcm_io -> detect
    ("sim", "calib"),        # sim/truth_calibration.h writes calibration files: sim -> calib -> source -> sim
]

# The solver core: the problem and its blocks, residuals, covariance and
# outliers (calib/; its own folder once calib is layered).
SOLVER_CORE = [
    "calib/problem.h", "calib/problem.cpp", "calib/residuals.h",
    "calib/camera_block.h", "calib/camera_block.cpp",
    "calib/covariance.h", "calib/covariance.cpp",
    "calib/outliers.h", "calib/outliers.cpp",
]

# Include prefixes the solver core must not reach: LCM (the library, the
# generated message types, the codecs) and file formats.
FORBIDDEN_IN_SOLVER = {
    "lcm/": "LCM", "widestereo/": "an LCM message type", "lcm_io/": "LCM codecs",
    "yaml-cpp/": "YAML", "nlohmann/": "JSON", "runtime/opencv_yaml.h": "YAML files",
    "runtime/yaml_config.h": "YAML files", "runtime/atomic_file.h": "file writing",
    "calib/calib_file.h": "the calibration file", "calib/report.h": "the JSON report",
    "calib/corner_import.h": "corner files", "calib/corner_export.h": "corner files",
    "interop/": "other tools' files", "opencv2/core/persistence.hpp": "cv::FileStorage",
}

# (solver core file, forbidden include) pairs known today, to be removed.
SOLVER_CORE_ALLOWED = [  # through calib/calib_data.h, the solver's input
    ("calib/problem.h", "widestereo/stereo_corners_t.hpp"),
    ("calib/problem.cpp", "widestereo/stereo_corners_t.hpp"),
    ("calib/outliers.h", "widestereo/stereo_corners_t.hpp"),
    ("calib/outliers.cpp", "widestereo/stereo_corners_t.hpp"),
]

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


def folder_graph(files, folders):
    """{folder: {included folder: [files that include it]}}."""
    graph = {folder: {} for folder in folders}
    for rel, includes in files.items():
        here = rel.split("/")[0]
        if here not in folders:
            continue
        for include, quoted in includes:
            there = include.split("/")[0]
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
    folders = sorted(d for d in os.listdir(common) if os.path.isdir(os.path.join(common, d)))
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

    out.write("solver core (%d files):\n" % len(solver_core))
    for rel in solver_core:
        if rel not in files:
            failures.append("solver core file %s does not exist: update SOLVER_CORE" % rel)
            continue
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
    cases = [
        ("a clean tree passes", clean, [], True),
        ("a new cycle fails", looped, [], False),
        ("an allowed edge passes", looped, [("b", "a")], True),
        ("a stale allowance fails", clean, [("b", "a")], False),
        ("an allowance closing no loop fails", clean, [("a", "b")], False),
        ("the core reaching LCM through a header fails", lcm, [], False),
    ]
    ok = True
    for name, files, allowed, expect in cases:
        got = check(tree(files), allowed, ["core/p.h"], [], io.StringIO())
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
