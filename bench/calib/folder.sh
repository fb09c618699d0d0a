#!/usr/bin/env bash
# The one command on a folder of images, detection included: the
# simulator's board frames of each CONFIG rendered as a folder of pairs
# (build/bench/sim_folder), then `stereo-calibrate --images DIR --board
# BOARD` timed (wall and CPU seconds), with the boards found and the model
# chosen. OTHER_TREE=DIR also runs another checkout's stereo-calibrate
# (built in DIR/build) on the same folder: a before and after in one run.
#   bench/calib/folder.sh [CONFIG.yaml...]   (default: config/sim/default.yaml config/sim/fisheye.yaml)
set -euo pipefail
cd "$(dirname "$0")/../.."
# The benchmarks are not in `make test`'s build (bench/CMakeLists.txt).
cmake --build build --target bench -j"$(nproc)" > /dev/null
OUT=$(mktemp -d /tmp/bench-folder-XXXX)
CONFIGS=${*:-config/sim/default.yaml config/sim/fisheye.yaml}
run() {  # LABEL BIN DIR BOARD
  local out=$OUT/$1
  mkdir -p "$out"
  /usr/bin/time -f "%e %U" -o "$out/time" "$2/stereo-calibrate" --images "$3" --board "$4" --out "$out/calib.yaml" \
    --log-dir "$out" --quiet > /dev/null 2>&1 || { echo "$1: failed (see $out/stereo-calibrate.log)"; return 0; }
  read -r wall cpu < "$out/time"
  echo "$1: ${wall} s wall, ${cpu} s CPU; $(grep -o 'found: left [0-9]* of [0-9]*, right [0-9]* of [0-9]*' \
    "$out/stereo-calibrate.log" | head -1); $(grep -o 'model: [a-z0-9_]* chosen' "$out/stereo-calibrate.log" | tail -1)"
}
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
for config in $CONFIGS; do
  name=$(basename "$config" .yaml)
  build/bench/sim_folder "$config" "$OUT/$name-images" 2> /dev/null
  board=$(sed -n 's/^ *spec: *\([^ ]*\).*/\1/p' "$config" | head -1)
  run "$name" build/bin "$OUT/$name-images" "$board"
  [ -z "${OTHER_TREE:-}" ] || run "baseline $name" "$OTHER_TREE/build/bin" "$OUT/$name-images" "$board"
done
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
