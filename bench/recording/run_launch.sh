#!/usr/bin/env bash
# The run launch's recording: raw images (the launch as shipped) against
# images PNG-compressed by stereo-capture, each run twice, alternately, for
# DURATION seconds (default 45) on a private bus: MB a minute and a pair,
# pairs a second captured and matched, and the depth chain's median latency
# (capture to disparity, capture to the filtered cloud's statistics). Needs
# the Python module (build/python).
#   bench/recording/run_launch.sh [DURATION]
set -euo pipefail
cd "$(dirname "$0")/../.."
duration=${1:-45}
cmake --build build --target stereo-capture stereo-match stereo-cloud stereo-health stereo-view _widestereo -j2 >/dev/null
url="udpm://239.255.76.$((RANDOM % 200 + 20)):$((RANDOM % 20000 + 20000))?ttl=0&recv_buf_size=16777216"
out=$(mktemp -d)
echo "| images | MB a minute | MB a pair | pairs/s captured | pairs/s matched | capture to disparity, median ms | capture to cloud, median ms |"
echo "|---|---|---|---|---|---|---|"
for run in 1 2; do
  for compression in none png; do
    scripts/launch config/launch/run.yaml --lcm-url "$url" --run-dir "$out/$compression$run" --duration "$duration" \
      --max-log-mb 100000 --set stereo-view.port=0 --set stereo-capture.compression=$compression >/dev/null
    PYTHONPATH=build/python /usr/bin/python3 bench/recording/run_launch.py "$out/$compression$run" "$compression ($run)"
  done
done
rm -rf "$out"
