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
    other than the known SOLVER_CORE_ALLOWED ones;
  - a file includes a header of a library layer (LAYERS) that its own layer
    is not built on. A file's layer is read from the folders' CMakeLists.txt
    (`target_sources(widestereo_LAYER ...` and `add_library(widestereo_LAYER
    ...`); a header's is its .cpp's, or, with none, the lowest layer of its
    folder's sources (UMBRELLAS: the umbrella headers'); a .cpp in no layer
    fails too;
  - a file of the core layer includes a library the core does not link
    (FORBIDDEN_IN_CORE: Ceres, LCM, Aravis, GLib, libsodium, JSON, CLI11,
    OpenCV's other modules), other than CORE_ALLOWED_EXTERNAL.
Prints the graph and the layers either way. Python 3 standard library only.
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

# The library's layers (common/CMakeLists.txt), lowest first, each with the
# layers it is built on: a file includes headers of its own layer and of
# those only. widestereo_cloud (cloud/) is on top of them all.
LAYERS = {
    "core": [],
    "calib": ["core"],
    "lcm": ["core"],
    "capture": ["core"],
    "runtime": ["core", "calib", "lcm", "capture"],
    "cloud": ["core", "calib", "lcm", "capture", "runtime"],
}

# Headers in a folder of no sources: the umbrella headers.
UMBRELLAS = {"widestereo/widestereo.h": "core", "widestereo/lcm.h": "lcm"}

# Include prefixes of libraries the core must not need (docs/library.md: it
# links Eigen, OpenCV's core, imgproc and calib3d, and yaml-cpp).
FORBIDDEN_IN_CORE = {
    "ceres/": "Ceres", "glog/": "glog", "lcm/": "LCM", "widestereo/": "an LCM message type",
    "arv": "Aravis", "glib": "GLib", "gio/": "GLib", "sodium": "libsodium", "nlohmann/": "JSON",
    "CLI/": "CLI11", "opencv2/imgcodecs": "OpenCV imgcodecs", "opencv2/aruco": "OpenCV aruco",
    "opencv2/features2d": "OpenCV features2d", "opencv2/video": "OpenCV video",
    "opencv2/highgui": "OpenCV highgui", "pcl/": "PCL",
}

# Ceres's Jet is header-only (the models' templated code, for the solver's
# automatic derivatives): the core includes it and links nothing of Ceres.
CORE_ALLOWED_EXTERNAL = ["ceres/jet.h"]

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


LAYER_SOURCES = re.compile(r"(?:target_sources|add_library)\(\s*widestereo_(\w+)([^)]*)\)")
LAYER_SOURCE = re.compile(r"\$\{CMAKE_CURRENT_SOURCE_DIR\}/([\w./-]+\.cpp)")


def file_layers(common, files, folders, layers, umbrellas):
    """{file relative to common: its layer} from the folders' CMakeLists.txt:
    a .cpp's from the target it is a source of; a header's from its .cpp,
    else the lowest layer of its folder's sources, else UMBRELLAS."""
    order = list(layers)
    of = {}
    for folder in os.listdir(common):
        lists = os.path.join(common, folder, "CMakeLists.txt")
        if not os.path.isfile(lists):
            continue
        with open(lists, encoding="utf-8") as f:
            text = re.sub(r"#[^\n]*", "", f.read())
        for layer, body in LAYER_SOURCES.findall(text):
            for source in LAYER_SOURCE.findall(body):
                of["%s/%s" % (folder, source)] = layer
    folder_layers = {}
    for rel, layer in of.items():
        folder_layers.setdefault(node_of(rel, folders), set()).add(layer)
    for rel in files:
        if rel in of or rel.endswith(".cpp") or rel.endswith(".in"):
            continue
        own = os.path.splitext(rel)[0] + ".cpp"
        if own in of:
            of[rel] = of[own]
        elif rel in umbrellas:
            of[rel] = umbrellas[rel]
        elif node_of(rel, folders) in folder_layers:
            of[rel] = min(folder_layers[node_of(rel, folders)], key=lambda l: order.index(l) if l in order else 0)
    return of


def check_layers(common, files, folders, layers, umbrellas, out):
    """The failures of the layer rules (see the module's doc)."""
    of = file_layers(common, files, folders, layers, umbrellas)
    if not of:
        return []
    failures = []
    counts = {}
    for layer in of.values():
        counts[layer] = counts.get(layer, 0) + 1
    out.write("layers (files): %s\n" % ", ".join("%s %d" % (l, counts.get(l, 0)) for l in layers))
    for rel in sorted(files):
        if rel.endswith(".cpp") and rel not in of:
            failures.append("%s is in no layer: add it to a target_sources(widestereo_LAYER ...)" % rel)
    for rel, layer in sorted(of.items()):
        if layer not in layers:
            failures.append("%s is in widestereo_%s, no layer of LAYERS" % (rel, layer))
            continue
        below = set(layers[layer]) | {layer}
        for include, quoted in files.get(rel, []):
            if quoted and include in files:
                there = of.get(include)
                if there is not None and there not in below:
                    failures.append("%s (%s) includes %s (%s): the %s layer is not built on %s"
                                    % (rel, layer, include, there, layer, there))
            elif layer == "core" and include not in CORE_ALLOWED_EXTERNAL:
                for prefix, what in FORBIDDEN_IN_CORE.items():
                    if include.startswith(prefix):
                        failures.append("the core's %s includes <%s> (%s), which the core does not link"
                                        % (rel, include, what))
    return failures


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


def check(common, allowed_edges, solver_core, solver_allowed, out, layers=LAYERS, umbrellas=UMBRELLAS):
    files = read_includes(common)
    folders = node_folders(common)
    graph = folder_graph(files, folders)
    failures = check_layers(common, files, folders, layers, umbrellas, out)

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
    # Layers from the folders' CMakeLists.txt: low/ in the core, up/ in calib
    # (Ceres), msg/ in lcm.
    def sources(layer, *names):
        return "target_sources(widestereo_%s PRIVATE\n%s)\n" % (
            layer, "\n".join("  ${CMAKE_CURRENT_SOURCE_DIR}/%s" % n for n in names))
    layer_ok = {
        "low/CMakeLists.txt": sources("core", "m.cpp"),
        "low/m.h": "#include <Eigen/Core>\n", "low/m.cpp": '#include "low/m.h"\n#include <ceres/jet.h>\n',
        "low/only.h": '#include "low/m.h"\n',
        "up/CMakeLists.txt": "# target_sources(widestereo_core ${CMAKE_CURRENT_SOURCE_DIR}/s.cpp)\n" + sources("calib", "s.cpp"),
        "up/s.h": '#include "low/only.h"\n', "up/s.cpp": '#include "up/s.h"\n#include <ceres/ceres.h>\n',
        "msg/CMakeLists.txt": sources("lcm", "c.cpp"),
        "msg/c.h": '#include "low/m.h"\n#include "widestereo/image_t.hpp"\n', "msg/c.cpp": '#include "msg/c.h"\n',
    }
    cases += [
        ("layers from the CMakeLists pass", layer_ok, [], [], True),
        ("a core file including a higher layer's header fails",
         dict(layer_ok, **{"low/m.cpp": '#include "up/s.h"\n'}), [], [], False),
        ("a core header of no .cpp including a higher layer's fails",
         dict(layer_ok, **{"low/only.h": '#include "msg/c.h"\n'}), [], [], False),
        ("a layer including a sibling layer's header fails",
         dict(layer_ok, **{"msg/c.cpp": '#include "up/s.h"\n'}), [], [], False),
        ("the core including Ceres's solver fails",
         dict(layer_ok, **{"low/m.cpp": "#include <ceres/ceres.h>\n"}), [], [], False),
        ("the core including LCM fails",
         dict(layer_ok, **{"low/m.h": "#include <lcm/lcm-cpp.hpp>\n"}), [], [], False),
        ("the core including Aravis fails",
         dict(layer_ok, **{"low/m.cpp": "#include <arv.h>\n"}), [], [], False),
        ("a .cpp in no layer fails",
         dict(layer_ok, **{"low/stray.cpp": '#include "low/m.h"\n'}), [], [], False),
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
