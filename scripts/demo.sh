#!/usr/bin/env bash
# The whole pipeline on the built-in default, leaving its outputs in
# logs/demo-<time>/. It runs every stage that exists so far.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=build/bin
OUT=logs/demo-$(date +%Y%m%d-%H%M%S)
mkdir -p "$OUT"
say() { printf '\n== %s\n' "$*"; }

if [[ -x $BIN/stereo-fit-curve ]]; then
  say "Fitting bspline, poly6 and poly12 to the Theia-like lens table (paper Sec. VII-A)"
  table=$(ls config/lenses/*.csv | head -n 1)
  $BIN/stereo-fit-curve --table "$table" --report "$OUT/fit.json" --plot "$OUT/fit.png"
fi

say "Monitoring the bus for 2 s (stereo-status)"
$BIN/stereo-status --log-dir "$OUT" --duration 2 --quiet | tail -n 8

say "Done: outputs in $OUT"
ls -l "$OUT"
