#!/usr/bin/env bash
# Transport benchmark (issue #7): 2 x 1280x960 GRAY8 pairs at RATE Hz
# (default 15) over udpm on this host, through stereo-match and stereo-cloud,
# for DURATION seconds (default 60): frames lost in transit, latency from
# capture to STEREO_CLOUD_FILTERED, each process's CPU share and the latency
# budget (each stage's time per frame). Then the same again with stereo-view
# and its depth view read as a browser on another machine would
# (transport-view-remote.yaml, page_reader.py), and with one headless Chromium
# on this host showing it (transport-view.yaml): the first run is the others'
# baseline. Uses the receive-buffer size the launch files ask for; the kernel
# grants at most net.core.rmem_max (see docs/launch.md).
#   bench/transport/run.sh [DURATION] [RATE] [OTHER_TREE]
# OTHER_TREE: another checkout, built in its build/: its stereo-* processes
# run with its own config/ files instead (a baseline measured in the same
# session), with this tree's listener.
# VARIANTS="transport" runs the first launch only.
set -euo pipefail
cd "$(dirname "$0")/../.."
DURATION=${1:-60}
RATE=${2:-15}
OTHER=${3:-}
VARIANTS=${VARIANTS:-transport transport-view-remote transport-view}
RUN=logs/bench-transport-$(date +%Y%m%d-%H%M%S)${OTHER:+-other}
mkdir -p "$RUN/frames"
echo "net.core.rmem_max = $(sysctl -n net.core.rmem_max)"
build/bench/bench_transport --prepare "$RUN/frames" --sim config/sim/wall.yaml --log-dir "$RUN" --quiet
mv "$RUN/frames/calibration.yaml" "$RUN/calibration.yaml"
PORT=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
for variant in $VARIANTS; do
  mkdir -p "$RUN/$variant"
  ln -sfn ../frames "$RUN/$variant/frames"
  ln -sfn ../calibration.yaml "$RUN/$variant/calibration.yaml"
  python3 - "bench/transport/$variant.yaml" "$RUN/$variant/launch.yaml" "$OTHER" <<'PY'
import sys, yaml
launch_file, out, other = sys.argv[1:]
launch = yaml.safe_load(open(launch_file))
for p in launch["processes"]:
    if other and p["name"].startswith("stereo-"):
        p["executable"] = f"{other}/build/bin/{p['name']}"
        if "config" in p:
            p["config"] = f"{other}/{p['config']}"
yaml.safe_dump(launch, open(out, "w"), sort_keys=False)
PY
  extra=()
  case $variant in
    transport-view) extra=(--append "stereo-view=--port=$PORT" --append "browser=http://127.0.0.1:$PORT/") ;;
    transport-view-remote) extra=(--append "stereo-view=--port=$PORT" --append "page_reader=http://127.0.0.1:$PORT/") ;;
  esac
  scripts/launch "$RUN/$variant/launch.yaml" --run-dir "$RUN/$variant" --no-record \
    --set "stereo-capture.rate=$RATE" --append "bench_transport=--duration=$DURATION" "${extra[@]}" \
    > "$RUN/$variant/launch.out"
  echo "== $variant.yaml, ${OTHER:-this tree}: capture at $RATE Hz for $DURATION s"
  cat "$RUN/$variant/bench_transport.out"
  grep -h "^browser: Chromium" "$RUN/$variant/browser.out" 2>/dev/null || true
  grep -h "^page reader: [0-9]" "$RUN/$variant/page_reader.out" 2>/dev/null || true
done
