#!/usr/bin/env bash
# Transport benchmark (issue #7): 2 x 1280x960 GRAY8 pairs at 15 Hz over udpm
# on this host, through stereo-match and stereo-cloud, for DURATION seconds
# (default 60): frames lost in transit, latency from capture to
# STEREO_CLOUD_FILTERED and each process's CPU share. Then the same again with
# stereo-view and its depth view read as a browser on another machine would
# (transport-view-remote.yaml, page_reader.py), and with one headless Chromium
# on this host showing it (transport-view.yaml): the first run is the others'
# baseline. Uses the receive-buffer size the launch
# files ask for; the kernel grants at most net.core.rmem_max (see docs/launch.md).
#   bench/transport/run.sh [DURATION]
set -euo pipefail
cd "$(dirname "$0")/../.."
DURATION=${1:-60}
RUN=logs/bench-transport-$(date +%Y%m%d-%H%M%S)
mkdir -p "$RUN/frames"
echo "net.core.rmem_max = $(sysctl -n net.core.rmem_max)"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/wall.yaml --log-dir "$RUN" --quiet
mv "$RUN/frames/calibration.yaml" "$RUN/calibration.yaml"
PORT=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
for variant in transport transport-view-remote transport-view; do
  mkdir -p "$RUN/$variant"
  ln -sfn ../frames "$RUN/$variant/frames"
  ln -sfn ../calibration.yaml "$RUN/$variant/calibration.yaml"
  extra=()
  case $variant in
    transport-view) extra=(--append "stereo-view=--port=$PORT" --append "browser=http://127.0.0.1:$PORT/") ;;
    transport-view-remote) extra=(--append "stereo-view=--port=$PORT" --append "page_reader=http://127.0.0.1:$PORT/") ;;
  esac
  scripts/launch "bench/transport/$variant.yaml" --run-dir "$RUN/$variant" --no-record \
    --append "bench_transport=--duration=$DURATION" "${extra[@]}" > "$RUN/$variant/launch.out"
  echo "== $variant.yaml"
  cat "$RUN/$variant/bench_transport.out"
  grep -h "^browser: Chromium" "$RUN/$variant/browser.out" 2>/dev/null || true
  grep -h "^page reader: [0-9]" "$RUN/$variant/page_reader.out" 2>/dev/null || true
done
