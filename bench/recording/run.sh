#!/usr/bin/env bash
# Recording benchmark: what each stereo-capture --compression costs a
# recording, and what it does to a calibration made from it. The simulated
# rig's 35 frames (config/sim/default.yaml: 30 board poses, 5 of a wall) are
# captured into an LCM log with none, png and jpeg (--jpeg-quality 95):
# megabytes a pair, a minute at 5 and 10 pairs a second and how long 500 and
# 3000 MB last; stereo-capture's encoding time a pair (its "encode" stage,
# median) and OpenCV's decoding time an image (median over the left
# images), raw's the baseline; then the offline recalibration from each log
# (stereo-detect, stereo-calibrate --once): the chosen model's RMS per
# camera. Needs the Python module (build/python) and OpenCV's Python.
#   bench/recording/run.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
RUN=logs/bench-recording-$(date +%Y%m%d-%H%M%S)
mkdir -p "$RUN"
BIN=build/bin
for c in none png jpeg; do
  $BIN/stereo-capture --source sim:config/sim/default.yaml --rate 0 --count 35 --frame-clock --compression $c \
    --jpeg-quality 95 --out-url "file://$PWD/$RUN/$c.lcmlog?mode=w" --log-dir "$RUN/$c" --quiet
  $BIN/stereo-detect --board chessboard:9x6:0.05 --in-url "file://$PWD/$RUN/$c.lcmlog?speed=0" \
    --out-url "file://$PWD/$RUN/$c-corners.lcmlog?mode=w" --log-dir "$RUN/$c" --quiet
  $BIN/stereo-calibrate --in-url "file://$PWD/$RUN/$c-corners.lcmlog?speed=0" --once \
    --out "$RUN/$c/calibration.yaml" --report "$RUN/$c/report.json" --log-dir "$RUN/$c" --quiet 2>/dev/null
done
PYTHONPATH=build/python /usr/bin/python3 - "$RUN" <<'PY'
import json, os, statistics, sys, time
import cv2
import numpy as np
import widestereo
run = sys.argv[1]
print("| compression | MB a pair | MB a minute at 5 / 10 pairs/s | 500 MB last at 5 / 10 | 3000 MB last at 5 / 10 | "
      "encode a pair, decode an image (ms) | chosen model: RMS left, right (px) |")
print("|---|---|---|---|---|---|---|")
for c in ("none", "png", "jpeg"):
    log = f"{run}/{c}.lcmlog"
    mb = os.path.getsize(log) / 35 / 1e6
    events = list(widestereo.read_log(log))
    status = [e.message for e in events if e.channel == "PROCESS_STATUS"][-1]
    encode = next(s.median_ms for s in status.stages if s.stage == "encode")
    decode = []
    for frame in (e.message for e in events if e.channel == "STEREO_IMAGES"):
        payload = np.frombuffer(bytes(frame.left.data), np.uint8)
        start = time.perf_counter()
        if c == "none":
            payload.reshape(frame.left.height, frame.left.width).copy()
        else:
            cv2.imdecode(payload, cv2.IMREAD_UNCHANGED)
        decode.append((time.perf_counter() - start) * 1e3)
    chosen = next(m for m in json.load(open(f"{run}/{c}/report.json"))["table_ii"] if m["chosen"])
    last = lambda cap: f"{cap / (mb * 300):.1f} / {cap / (mb * 600):.1f} min"
    print(f"| {c} | {mb:.2f} | {mb * 300:.0f} / {mb * 600:.0f} | {last(500)} | {last(3000)} | "
          f"{encode:.1f}, {statistics.median(decode):.1f} | "
          f"{chosen['model']} {chosen['coeffs']}: {chosen['left_rms_px']:.5f}, {chosen['right_rms_px']:.5f} |")
PY
