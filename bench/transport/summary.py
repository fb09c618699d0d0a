#!/usr/bin/env python3
"""Summary of a bench/transport/run.sh run with ROUNDS > 1: for each
variant, each figure's median over the rounds and its range (lowest,
highest), from every round's bench_transport.out (and the pairs stereo-match
skipped for each reason, from its log), then each stage's median
and p99 per frame (the medians over the rounds); with --rounds, one
Markdown table row per round and variant instead, in the order they ran.

  bench/transport/summary.py [--rounds] RUN_DIR VARIANT...
"""
import glob
import os
import re
import statistics
import sys

# figure name -> pattern on bench_transport.out (first group: the value)
FIGURES = {
    "in: STEREO_IMAGES Hz": r"^  stereo-capture +STEREO_IMAGES +([\d.]+) Hz",
    "out: STEREO_CLOUD_FILTERED Hz": r"^  stereo-cloud +STEREO_CLOUD_FILTERED +([\d.]+) Hz",
    "clouds missing from the first on %": r"^clouds missing from the first on: \d+ of \d+ pairs \(([\d.]+) %\)",
    "  after the first quarter %": r"^clouds missing from the first on: .*; after the first \d+ s: \d+ of \d+ pairs \(([\d.]+) %\)",
    "latency median ms": r"^capture -> STEREO_CLOUD_FILTERED: \d+ clouds, latency median (\d+) ms",
    "latency p99 ms": r"^capture -> STEREO_CLOUD_FILTERED: .* p99 (\d+) ms",
    "  after the first quarter: p99 ms": r"^  after the first \d+ s: \d+ clouds, .* p99 (\d+) ms",
    "median / sum of the stages": r"^latency median / sum of the stage medians .*: ([\d.]+)",
    # the machine's speed in that round: stages whose work does not change
    "stereo-match match, median ms": r"^  stereo-match +match +([\d.]+) ",
    "stereo-cloud filter, median ms": r"^  stereo-cloud +filter +([\d.]+) ",
}
PROCESSES = ("stereo-match", "stereo-cloud", "stereo-view", "stereo-status")
# figure name -> a reason stereo-match skips a pair for, counted in its log's
# last line of counters (STEREO_IMAGES ... skipped N (REASON COUNT, ...))
SKIPS = {
    "pairs skipped: a newer pair": "a newer pair came while matching",
    "pairs skipped: filter busy": "the cloud filter had a cloud waiting",
    "pairs skipped: latency budget": "it would come later than the latency budget",
}
NAMES = list(FIGURES) + ["CPU %s %%" % p for p in PROCESSES] + list(SKIPS)  # every figure, in table order


BUDGET_ROW = re.compile(r"^  (\S+)\s+(.+?)\s+([\d.]+)\s+([\d.]+)\s+\d+$")


def budget(text):
    """(process, stage) -> (median ms, p99 ms) from the latency budget table."""
    table = text.split("latency budget", 1)[-1].split("capture -> STEREO_CLOUD_FILTERED", 1)[0]
    rows = {}
    for line in table.splitlines()[2:]:
        m = BUDGET_ROW.match(line)
        if m:
            rows[(m.group(1), m.group(2))] = (float(m.group(3)), float(m.group(4)))
    return rows


def figures(path):
    text = open(path).read()
    out = {"budget": budget(text)}
    for name, pattern in FIGURES.items():
        m = re.search(pattern, text, re.M)
        if m:
            out[name] = float(m.group(1))
    cpu = text.split("CPU (share of one core", 1)[-1].split("latency budget", 1)[0]
    for process in PROCESSES:
        m = re.search(r"^  %s\s+([\d.]+) %%" % process, cpu, re.M)
        if m:
            out["CPU %s %%" % process] = float(m.group(1))
    try:
        finals = [l for l in open(os.path.join(os.path.dirname(path), "stereo-match.log")) if " final: " in l]
    except OSError:
        finals = []
    if finals:
        images = re.search(r"STEREO_IMAGES in [^|]*", finals[-1])
        for name, reason in SKIPS.items():
            m = re.search(re.escape(reason) + r" (\d+)", images.group(0) if images else "")
            out[name] = float(m.group(1)) if m else 0.0
    return out


def round_rows(run, variants):
    print("| round | launch | " + " | ".join(n.strip() for n in NAMES) + " |")
    print("|---|---|" + "---|" * len(NAMES))
    for path in sorted(glob.glob(f"{run}/round-*"), key=lambda p: int(p.rsplit("-", 1)[1])):
        for variant in variants:
            f = figures(f"{path}/{variant}/bench_transport.out")
            cells = ["%g" % f[n] if n in f else "—" for n in NAMES]
            print(f"| {path.rsplit('-', 1)[1]} | {variant} | " + " | ".join(cells) + " |")


def main():
    if sys.argv[1] == "--rounds":
        round_rows(sys.argv[2], sys.argv[3:])
        return
    run, variants = sys.argv[1], sys.argv[2:]
    per_variant = {}
    for variant in variants:
        rounds = [figures(f) for f in sorted(glob.glob(f"{run}/round-*/{variant}/bench_transport.out"))]
        per_variant[variant] = rounds
    print(f"== summary over the rounds: median (lowest - highest) of {', '.join(str(len(r)) for r in per_variant.values())} rounds")
    print("  %-36s" % "figure" + "".join("%-30s" % v for v in variants))
    for name in NAMES:
        cells = []
        for variant in variants:
            values = [r[name] for r in per_variant[variant] if name in r]
            cells.append("%g (%g - %g)" % (statistics.median(values), min(values), max(values)) if values else "-")
        if any(c != "-" for c in cells):
            print("  %-36s" % name + "".join("%-30s" % c for c in cells))
    print("== latency budget: each stage's median / p99 ms per frame, medians over the rounds")
    stages = []
    for rounds in per_variant.values():
        for r in rounds:
            stages += [k for k in r["budget"] if k not in stages]
    for process, stage in stages:
        cells = []
        for variant in variants:
            rows = [r["budget"][(process, stage)] for r in per_variant[variant] if (process, stage) in r["budget"]]
            cells.append("%.1f / %.1f" % (statistics.median(m for m, _ in rows), statistics.median(p for _, p in rows))
                         if rows else "-")
        print("  %-36s" % f"{process} {stage}"[:36] + "".join("%-30s" % c for c in cells))


if __name__ == "__main__":
    main()
