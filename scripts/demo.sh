#!/usr/bin/env bash
# make demo: the whole pipeline on the built-in default, no camera needed.
# The simulated Theia-like rig (two ~125 deg mustache-lens cameras, 0.3 m
# apart) is served as two fake GigE Vision cameras and captured through
# Aravis; the board is found; the rig is calibrated with bspline, poly6 and
# poly12 (the paper's Table II); then each calibration reconstructs the flat
# wall 2.0 m in front of the rig (the paper's Sec. VII-C). Everything is left
# in logs/demo-<time>/.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=build/bin
OUT=logs/demo-$(date +%Y%m%d-%H%M%S)
URL=${DEMO_LCM_URL:-udpm://239.255.76.67:7670?ttl=0&recv_buf_size=16777216}
BOARD=chessboard:9x6:0.05
MODELS=(bspline poly6 poly12)
mkdir -p "$OUT"
echo "demo: no rig key (--key-file): commands and calibrations on the demo's bus are unauthenticated (docs/security.md)"
say() { printf '\n== %s\n' "$*"; }
file_url() { echo "file://$PWD/$1"; }
root() { [[ $(id -u) == 0 ]]; }

# Two fake GigE Vision cameras need two IPv4 addresses of this host.
if (( $(ip -4 -o addr show up | wc -l) < 2 )); then
  if root; then
    ip addr add 127.0.0.2/8 dev lo && echo "demo: added 127.0.0.2 to lo for the second fake camera"
  else
    echo "demo: the two fake cameras need two IPv4 addresses; run: sudo ip addr add 127.0.0.2/8 dev lo" >&2; exit 1
  fi
fi
# A 1280x960 stereo pair is a 2.4 MB LCM message: small receive buffers lose them.
LAUNCH_EXTRA=()
if (( $(sysctl -n net.core.rmem_max) < 16777216 )); then
  if root; then
    sysctl -qw net.core.rmem_max=16777216
    echo "demo: raised net.core.rmem_max to 16 MB for image messages (config/systemd/60-widestereo-lcm.conf keeps it)"
  else
    LAUNCH_EXTRA=(--append stereo-capture=--compression=jpeg)
    echo "demo: net.core.rmem_max is small (see docs/launch.md, Receive buffers): images go JPEG-compressed"
  fi
fi

say "1/5 Two fake GigE Vision cameras serve the simulated rig (30 board poses, 5 wall frames);"
echo "    stereo-capture reads them through Aravis, stereo-detect finds the board live, lcm-logger records"
scripts/launch config/launch/demo.yaml --run-dir "$OUT" --lcm-url "$URL" "${LAUNCH_EXTRA[@]}" | sed 's/^/    /'

say "2/5 stereo-detect over the recorded log: every frame, in order"
$BIN/stereo-detect --board "$BOARD" --in-url "$(file_url "$OUT/demo.lcmlog")?speed=0" \
  --out-url "$(file_url "$OUT/corners.lcmlog")?mode=w" --log-dir "$OUT" --quiet
final() { grep -h "final: " "$OUT/$1.log" | sed -n "$2p" | sed 's/.*final: [a-z]* | //; s/PROCESS_STATUS[^|]*| //'; }
echo "    capture, live:  $(final stereo-capture 1)"
echo "    detect, live:   $(final stereo-detect 1)"
echo "    detect, replay: $(final stereo-detect 2)"

say "3/5 stereo-calibrate --model all: the paper's Table II (reprojection RMS per model per camera)"
$BIN/stereo-calibrate --in-url "$(file_url "$OUT/corners.lcmlog")?speed=0" --once --model all \
  --out "$OUT/calibration.yaml" --report "$OUT/report.json" --plot-dir "$OUT" \
  --out-url "$(file_url "$OUT/calibration.lcmlog")?mode=w" --log-dir "$OUT" --quiet
sed -n '/Table II/,/^$/p' "$OUT/stereo-calibrate.log" | sed 's/^[0-9-]* [0-9:.]* info //; s/^/    /'

say "4/5 The flat wall 2.0 m in front of the rig, reconstructed with each model's calibration"
$BIN/stereo-capture --source "sim:config/sim/wall.yaml?truth=$OUT/wall.truth.yaml" --frame-clock --count 1 \
  --out-url "$(file_url "$OUT/wall.lcmlog")?mode=w" --log-dir "$OUT" --quiet
for model in "${MODELS[@]}"; do
  $BIN/stereo-match --config config/stereo-match.yaml --calib "$OUT/calibration.$model.yaml" \
    --in-url "$(file_url "$OUT/wall.lcmlog")?speed=0" --out-url "$(file_url "$OUT/wall-$model.lcmlog")?mode=w" \
    --log-dir "$OUT/$model" --quiet
  $BIN/stereo-cloud --config config/stereo-cloud.yaml --pcd-dir "$OUT/$model" --save-every 1 \
    --in-url "$(file_url "$OUT/wall-$model.lcmlog")?speed=0" --out-url "$(file_url "$OUT/cloud-$model.lcmlog")?mode=w" \
    --log-dir "$OUT/$model" --quiet
  printf '    %-8s %s rectification; ' "$model" \
    "$(grep -ho '[a-z]* rectification' "$OUT/$model/stereo-match.log" | tail -n 1 | cut -d' ' -f1)"
  grep -h " plane " "$OUT/$model/stereo-cloud.log" | tail -n 1 | sed -E 's/^[0-9-]+ [0-9:.]+ [a-z]+ //'
done

say "5/5 Done. In $OUT:"
echo "    demo.lcmlog (the recording: replay it with lcm-logplayer), calibration.yaml,"
echo "    calibration.<model>.yaml, report.json, distortion_curves.png, residual_map.png,"
echo "    <model>/cloud_*.pcd, every process's log"
echo "    The demo left $(du -sh "$OUT" | cut -f1) there; remove it with: rm -r $OUT"
echo "    (every demo: rm -r logs/demo-*)"
