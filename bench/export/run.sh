#!/usr/bin/env bash
# stereo-export --to mrcal on the calibrations at hand, measured with mrcal
# itself (measure.py), per camera: the spline's knots across (Nx; "exact"
# for a model mrcal has), the file's size, mrcal.project's worst / RMS
# pixel difference from the calibration within the lens circle the export
# was fitted in and over the whole observed field (every 2nd pixel), the
# worst angle between mrcal.unproject and the calibration's ray within the
# circle, and the export's wall-clock seconds (both cameras).
#   bench/export/run.sh [CALIBRATION.yaml[:REPORT.json] ...]
# The calibrations: config/calib/*.yaml; the real sets' bspline_theta
# calibrations in a bench/real/run.sh output folder, REAL=DIR
# (DIR/ros/own/ws.bspline_theta.yaml, DIR/babelcalib/ws.bspline_theta.yaml,
# each with its report ws.json; without REAL they are skipped, saying so);
# and those given.
# A calibration given with its report (stereo-calibrate --report) is
# exported twice: over the whole observed field, and with --report.
# OTHER_TREE="DIR ..." also runs each other checkout's stereo-export (built
# in DIR/build), its rows labelled with its commit: a before and after in
# the same run. Every row's lens circle is this tree's, so the rows of a
# camera are measured over the same pixels.
set -euo pipefail
cd "$(dirname "$0")/../.."
export PYTHONPATH=$PWD/build/python
OUT=$(mktemp -d /tmp/bench-export-XXXX)

CALIBRATIONS=(config/calib/*.yaml)
if [ -z "${REAL:-}" ]; then
  if [ -d ../shared/data ]; then
    echo "(the real sets' calibrations skipped: run bench/real/run.sh and give its folder as REAL=DIR)"
  else
    echo "(the real sets' calibrations skipped: ../shared/data absent)"
  fi
else
  for set in ros/own babelcalib; do
    if [ -f "$REAL/$set/ws.bspline_theta.yaml" ]; then
      CALIBRATIONS+=("$REAL/$set/ws.bspline_theta.yaml:$REAL/$set/ws.json")
    else
      echo "($REAL/$set/ws.bspline_theta.yaml absent: skipped)"
    fi
  done
fi
CALIBRATIONS+=("$@")

TREES=(.)
for tree in ${OTHER_TREE:-}; do
  [ -x "$tree/build/bin/stereo-export" ] || { echo "OTHER_TREE $tree: no build/bin/stereo-export; build it there first"; exit 2; }
  TREES+=("$tree")
done
label() { git -C "$1" log -1 --format=%h; }

# The lens circle this tree's export printed for SIDE in FILE (inf: none).
circle() {
  local r
  r=$(sed -n "s/^$1: .*lens circle (r = \([0-9.]*\) px.*/\1/p" "$2")
  echo "${r:-inf}"
}

echo "| calibration | camera | tree | export | lens circle r px | Nx | kB | export s | in circle worst / RMS px | whole field worst / RMS px | unproject worst ° in circle |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
n=0
for entry in "${CALIBRATIONS[@]}"; do
  calibration=${entry%%:*}
  report=
  [ "$entry" != "$calibration" ] && report=${entry#*:}
  name=${calibration#"${REAL:-}/"}
  for options in "" ${report:+--report}; do
    n=$((n + 1))
    args=()
    [ -n "$options" ] && args=(--report "$report")
    for tree in "${TREES[@]}"; do
      dir=$OUT/$n-$(label "$tree")
      if [ -n "$options" ] && ! "$tree/build/bin/stereo-export" --help | grep -q -- --report; then
        echo "| $name | | $(label "$tree") | --report | (no --report in this stereo-export) | | | | | | |"
        continue
      fi
      start=$(date +%s.%N)
      "$tree/build/bin/stereo-export" "$calibration" --to mrcal "$dir" "${args[@]}" > "$dir.txt"
      seconds=$(awk -v end="$(date +%s.%N)" -v start="$start" 'BEGIN { printf "%.1f", end - start }')
      [ "$tree" = . ] && printed=$dir.txt
      for side in left right; do
        [ -f "$dir/camera-$([ $side = left ] && echo 0 || echo 1).cameramodel" ] || continue
        read -r nx kb in_worst in_rms whole_worst whole_rms angle < <(
          /usr/bin/python3 bench/export/measure.py "$calibration" "$dir" $side "$(circle $side "$printed")")
        echo "| $name | $side | $(label "$tree") | ${options:-default} | $(circle $side "$printed" | sed 's/inf/none (no fold)/') |" \
             "$([ "$nx" = 0 ] && echo exact || echo "$nx") | $kb | $seconds | $in_worst / $in_rms | $whole_worst / $whole_rms | $angle |"
      done
    done
  done
done
echo "(exports and their output in $OUT)"
