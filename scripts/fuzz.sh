#!/usr/bin/env bash
# scripts/fuzz.sh [BUILD [SECONDS [TARGET...]]]: runs every libFuzzer target of
# BUILD (default build-fuzz, made by `make fuzz`) for SECONDS each (default
# 60), one after the other on one core, and prints the executions and CPU
# seconds of each.
#
# Seeds: BUILD/fuzz-seeds (real messages, configs and files, written by
# fuzz-seeds) and tests/fuzz/corpus/<target> (regression inputs). What
# libFuzzer finds that covers new code is kept in BUILD/fuzz-corpus/<target>
# and used again on the next run. A crash, a sanitizer report, a leak, an
# input slower than 10 s or an allocation over 2 GB is saved in
# BUILD/fuzz-findings/<target>/ and makes the script exit 1; reproduce it with
# `BUILD/fuzz/<target> FILE`, fix it, and add FILE to tests/fuzz/corpus/<target>/
# so that ctest replays it from then on.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
seconds=${2:-60}
shift $(( $# < 2 ? $# : 2 ))
targets=("$@")
if (( ${#targets[@]} == 0 )); then
  for binary in "$build"/fuzz/fuzz_*; do targets+=("$(basename "$binary")"); done
fi
[[ -x $build/fuzz/fuzz-seeds ]] || { echo "fuzz.sh: no $build/fuzz/fuzz-seeds; run make fuzz" >&2; exit 2; }
"$build/fuzz/fuzz-seeds" "$build/fuzz-seeds" || exit 2

failed=0
printf '%-28s %8s %8s %14s %10s %8s  %s\n' target seconds 'cpu s' executions 'exec/s' corpus findings
for target in "${targets[@]}"; do
  corpus=$build/fuzz-corpus/$target findings=$build/fuzz-findings/$target log=$build/fuzz-logs/$target.log
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  before=$(ls "$findings" | wc -l)
  seeds=("$build/fuzz-seeds/$target" tests/fuzz/corpus/"$target")
  existing=()
  for dir in "${seeds[@]}"; do [[ -d $dir ]] && existing+=("$dir"); done
  start=$(date +%s)
  /usr/bin/time -o "$log.cpu" -f '%U %S' \
    "$build/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" "${existing[@]}" >"$log" 2>&1
  status=$?
  cpu=$(awk 'END {printf "%d", $1 + $2}' "$log.cpu")
  elapsed=$(( $(date +%s) - start ))
  executions=$(awk '/stat::number_of_executed_units/ {n = $2} END {print n + 0}' "$log")
  found=$(( $(ls "$findings" | wc -l) - before ))
  (( status != 0 || found > 0 )) && failed=1
  printf '%-28s %8d %8d %14d %10d %8d  %s\n' "$target" "$elapsed" "$cpu" "$executions" \
    $(( executions / (elapsed > 0 ? elapsed : 1) )) "$(ls "$corpus" | wc -l)" \
    "$( (( found > 0 )) && echo "$found in $findings (log $log)" || echo none)"
done
exit $failed
