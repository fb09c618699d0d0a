#!/usr/bin/env bash
# Transport benchmark (issue #7): 2 x 1280x960 GRAY8 pairs at 15 Hz over udpm
# on this host, through stereo-match and stereo-cloud, for DURATION seconds
# (default 60): frames lost in transit and latency from capture to
# STEREO_CLOUD_FILTERED. Uses the receive-buffer size the launch files ask
# for; the kernel grants at most net.core.rmem_max (see docs/launch.md).
#   bench/transport/run.sh [DURATION]
set -euo pipefail
cd "$(dirname "$0")/../.."
DURATION=${1:-60}
RUN=logs/bench-transport-$(date +%Y%m%d-%H%M%S)
mkdir -p "$RUN/frames"
echo "net.core.rmem_max = $(sysctl -n net.core.rmem_max)"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/wall.yaml --log-dir "$RUN" --quiet
mv "$RUN/frames/calibration.yaml" "$RUN/calibration.yaml"
scripts/launch bench/transport/transport.yaml --run-dir "$RUN" --no-record \
  --append "bench_transport=--duration=$DURATION" > "$RUN/launch.out"
cat "$RUN/bench_transport.out"
